#include "curving/deform_mesh.h"

#include <algorithm>

#include "core/error.h"
#include "fem/solve_elasticity.h"
#include "quality/mesh_validity.h"

namespace homesh {

std::vector<bool> boundary_nodes(const Mesh& m) {
  std::vector<bool> b(static_cast<std::size_t>(m.num_nodes()));
  for (int i = 0; i < m.num_nodes(); ++i) b[i] = m.node_class[i].dim < 2;
  return b;
}

DeformResult deform_mesh(const Mesh& m, const Eigen::Matrix2Xd& target,
                         const std::vector<bool>& prescribed, const DeformOptions& opt) {
  if (target.cols() != m.num_nodes() || prescribed.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("deform_mesh: target and prescribed must have one entry per node");
  if (opt.increments < 1) throw Error("deform_mesh: increments must be >= 1");
  const AnalogyFormulation& formulation = analogy_formulation(opt.formulation);
  const Eigen::Matrix2Xd start = m.x;

  DeformResult r{m, 0.0, false, 0, 0, 1.0, 0};
  // The prescribed dofs are the same at every increment: one pattern, one
  // symbolic analysis. A halved increment keeps the mesh, hence the stiffness
  // and loads: it only needs new prescribed values (resolve).
  auto boundary_condition = [&](double fraction) {
    DirichletBC bc;
    for (int i = 0; i < m.num_nodes(); ++i)
      if (prescribed[i])
        bc.fix(i, Eigen::Vector2d(start.col(i) + fraction * (target.col(i) - start.col(i)) -
                                  r.mesh.x.col(i)));
    return bc;
  };
  ElasticitySolver solver(m, boundary_condition(0.0), {opt.params.assembly, opt.solver});
  const double full_step = 1.0 / opt.increments;
  double step = full_step;
  int halvings = 0;
  while (r.reached < 1.0 - 1e-12) {
    const double next = std::min(1.0, r.reached + step);
    const DirichletBC bc = boundary_condition(next);
    const ElasticitySolution s =
        halvings == 0
            ? solver.solve(r.mesh.x, formulation.coefficients(r.mesh, m, opt.params), bc)
            : solver.resolve(bc);
    ++r.solves;
    r.iterations += s.iterations;

    Mesh trial = r.mesh;
    trial.x += s.u;
    const MeshValidity v = mesh_validity(trial);
    if (v.invalid == 0) {
      r.mesh = std::move(trial);
      r.reached = next;
      r.worst_ratio = v.worst;
      halvings = 0;
      step = std::min(2 * step, full_step);
      continue;
    }
    if (r.invalid_at_failure == 0) r.invalid_at_failure = v.invalid;
    if (++halvings > opt.max_halvings) return r;
    step *= 0.5;
  }
  r.complete = true;
  r.invalid_at_failure = 0;
  return r;
}

}  // namespace homesh
