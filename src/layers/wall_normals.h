#pragma once
// Normal vectors of a boundary layer at the wall nodes (thesis Sections 4.3.1,
// 4.3.2, Figs 4.5-4.7).
//
// At a wall node x with neighbours prev (edge prev -> x) and next (edge
// x -> next), the domain on the left, the domain angle theta in (0, 2 pi) turns
// the outgoing edge direction next - x counter-clockwise onto prev - x (90 deg
// at a convex corner of the domain, 270 deg at a re-entrant one, about 330 deg
// at a sharp trailing edge).
//  - Single normal: along the bisector, at theta / 2 from the outgoing edge.
//    A layer of depth d puts its node at x + d s n with the miter
//    s = min(1 / sin(theta / 2), max_scale), so the layer keeps the depth d from
//    both edges up to right-angle corners (s = sqrt 2) and thins at sharper ones.
//  - Multiple normals (a fan, Fig 4.7) where theta >= fan_angle: `fan` (odd)
//    normals at equal angles from the normal of the outgoing edge
//    (theta_1 = 90 deg) to that of the incoming edge (theta_m = theta - 90 deg),
//    the middle one on the bisector; equidistant displacement (s = 1).
//  - At the ends of an open wall the normal runs along the adjacent non-wall
//    boundary edge, so the layer's end nodes slide along that boundary and the
//    layers end on it; s = min(1 / sin theta, max_scale) keeps the depth d from
//    the wall edge (theta the angle between wall edge and boundary edge, which
//    must stay below max_end_angle).
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "core/mesh.h"
#include "layers/wall_loops.h"

namespace homesh {

struct NormalOptions {
  bool multi = false;          ///< fans at nodes whose domain angle reaches fan_angle
  int fan = 5;                 ///< normals per fan: odd, >= 3
  double fan_angle = 330;      ///< degrees, in [180, 360)
  double max_scale = M_SQRT2;  ///< cap of the single-normal miter 1 / sin(theta / 2)
  double max_end_angle = 160;  ///< degrees, largest domain angle at the end of an open wall
  /// Sweeps blending the single normals along the wall where it turns fast
  /// (blend_normals); 0: each node's own bisector. 3, chosen on the 24 layer cases
  /// of the corpus (scripts/bench/layers_corpus.py, p = 2..4): the worst minJ/maxJ
  /// after curving 0.846 -> 0.857 (the flap's nose), the mean unchanged; 10 sweeps
  /// gave 0.859 but lowered more of the easy cases.
  int blend = 3;
};

/// The normals at one wall node.
struct WallNormal {
  double angle = M_PI;  ///< domain angle theta, radians in (0, 2 pi]
  /// 1 (single) or `fan` unit directions, counter-clockwise from the outgoing edge's side.
  std::vector<Eigen::Vector2d> directions;
  double scale = 1;  ///< s above: depth d lies at x + d * scale * direction
};

/// Normals at wall node x between prev and next (domain on the left of
/// prev -> x -> next). A zero angle (prev and next in one direction) counts as
/// 2 pi, a slit. Throws homesh::Error on coincident points or bad options.
WallNormal wall_normal(const Eigen::Vector2d& prev, const Eigen::Vector2d& x,
                       const Eigen::Vector2d& next, const NormalOptions& opt = {});

/// The normal at the end x of an open wall: along the boundary edge from x to
/// `side`, the wall edge from x to `wall` (start: side = prev, wall = next; end:
/// the other way round), as above. Throws homesh::Error, naming x, if the domain
/// angle between them is max_end_angle or more.
WallNormal wall_end_normal(const Eigen::Vector2d& side, const Eigen::Vector2d& x,
                           const Eigen::Vector2d& wall, bool start, const NormalOptions& opt = {});

/// Blends, in place, the single normals of a loop along the wall where it turns
/// fast from node to node (a small nose radius under long wall edges: at a node
/// whose edges, or a neighbour's, turn by more than 30 deg, unless that node is
/// on a CAD point with neighbours turning by less than 10 deg, a corner of the
/// geometry; elsewhere the bisectors stay): `sweeps`
/// Jacobi sweeps d_i <- (d_(i-1) + 2 d_i + d_(i+1)) / |.|, a fan neighbour
/// giving its normal on the shared edge's side, each direction kept within
/// 30 deg of its bisector and 30 deg of either wall edge (inside the domain's
/// wedge); the miter becomes s = 1 / min(sin phi, sin(theta - phi)) (phi from
/// the outgoing edge; at most max_scale), so the layers keep their depth from
/// both edges' lines, as wall_normal's on the bisector. Fans and open ends are kept.
void blend_normals(const Mesh& m, const WallLoop& loop, std::vector<WallNormal>& normals,
                   int sweeps, double max_scale = M_SQRT2);

/// #loop nodes normals at the nodes of a loop of m (open ends by wall_end_normal),
/// blended by opt.blend sweeps.
std::vector<WallNormal> wall_normals(const Mesh& m, const WallLoop& loop,
                                     const NormalOptions& opt = {});

}  // namespace homesh
