#include "fem/assemble_elasticity.h"

#include <string>
#include <vector>

#include "core/error.h"
#include "fem/element_load.h"
#include "fem/element_stiffness.h"
#include "fem/element_tabulation.h"

namespace homesh {
namespace {

// Lame's constants, body force and thermal stress (xx, yy, xy) at the points of g.
struct PointCoefficients {
  Eigen::VectorXd lambda, mu;
  Eigen::Matrix2Xd f;
  Eigen::Matrix3Xd sigma_t;
};

PointCoefficients evaluate(const ElasticityCoefficients& c, int e, const ElementGeometry& g) {
  const Eigen::Index nq = g.x.cols();
  PointCoefficients pc{Eigen::VectorXd(nq), Eigen::VectorXd(nq), Eigen::Matrix2Xd(2, nq),
                       Eigen::Matrix3Xd(3, nq)};
  for (Eigen::Index q = 0; q < nq; ++q) {
    const QuadraturePoint point{e, static_cast<int>(q), g.x.col(q)};
    const Lame lame = lame_plane_strain(c.young(point), c.poisson(point));
    pc.lambda(q) = lame.lambda;
    pc.mu(q) = lame.mu;
    pc.f.col(q) = c.body_force(point);
    const double s = c.beta(point) * (c.temperature(point) - c.reference_temperature);  // Eq 4.5
    const Eigen::Matrix2d S = c.anisotropic_stress(point);
    pc.sigma_t.col(q) << s + S(0, 0), s + S(1, 1), 0.5 * (S(0, 1) + S(1, 0));
  }
  return pc;
}

}  // namespace

LinearSystem assemble_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                 const AssemblyOptions& options) {
  const int n = triangle_node_count(m.order);
  if (m.tri.rows() != n)
    throw Error("assemble_elasticity: " + std::to_string(m.tri.rows()) +
                " nodes per triangle for order " + std::to_string(m.order));
  const ElementTabulation tab =
      tabulate_element(m.order, stiffness_quadrature_degree(m.order, options.quadrature_margin));
  const int num_dofs = 2 * m.num_nodes();

  LinearSystem sys;
  sys.b = Eigen::VectorXd::Zero(num_dofs);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(static_cast<size_t>(m.num_triangles()) * 4 * n * n + m.num_nodes());
  std::vector<char> used(m.num_nodes(), 0);
  std::vector<int> dof(2 * n);
  for (int e = 0; e < m.num_triangles(); ++e) {
    Eigen::MatrixXd Ke;
    Eigen::VectorXd fe;
    try {
      const ElementGeometry g = element_geometry(m.triangle_nodes(e), tab);
      const PointCoefficients pc = evaluate(c, e, g);
      Ke = element_stiffness(g, pc.lambda, pc.mu);
      fe = element_load(g, tab.N, pc.f, pc.sigma_t);
    } catch (const Error& error) {
      throw Error("assemble_elasticity: triangle " + std::to_string(e) + ": " + error.what());
    }
    // Element dof (c, i) at c n + i (Eq 4.14) is global dof 2 node + c.
    for (int i = 0; i < n; ++i) {
      const int node = m.tri(i, e);
      used[node] = 1;
      dof[i] = 2 * node;
      dof[n + i] = 2 * node + 1;
    }
    for (int a = 0; a < 2 * n; ++a) {
      sys.b(dof[a]) += fe(a);
      for (int b = 0; b < 2 * n; ++b) triplets.emplace_back(dof[a], dof[b], Ke(a, b));
    }
  }
  for (int node = 0; node < m.num_nodes(); ++node) {
    if (used[node]) continue;
    triplets.emplace_back(2 * node, 2 * node, 1.0);
    triplets.emplace_back(2 * node + 1, 2 * node + 1, 1.0);
  }
  sys.K.resize(num_dofs, num_dofs);
  sys.K.setFromTriplets(triplets.begin(), triplets.end());
  return sys;
}

}  // namespace homesh
