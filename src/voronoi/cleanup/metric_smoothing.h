#pragma once
// Smart smoothing of the free nodes of a linear triangle mesh in a metric,
// a cheap last step after the dual triangulation (Freitag, "On combining
// Laplacian and optimization-based mesh smoothing techniques", AMD 220, 1997).
// Each free node v tries the positions below and takes a better one, never
// letting the worst triangle round it get worse:
//
//  - Laplacian: the mean of its neighbours;
//  - ideal apexes: the mean over its triangles (v, a, b) of the point that
//    makes (v, a, b) equilateral in the metric M at v,
//      p = (a + b) / 2 + (sqrt 3 / 2) M^-1/2 R M^1/2 (b - a),  R: +90 degrees
//    (Vartziotis et al.'s geometric element transformation, in its
//    one-step form, "The geometric element transformation method for mixed
//    mesh smoothing", Eng Comput 25, 2009);
//  - where its worst triangle stays below 0.8: a compass search (8
//    directions, step halved on failure) for the largest worst quality;
//  - then a compass search for the smallest sum of inverse qualities
//    sum 1/q over its triangles (Knupp's inverse mean ratio objective,
//    "Achieving finite element mesh quality via optimization of the Jacobian
//    matrix norm and associated quantities", IJNME 48, 2000), the worst
//    triangle kept no worse: the star's local optimum, which the two fixed
//    candidates only come near. Candidates are taken by the same rule.
//
// Quality is the mean ratio in M, q = 4 sqrt(3) A sqrt(det M) / sum |e|_M^2
// (1 for a triangle equilateral in M, 0 degenerate; equal to Q11 for linear
// triangles in the identity metric), in the metric at v's old position. A
// fold has q < 0, so no move turns a triangle over, and the mesh's worst
// quality never decreases. The connectivity does not change.
#include <Eigen/Core>
#include <vector>

#include "voronoi/metric/metric_field.h"

namespace homesh {

/// Mean ratio in the metric M of the triangle (a, b, c), counter-clockwise
/// positive, clockwise negative.
double metric_mean_ratio(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                         const Eigen::Vector2d& c, const Eigen::Matrix2d& M);

/// x: 2 by N node positions, moved in place; tri: 3 (or more; rows 0-2 the
/// corners, counter-clockwise) by T; free_node: N flags, 1 for a node that
/// may move. sweeps passes over the free nodes. Returns the number of moves.
int smooth_free_nodes(Eigen::Matrix2Xd& x, const Eigen::MatrixXi& tri,
                      const std::vector<char>& free_node, const MetricField& metric, int sweeps);

/// The mesh's worst triangle (mean ratio in the metric at its centroid),
/// again and again: each of its free corners moves by the compass search
/// above to the position that makes the worst triangle of its star the
/// best, until the worst triangle has no free corner that can raise it or
/// max_steps. Raises the mesh's minimum where the sweeps above, which trade
/// it for the sum of inverse qualities once it is above 0.8, leave it;
/// only the few nodes of the worst triangles move. Returns the steps taken.
int raise_worst_triangle(Eigen::Matrix2Xd& x, const Eigen::MatrixXi& tri,
                         const std::vector<char>& free_node, const MetricField& metric,
                         int max_steps);

}  // namespace homesh
