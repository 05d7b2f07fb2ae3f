#pragma once
// Smooth boundary curves rebuilt from a linear boundary, for meshes read without
// CAD (a bare .msh): the high-order boundary nodes go onto interpolating cubic
// splines through the boundary vertices instead of onto the CAD curves.
//
// Chains. The corners of the boundary lines (Mesh::line) form chains of
// vertices. A chain ends at a vertex that
//  - is shared by other than exactly two boundary lines,
//  - joins lines of two different curve entities (line_entity), or
//  - turns by more than `corner_degrees`: the angle between the directions of
//    its incoming and outgoing edges (0 on a straight boundary, 90 at a square
//    corner; a regular N-gon turns 360 / N at every vertex).
// A loop with no such vertex is closed.
//
// Curves. Each chain gets the chordal cubic spline through its vertices
// (parameter t = cumulative chord length), C2, periodic on closed loops and
// with de Boor's not-a-knot ends on open chains (C. de Boor, A Practical Guide
// to Splines, rev. ed., Springer 2001, Ch. IV); a chain of three vertices gets
// the parabola through them, one of two vertices its straight edge. Chordal
// cubic splines are fourth-order accurate: for vertices sampled from a smooth
// curve with spacing h, the spline lies within O(h^4) of the curve
// (M. S. Floater, "Chordal cubic spline interpolation is fourth order
// accurate", IMA J. Numer. Anal. 26 (2006) 25-33). Data on a straight line is
// reproduced exactly, so edges between corners stay straight.
//
// Placement. The p - 1 interior nodes of each boundary line of order p go onto
// its chain's spline between the line's end vertices, at the arc-length
// fractions of the reference line nodes (equally spaced), as
// gmsh/cad_boundary.h does on CAD curves. Arc length is integrated with 8-point
// Gauss-Legendre per segment, fractions solved by Newton's method.
#include <Eigen/Core>

#include "core/mesh.h"

namespace homesh {

struct BoundaryReconstructionOptions {
  /// Vertices turning by more than this (degrees, in (0, 180)) stay sharp. 40
  /// keeps circles resolved by at least 10 edges smooth (36 degree turns) and
  /// every corner of 90 degrees or sharper; it is the feature angle of Gmsh's
  /// classifySurfaces tutorial (t13).
  double corner_degrees = 40;
};

struct BoundaryReconstruction {
  /// 2 by #nodes: positions of all nodes, the interior nodes of every boundary
  /// line on its chain's spline, every other node unmoved.
  Eigen::Matrix2Xd target;
  int chains = 0;        ///< open chains (between chain ends)
  int closed_loops = 0;  ///< loops without a chain end (periodic splines)
  int corners = 0;       ///< chain ends that are there only because of their angle
};

/// Whether the rebuilt boundary keeps a sharp corner at a node where exactly two
/// boundary lines meet, the wall coming in along `in` and leaving along `out`: the
/// lines lie on different curves, or they turn by more than corner_degrees.
bool rebuilt_corner(const Eigen::Vector2d& in, const Eigen::Vector2d& out, bool same_curve,
                    double corner_degrees);

/// The boundary of m rebuilt as above. m may be of any order; lines of order 1
/// move no node. Throws homesh::Error for corner_degrees outside (0, 180) or a
/// boundary line of zero length.
BoundaryReconstruction reconstruct_boundary(const Mesh& m,
                                            const BoundaryReconstructionOptions& opt = {});

}  // namespace homesh
