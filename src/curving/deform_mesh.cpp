#include "curving/deform_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "core/error.h"
#include "core/progress.h"
#include "fem/solve_elasticity.h"
#include "quality/mesh_validity.h"

namespace homesh {

std::vector<bool> boundary_nodes(const Mesh& m) {
  std::vector<bool> b(static_cast<std::size_t>(m.num_nodes()));
  for (int i = 0; i < m.num_nodes(); ++i) b[i] = m.node_class[i].dim < 2;
  return b;
}

namespace {

// 3 for a triangle, 4 for a quadrilateral: its corners head its nodes.
int corner_count(const Mesh& m, int e) { return e < m.num_triangles() ? 3 : 4; }

}  // namespace

std::vector<bool> vertex_nodes(const Mesh& m) {
  std::vector<bool> v(static_cast<std::size_t>(m.num_nodes()), false);
  for (int e = 0; e < m.num_elements_2d(); ++e) {
    const auto nodes = element_node_indices(m, e);
    for (int k = 0; k < corner_count(m, e); ++k) v[nodes(k)] = true;
  }
  return v;
}

std::vector<int> moving_region(const Mesh& m, const std::vector<bool>& moving, int layers) {
  const int n = m.num_elements_2d();
  std::vector<bool> reached = moving, selected(n, false);
  for (int layer = 0; layer < layers; ++layer) {
    for (int e = 0; e < n; ++e) {
      const auto nodes = element_node_indices(m, e);
      for (Eigen::Index i = 0; i < nodes.size() && !selected[e]; ++i)
        selected[e] = reached[nodes(i)];
    }
    for (int e = 0; e < n; ++e)
      if (selected[e]) {
        const auto nodes = element_node_indices(m, e);
        for (Eigen::Index i = 0; i < nodes.size(); ++i) reached[nodes(i)] = true;
      }
  }
  std::vector<int> region;
  for (int e = 0; e < n; ++e)
    if (selected[e]) region.push_back(e);
  return region;
}

std::vector<int> reach_region(const Mesh& m, const std::vector<bool>& moving, double reach) {
  // The disks (corner centroid, reach * longest edge) of the elements touching
  // a moving node, hashed on a grid of their mean diameter.
  const int n = m.num_elements_2d();
  std::vector<Eigen::Vector2d> centre;
  std::vector<double> radius;
  for (int e = 0; e < n; ++e) {
    const auto nodes = element_node_indices(m, e);
    bool touches = false;
    for (Eigen::Index i = 0; i < nodes.size() && !touches; ++i) touches = moving[nodes(i)];
    if (!touches) continue;
    const int corners = corner_count(m, e);
    double h = 0;
    for (int a = 0; a < corners; ++a)
      h = std::max(h, (m.x.col(nodes(a)) - m.x.col(nodes((a + 1) % corners))).norm());
    centre.push_back(m.corner_centroid(e));
    radius.push_back(reach * h);
  }
  std::vector<int> region;
  if (centre.empty()) return region;
  double cell = 0;
  for (double r : radius) cell += 2 * r / double(radius.size());
  auto cell_of = [cell](double v) { return std::int32_t(std::floor(v / cell)); };
  // Cell (i, j) as a 64-bit key; unsigned, as i and j may be negative.
  auto key = [](std::int32_t i, std::int32_t j) {
    return (std::uint64_t(std::uint32_t(i)) << 32) | std::uint32_t(j);
  };
  std::unordered_map<std::uint64_t, std::vector<int>> grid;
  for (int k = 0; k < int(centre.size()); ++k) {
    const Eigen::Vector2d c = centre[k];
    const double r = radius[k];
    for (std::int32_t i = cell_of(c.x() - r); i <= cell_of(c.x() + r); ++i)
      for (std::int32_t j = cell_of(c.y() - r); j <= cell_of(c.y() + r); ++j)
        grid[key(i, j)].push_back(k);
  }
  auto near = [&](int node) {
    const Eigen::Vector2d x = m.x.col(node);
    const auto it = grid.find(key(cell_of(x.x()), cell_of(x.y())));
    if (it == grid.end()) return false;
    for (int k : it->second)
      if ((x - centre[k]).norm() <= radius[k]) return true;
    return false;
  };
  for (int e = 0; e < n; ++e) {
    const auto nodes = element_node_indices(m, e);
    bool in = false;
    for (int a = 0; a < corner_count(m, e) && !in; ++a) in = near(nodes(a));
    if (in) region.push_back(e);
  }
  return region;
}

namespace {

// deform_mesh on the submesh of moving_region or reach_region: its nodes
// shared with the rest of the mesh are held where they are.
DeformResult deform_region(const Mesh& m, const Eigen::Matrix2Xd& target,
                           const std::vector<bool>& prescribed, const DeformOptions& opt,
                           const KnownValidity& known) {
  std::vector<bool> moving(m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i) moving[i] = prescribed[i] && target.col(i) != m.x.col(i);
  const std::vector<int> region = !opt.region.empty() ? opt.region
                                  : opt.layers > 0    ? moving_region(m, moving, opt.layers)
                                                      : reach_region(m, moving, opt.reach);
  if (region.empty()) {
    DeformResult r{m, 1.0, true, 0, 0, 1.0, 0, 0, mesh_validity(m, known)};
    r.worst_ratio = r.validity.worst;
    return r;
  }
  const int num_2d = m.num_elements_2d(), num_tri = m.num_triangles();
  std::vector<bool> inside(num_2d, false), outside_node(m.num_nodes(), false);
  for (int e : region) {
    if (e < 0 || e >= num_2d)
      throw Error("deform_mesh: region element " + std::to_string(e) + " out of range 0.." +
                  std::to_string(num_2d - 1));
    inside[e] = true;
  }
  for (int e = 0; e < num_2d; ++e)
    if (!inside[e]) {
      const auto nodes = element_node_indices(m, e);
      for (Eigen::Index i = 0; i < nodes.size(); ++i) outside_node[nodes(i)] = true;
    }
  std::vector<int> local(m.num_nodes(), -1), global;
  Mesh sub;
  sub.order = m.order;
  const Eigen::Index sub_tri =
      std::count_if(region.begin(), region.end(), [num_tri](int e) { return e < num_tri; });
  sub.tri.resize(m.tri.rows(), sub_tri);
  sub.quad.resize(m.quad.rows(), Eigen::Index(region.size()) - sub_tri);
  Eigen::Index next_tri = 0, next_quad = 0;
  for (int e : region) {
    const auto nodes = element_node_indices(m, e);
    const bool triangle = e < num_tri;
    for (Eigen::Index i = 0; i < nodes.size(); ++i) {
      int& node = local[nodes(i)];
      if (node < 0) {
        node = int(global.size());
        global.push_back(nodes(i));
      }
      (triangle ? sub.tri(i, next_tri) : sub.quad(i, next_quad)) = node;
    }
    if (triangle) {
      if (!m.tri_entity.empty()) sub.tri_entity.push_back(m.tri_entity[e]);
      ++next_tri;
    } else {
      if (!m.quad_entity.empty()) sub.quad_entity.push_back(m.quad_entity[e - num_tri]);
      ++next_quad;
    }
  }
  sub.x.resize(2, Eigen::Index(global.size()));
  Eigen::Matrix2Xd sub_target(2, Eigen::Index(global.size()));
  std::vector<bool> sub_prescribed(global.size());
  for (std::size_t k = 0; k < global.size(); ++k) {
    const int i = global[k];
    sub.x.col(Eigen::Index(k)) = m.x.col(i);
    sub.node_class.push_back(m.node_class[i]);
    sub_prescribed[k] = prescribed[i] || outside_node[i];
    sub_target.col(Eigen::Index(k)) = prescribed[i] ? target.col(i) : m.x.col(i);
  }
  DeformOptions whole = opt;
  whole.layers = 0;
  whole.reach = 0;
  whole.region.clear();
  const DeformResult s = deform_mesh(sub, sub_target, sub_prescribed, whole);
  DeformResult r = s;
  r.mesh = m;
  for (std::size_t k = 0; k < global.size(); ++k)
    r.mesh.x.col(global[k]) = s.mesh.x.col(Eigen::Index(k));
  // Prescribed nodes in no element of the region (an explicit region, e.g. round
  // the poor elements of a placed mesh, need not hold every moving node) go to
  // their targets: left where they were, the curve stage's local solve kept the
  // hole of the plate straight-sided away from its poor elements (DOLFINx's
  // convergence study at p = 3 lost its rate).
  for (int i = 0; i < m.num_nodes(); ++i)
    if (prescribed[i] && local[i] < 0) r.mesh.x.col(i) = target.col(i);
  r.validity = mesh_validity(r.mesh, known);
  r.worst_ratio = r.validity.worst;
  r.solved_triangles = int(region.size());
  return r;
}

}  // namespace

DeformResult deform_mesh(const Mesh& m, const Eigen::Matrix2Xd& target,
                         const std::vector<bool>& prescribed, const DeformOptions& opt) {
  return deform_mesh(m, target, prescribed, opt, KnownValidity{});
}

DeformResult deform_mesh(const Mesh& m, const Eigen::Matrix2Xd& target,
                         const std::vector<bool>& prescribed, const DeformOptions& opt,
                         const KnownValidity& known) {
  if (target.cols() != m.num_nodes() ||
      prescribed.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("deform_mesh: target and prescribed must have one entry per node");
  if (opt.increments < 1) throw Error("deform_mesh: increments must be >= 1");
  if (opt.layers < 0) throw Error("deform_mesh: layers must be >= 0");
  if (!(opt.reach >= 0)) throw Error("deform_mesh: reach must be >= 0");
  if (!opt.region.empty() || opt.layers > 0 || opt.reach > 0)
    return deform_region(m, target, prescribed, opt, known);
  const AnalogyFormulation& formulation = analogy_formulation(opt.formulation);
  const Eigen::Matrix2Xd start = m.x;

  DeformResult r{m, 0.0, false, 0, 0, 1.0, 0, m.num_elements_2d(), {}};
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
  bool retrying = false;  // the last increment failed: re-solve with its factor
  Progress progress("boundary motion", 0);
  while (r.reached < 1.0 - 1e-12) {
    const double next = std::min(1.0, r.reached + step);
    progress.update(r.solves, std::to_string(std::lround(100 * r.reached)) + " % done, solve " +
                                  std::to_string(r.solves + 1));
    const DirichletBC bc = boundary_condition(next);
    const ElasticitySolution s =
        retrying ? solver.resolve(bc)
                 : solver.solve(r.mesh.x, formulation.coefficients(r.mesh, m, opt.params), bc);
    ++r.solves;
    r.iterations += s.iterations;

    Mesh trial = r.mesh;
    trial.x += s.u;
    MeshValidity v = mesh_validity(trial);
    if (v.invalid == 0) {
      r.mesh = std::move(trial);
      r.reached = next;
      r.worst_ratio = v.worst;
      r.validity = std::move(v);
      retrying = false;
      step = std::min(2 * step, full_step);
      continue;
    }
    if (r.invalid_at_failure == 0) r.invalid_at_failure = v.invalid;
    // A bound on the step, not a count of halvings in a row: after each
    // acceptance the step doubles, so a motion that creeps towards its
    // validity limit would halve and succeed forever in ever smaller steps.
    retrying = true;
    step *= 0.5;
    if (step < std::ldexp(full_step, -opt.max_halvings)) return r;
  }
  r.complete = true;
  r.invalid_at_failure = 0;
  return r;
}

}  // namespace homesh
