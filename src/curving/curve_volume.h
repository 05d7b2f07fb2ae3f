#pragma once
// Curving a tetrahedral mesh onto its CAD (issue 24): the 3D counterpart of
// curving/curve_mesh.h. The mesh is raised to order p with straight sides
// (core/raise_volume_order.h); every new node on a CAD curve or surface is put
// on it (curving/place_on_volume_cad.h); the displacement of those boundary nodes is
// carried into the volume by the elastic analogy (thesis Ch 4, Eq 4.13, in its
// 3D form fem/tet_elasticity.h), solved only on the tetrahedra within `rings`
// layers of those whose nodes moved, the rest of the mesh held.
#include <Eigen/Core>
#include <functional>

#include "core/volume_mesh.h"
#include "fem/linear_solver.h"
#include "quality/mesh_validity.h"

namespace homesh {

/// The CAD of a volume mesh's curves and surfaces, as the curving needs it (the
/// Gmsh adapter gives it: gmsh/volume_cad.h).
struct VolumeCad {
  /// Whether curve (dim 1) or surface (dim 2) `tag` has a geometry to put nodes on.
  std::function<bool(int dim, int tag)> has_geometry;
  /// The closest points on entity (dim, tag) to the columns of x (3 by n).
  std::function<Eigen::Matrix3Xd(int dim, int tag, const Eigen::Matrix3Xd& x)> closest;
  /// The points of entity (dim, tag) at the parameters (dim by n) (3 by n).
  std::function<Eigen::Matrix3Xd(int dim, int tag, const Eigen::MatrixXd& params)> value;
  /// The range of entity (dim, tag)'s parameters: dim by 2, lower then upper.
  std::function<Eigen::MatrixXd(int dim, int tag)> bounds;
  /// The derivatives at the parameters (dim by n): 3 dim by n, d/du then d/dv.
  std::function<Eigen::MatrixXd(int dim, int tag, const Eigen::MatrixXd& params)> derivatives;
  /// The parameters (dim by n: u, or u and v) of the points x on entity (dim,
  /// tag); NaN where they cannot be found.
  std::function<Eigen::MatrixXd(int dim, int tag, const Eigen::Matrix3Xd& x)> parameters;
  /// At the points x on entity (dim, tag): the unit normals of a surface, the
  /// unit tangents of a curve (3 by n); NaN where they cannot be found. The
  /// optimiser moves nodes on CAD in these planes and lines, projecting them
  /// back once per round.
  std::function<Eigen::Matrix3Xd(int dim, int tag, const Eigen::Matrix3Xd& x)> directions;
};

struct VolumeCurveOptions {
  /// p, 2 to kMaxTetrahedronOrder.
  int order = 2;
  /// Carry the boundary's displacement into the volume by the elastic analogy;
  /// false: only the boundary nodes move (as Gmsh's setOrder does).
  bool elastic = true;
  /// Poisson's ratio of the analogy.
  double nu = 0.4;
  /// Young's modulus of an element is its volume to the power -stiffening: the
  /// thesis' E = 1 / Ae (Sec 4.2.1) in 3D for 1, so small elements next to the
  /// wall deform least.
  double stiffening = 1.0;
  /// Layers of tetrahedra round those with a moved node that the solve takes
  /// in (beyond them the mesh is held).
  int rings = 1;
  /// Solve the analogy at order q, 2 <= q < p, on the mesh raised to q and
  /// placed on the CAD there, and give each order-p node inside the volume the
  /// displacement the order-q elements interpolate at it (the wall nodes are
  /// placed at order p as ever). 0 (or q >= p): solve at p. At p = 4, q = 2
  /// solves a system 8x smaller. On the 3D corpus at p = 3-4 (against the
  /// default, two-level CG at p = 4) q = 2 was faster in 18 of 24 runs, up to
  /// 5.7x, with 1.1-5.6x less memory (fine close spheres p = 4: 4.0 s and
  /// 0.23 GB against 11 s and 1.3 GB); but its worst fell in 19 (by up to
  /// 0.17: fine ellipsoid p = 4, 0.707 -> 0.534) and rose in 5 (the wing at
  /// p = 4: 0.573 -> 0.867), and where the optimiser then had more to do it
  /// was slower (coarse ellipsoid p = 4: 2.7 -> 8.5 s). Hence 0; q = 2 for
  /// meshes whose order-p solve would not fit in memory, or where time matters
  /// more than the last tenth of minJ/maxJ.
  int solve_order = 0;
  /// At p >= 4 with the "cg" solver: precondition CG by two levels, the
  /// solver's preconditioner (Jacobi) plus the same analogy at order 2 solved
  /// exactly (CHOLMOD) and interpolated (fem/two_level_preconditioner.h). The
  /// same mesh to the solver's tolerance in fewer iterations: on the fine torus
  /// at p = 4, 86 against 248; on the 3D corpus at p = 4 the solve 1.7-3.0x
  /// faster and the curving's peak memory 1.9-2.2x lower. At p = 3 the coarse
  /// factorisation cost more than the iterations it saved (fine torus: solve
  /// 2.8 s against 1.7 s), so there CG stays one-level.
  bool two_level = true;
  /// The solve: CG with the Jacobi preconditioner to 1e-6, which gave the same
  /// mesh (worst minJ/maxJ to 4 digits) in half CHOLMOD's time and memory on
  /// the 3D corpus at p = 4 (torus 10618 tetrahedra: 4.7 s and 1.0 GB against
  /// 9.5 s and 2.1 GB; wing 27035: 16 s and 2.1 GB against 20 s and 4.2 GB).
  LinearSolverOptions solver = {"cg", "jacobi", 1e-6, 0};
  /// Then optimise round the elements left below this certified minJ/maxJ
  /// (curving/optimise_volume.h; <= 0: never): up to three starts, the later
  /// ones sliding the linear mesh's vertices on the CAD, the last one ring wider.
  /// 0.5, chosen on the 3D corpus: the fine bracket's worst at p = 2 rises from
  /// 0.314 (0.3: no patch; Gmsh's HighOrderElastic 0.337) to 0.510 for 0.06 s;
  /// 0.7 lifts the fine meshes to 0.70-0.71 but doubles the bracket's time at
  /// p = 4 (9 -> 18 s) and triples the coarse ones' (which stay below it).
  double optimise_threshold = 0.5;
  int optimise_rings = 1;
  /// Split wall caps, tetrahedra with all four corners on the wall
  /// (core/split_tetrahedra.h: conforming, the children reproduce the
  /// parents). A cap with two wall faces and one edge on neither is squeezed
  /// flat between its curved wall faces and that edge where the wall is smooth
  /// (the edge lies on the wall too); if the solve leaves such a cap below
  /// optimise_threshold, that edge is split before the optimiser, giving the
  /// cap and its neighbours round the edge a vertex inside the volume. Caps
  /// still invalid after the optimiser are split (at that edge or their
  /// centroid) and optimised again, kept only if certified better. On the 3D
  /// corpus this mends the wing at p = 4 and the close spheres, and lifts the
  /// worst of 14 of its 36 runs (e.g. the coarse ellipsoid at p = 2 from 0.032
  /// to 0.53). false: the mesh's tetrahedra stay the caller's, and the caps
  /// may stay poor or invalid. Only with the optimiser on (optimise_threshold
  /// > 0).
  bool split_wall_caps = true;
};

struct VolumeCurveResult {
  /// Boundary nodes put on the CAD (of them, by projection: where the
  /// interpolated parameters failed), and the largest distance one moved.
  int placed = 0;
  int projected = 0;
  double largest_move = 0;
  /// Tetrahedra and unknowns of the elastic solve.
  int region = 0;
  int unknowns = 0;
  /// CG's iterations in the elastic solve (0 for a direct solver), and whether
  /// it was preconditioned by two levels (two_level).
  int iterations = 0;
  bool two_level = false;
  /// The optimiser's patches and those it kept, and the worst minJ/maxJ before it.
  int patches = 0, optimised = 0;
  /// Wall caps split, at an edge or their centroid (split_wall_caps); each
  /// split adds tetrahedra (an edge split as many as the edge has).
  int split = 0;
  double worst_before_optimiser = 1;
  /// Certified validity of the result (quality/volume_validity.h).
  MeshValidity validity;
  /// Wall seconds: raising and placing, solving, certifying, optimising.
  double seconds_place = 0, seconds_solve = 0, seconds_certify = 0, seconds_optimise = 0;
};

/// Curves m (linear or of any order: only its corners are kept) to order
/// o.order onto `cad`. Throws homesh::Error if o.order is out of range or the
/// solve fails.
VolumeCurveResult curve_volume(VolumeMesh& m, const VolumeCad& cad,
                               const VolumeCurveOptions& o = {});

}  // namespace homesh
