#pragma once
// How coarse a mesh's boundary is for its curvature: the largest angle by which
// consecutive boundary lines turn where the wall they approximate is smooth. A
// polygon of N lines round a circle turns by 360 / N degrees at each node; a
// straight line's lines do not turn; a sharp corner of the wall (a trailing edge,
// a re-entrant corner) is no measure of coarseness and is left out. Issue 16's
// corpus sets its quality bar by it (0.9 where the wall turns by less than 30
// degrees, 0.8 elsewhere), and the curve pipeline (curving/curve_mesh.h) its
// optimiser's threshold.
#include "core/mesh.h"
#include "curving/curve_evaluator.h"

namespace homesh {

/// The largest turn in degrees (0 to 180) between two boundary lines of `m` (the
/// chords of their end nodes) at a node where exactly two meet and the wall is smooth:
/// - with `curves` giving both lines' curves (CAD): a node inside the curve both lie
///   on, or a model point where their curves' tangents meet within 1 degree (as the
///   corpus, scripts/bench/corpus.py, sees a smooth join);
/// - else (no CAD: the boundary is rebuilt, curving/boundary_reconstruction.h): any
///   such node the rebuilt boundary keeps smooth (rebuilt_corner: both lines on one
///   curve, turning by at most `corner_degrees`).
/// 0 if there is none.
double largest_wall_turn(const Mesh& m, const CurveEvaluator* curves, double corner_degrees);

}  // namespace homesh
