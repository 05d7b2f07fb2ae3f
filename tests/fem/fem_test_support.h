#pragma once
// Meshes, exact fields and error norms shared by the fem tests.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "core/mesh.h"
#include "core/raise_order.h"
#include "fem/element_geometry.h"
#include "fem/element_tabulation.h"

namespace homesh::fem_test {

// Structured n by n linear triangles on the parameter square [0, 1]^2 (each cell
// cut along its diagonal, both triangles counter-clockwise), raised to order p
// with straight sides.
inline Mesh unit_square(int n, int p) {
  Mesh m;
  m.x.resize(2, (n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.x.col(j * (n + 1) + i) << double(i) / n, double(j) / n;
  m.node_class.resize(m.x.cols());
  m.tri.resize(3, 2 * n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int v00 = j * (n + 1) + i, v10 = v00 + 1, v01 = v00 + n + 1, v11 = v01 + 1;
      const int e = 2 * (j * n + i);
      m.tri.col(e) << v00, v10, v11;
      m.tri.col(e + 1) << v00, v11, v01;
    }
  }
  m.tri_entity.assign(m.tri.cols(), 1);
  return raise_order(m, p);
}

// Nodes of the unit square on its boundary (before any perturbation).
inline std::vector<int> square_boundary(const Mesh& m) {
  std::vector<int> nodes;
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double x = m.x(0, i), y = m.x(1, i);
    if (std::min({x, y, 1.0 - x, 1.0 - y}) < 1e-12) nodes.push_back(i);
  }
  return nodes;
}

// Moves every node by the smooth map x -> x + a (sin(2 pi y + 1), sin(2 pi x + 2)),
// one-to-one for |a| < 1 / (2 pi): straight elements become curved ones
// (boundary included) and stay valid at every order.
inline void warp(Mesh& m, double a) {
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double x = m.x(0, i), y = m.x(1, i);
    m.x.col(i) += a * Eigen::Vector2d(std::sin(2 * M_PI * y + 1), std::sin(2 * M_PI * x + 2));
  }
}

// The quarter annulus a <= r <= b, 0 <= theta <= pi/2: unit_square(n, 2n) mapped
// (s, t) -> r = a + (b - a) s, theta = pi/2 t, node by node, so every high-order
// node of the circles lies exactly on them (isoparametric curved elements).
inline Mesh quarter_annulus(int n, int p, double a, double b) {
  Mesh m = unit_square(n, p);
  for (int i = 0; i < m.num_nodes(); ++i) {
    const double r = a + (b - a) * m.x(0, i), theta = 0.5 * M_PI * m.x(1, i);
    m.x.col(i) << r * std::cos(theta), r * std::sin(theta);
  }
  return m;
}

using VectorField = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;
using Gradient = std::function<Eigen::Matrix2d(const Eigen::Vector2d&)>;  // du_i/dx_j

struct ErrorNorms {
  double l2 = 0.0;      // ||u_h - u||_L2
  double energy = 0.0;  // (int eps(e) : C eps(e))^1/2, e = u_h - u
};

// Errors of the nodal displacement U (2 by #nodes) against the exact field, by
// a rule of degree 2p + 8 on each element.
inline ErrorNorms error_norms(const Mesh& m, const Eigen::Matrix2Xd& U, const VectorField& u,
                              const Gradient& grad, double lambda, double mu) {
  const ElementTabulation tab = tabulate_element(m.order, 2 * m.order + 8);
  double l2 = 0.0, energy = 0.0;
  Eigen::Matrix2Xd Ue(2, m.tri.rows());
  for (int e = 0; e < m.num_triangles(); ++e) {
    const ElementGeometry g = element_geometry(m.triangle_nodes(e), tab);
    for (Eigen::Index i = 0; i < m.tri.rows(); ++i) Ue.col(i) = U.col(m.tri(i, e));
    const Eigen::Matrix2Xd uh = Ue * tab.N;
    const Eigen::Matrix2Xd dx = Ue * g.dNdx, dy = Ue * g.dNdy;
    for (Eigen::Index q = 0; q < g.x.cols(); ++q) {
      Eigen::Matrix2d G;
      G << dx.col(q), dy.col(q);
      G -= grad(g.x.col(q));
      const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
      l2 += g.weight(q) * (uh.col(q) - u(g.x.col(q))).squaredNorm();
      energy += g.weight(q) * (2.0 * mu * eps.squaredNorm() + lambda * eps.trace() * eps.trace());
    }
  }
  return {std::sqrt(l2), std::sqrt(energy)};
}

// Nodal interpolant of a field.
inline Eigen::Matrix2Xd interpolate(const Mesh& m, const VectorField& u) {
  Eigen::Matrix2Xd U(2, m.num_nodes());
  for (int i = 0; i < m.num_nodes(); ++i) U.col(i) = u(m.x.col(i));
  return U;
}

}  // namespace homesh::fem_test
