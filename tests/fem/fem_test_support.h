#pragma once
// Meshes, exact fields and error norms shared by the fem tests.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/raise_order.h"
#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "fem/assemble_elasticity.h"
#include "fem/dirichlet.h"
#include "fem/elasticity_coefficients.h"
#include "fem/element_geometry.h"
#include "fem/element_tabulation.h"

namespace homesh::fem_test {

/// The affine displacement of the patch tests, u(x) = G x + s: every element
/// of any order must reproduce it exactly, with the constant strain sym(G).
inline const Eigen::Matrix2d kPatchGradient =
    (Eigen::Matrix2d() << 0.02, -0.05, 0.03, 0.04).finished();
inline const Eigen::Vector2d kPatchShift(0.01, -0.02);
inline Eigen::Vector2d patch_field(const Eigen::Vector2d& x) {
  return kPatchGradient * x + kPatchShift;
}

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

// n by n cells of the unit square [0, 1]^2 at order p, straight-sided: the
// cells of the first `quad_columns` columns (x < quad_columns / n) are
// quadrilaterals, the others are cut along their diagonal into two triangles
// (as unit_square), all counter-clockwise. The high-order nodes are the images
// of the reference nodes (affine on a triangle, bilinear on a quadrilateral),
// shared between elements. Boundary nodes are classified on curves (dim 1),
// the four corners of the square on points (dim 0). With `corner_map`, the
// cell corners go to corner_map(corner) and every element stays
// straight-sided between them (its other nodes interpolated as above): a
// structured mixed mesh of another domain, its nodes classified by their
// position on the square.
inline Mesh mixed_square(
    int n, int p, int quad_columns,
    const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& corner_map = nullptr) {
  Mesh m;
  m.order = p;
  std::map<std::pair<long, long>, int> index;  // node at (i, j) / (n p)
  std::vector<Eigen::Vector2d> x, mapped;
  // Node at y of the square, at z once mapped.
  auto node = [&](const Eigen::Vector2d& y, const Eigen::Vector2d& z) {
    const std::pair<long, long> key(std::lround(y(0) * n * p), std::lround(y(1) * n * p));
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    x.push_back(Eigen::Vector2d(double(key.first), double(key.second)) / double(n * p));
    mapped.push_back(z);
    return index[key] = int(x.size()) - 1;
  };
  auto map = [&](const Eigen::Vector2d& y) { return corner_map ? corner_map(y) : y; };
  const Eigen::Matrix2Xd tri_ref = reference_nodes(p), quad_ref = quad_reference_nodes(p);
  std::vector<Eigen::VectorXi> tris, quads;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector2d a(double(i) / n, double(j) / n), b(double(i + 1) / n, double(j) / n),
          c(double(i + 1) / n, double(j + 1) / n), d(double(i) / n, double(j + 1) / n);
      const Eigen::Vector2d A = map(a), B = map(b), C = map(c), D = map(d);
      if (i < quad_columns) {
        Eigen::VectorXi q(quad_ref.cols());
        for (Eigen::Index k = 0; k < quad_ref.cols(); ++k) {
          const double u = quad_ref(0, k), v = quad_ref(1, k);
          auto bilinear = [u, v](const Eigen::Vector2d& w00, const Eigen::Vector2d& w10,
                                 const Eigen::Vector2d& w11, const Eigen::Vector2d& w01) {
            return Eigen::Vector2d((1 - u) * (1 - v) * w00 + u * (1 - v) * w10 + u * v * w11 +
                                   (1 - u) * v * w01);
          };
          q(k) = node(bilinear(a, b, c, d), bilinear(A, B, C, D));
        }
        quads.push_back(q);
        continue;
      }
      for (const auto& corners : {std::array<Eigen::Vector2d, 6>{a, b, c, A, B, C},
                                  std::array<Eigen::Vector2d, 6>{a, c, d, A, C, D}}) {
        Eigen::VectorXi t(tri_ref.cols());
        for (Eigen::Index k = 0; k < tri_ref.cols(); ++k) {
          const double u = tri_ref(0, k), v = tri_ref(1, k);
          t(k) = node(corners[0] + u * (corners[1] - corners[0]) + v * (corners[2] - corners[0]),
                      corners[3] + u * (corners[4] - corners[3]) + v * (corners[5] - corners[3]));
        }
        tris.push_back(t);
      }
    }
  // Number the nodes by position ((i, j) lexicographic), whatever the cells'
  // kinds: two such meshes of one n and p have the same nodes.
  std::vector<int> rank(x.size());
  std::vector<Eigen::Vector2d> position(x.size());
  int next = 0;
  for (const auto& entry : index) {
    x[std::size_t(next)] =
        Eigen::Vector2d(double(entry.first.first), double(entry.first.second)) / double(n * p);
    position[std::size_t(next)] =
        corner_map ? mapped[std::size_t(entry.second)] : x[std::size_t(next)];
    rank[std::size_t(entry.second)] = next++;
  }
  for (auto* elements : {&tris, &quads})
    for (Eigen::VectorXi& e : *elements)
      for (Eigen::Index k = 0; k < e.size(); ++k) e(k) = rank[std::size_t(e(k))];
  m.x.resize(2, Eigen::Index(x.size()));
  for (std::size_t k = 0; k < x.size(); ++k) m.x.col(Eigen::Index(k)) = position[k];
  m.node_class.resize(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const bool on_x = x[k](0) < 1e-12 || x[k](0) > 1 - 1e-12;
    const bool on_y = x[k](1) < 1e-12 || x[k](1) > 1 - 1e-12;
    m.node_class[k].dim = on_x && on_y ? 0 : on_x || on_y ? 1 : 2;
  }
  m.tri.resize(triangle_node_count(p), Eigen::Index(tris.size()));
  for (std::size_t e = 0; e < tris.size(); ++e) m.tri.col(Eigen::Index(e)) = tris[e];
  m.quad.resize(quad_node_count(p), Eigen::Index(quads.size()));
  for (std::size_t e = 0; e < quads.size(); ++e) m.quad.col(Eigen::Index(e)) = quads[e];
  m.tri_entity.assign(tris.size(), 1);
  m.quad_entity.assign(quads.size(), 1);
  return m;
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
// a rule of degree 2p + 8 on each element (per variable on quadrilaterals).
inline ErrorNorms error_norms(const Mesh& m, const Eigen::Matrix2Xd& U, const VectorField& u,
                              const Gradient& grad, double lambda, double mu) {
  const ElementTabulation tri_tab = tabulate_element(m.order, 2 * m.order + 8);
  const ElementTabulation quad_tab = tabulate_quad_element(m.order, 2 * m.order + 8);
  double l2 = 0.0, energy = 0.0;
  for (int e = 0; e < m.num_elements_2d(); ++e) {
    const bool quad = e >= m.num_triangles();
    const int local = quad ? e - m.num_triangles() : e;
    const ElementTabulation& tab = quad ? quad_tab : tri_tab;
    const Eigen::MatrixXi& nodes = quad ? m.quad : m.tri;
    const ElementGeometry g =
        element_geometry(quad ? m.quad_nodes(local) : m.triangle_nodes(local), tab);
    Eigen::Matrix2Xd Ue(2, nodes.rows());
    for (Eigen::Index i = 0; i < nodes.rows(); ++i) Ue.col(i) = U.col(nodes(i, local));
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

// The manufactured solution of the convergence tests (triangles and quadrilaterals).
// u = (sin(pi x) sin(pi y), e^x cos y); with constant Lame constants
// div sigma = mu lap(u) + (lambda + mu) grad(div u), so f = -div sigma with
//   lap(u) = (-2 pi^2 sin(pi x) sin(pi y), 0),
//   grad(div u) = (-pi^2 sin(pi x) sin(pi y) - e^x sin y, pi^2 cos(pi x) cos(pi y) - e^x cos y).
inline Eigen::Vector2d manufactured_exact(const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1);
  return {std::sin(M_PI * x) * std::sin(M_PI * y), std::exp(x) * std::cos(y)};
}

inline Eigen::Matrix2d manufactured_gradient(const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1);
  Eigen::Matrix2d G;
  G << M_PI * std::cos(M_PI * x) * std::sin(M_PI * y),
      M_PI * std::sin(M_PI * x) * std::cos(M_PI * y), std::exp(x) * std::cos(y),
      -std::exp(x) * std::sin(y);
  return G;
}

inline Eigen::Vector2d manufactured_body_force(const Lame& l, const Eigen::Vector2d& p) {
  const double x = p(0), y = p(1), pi2 = M_PI * M_PI;
  const double ss = std::sin(M_PI * x) * std::sin(M_PI * y);
  const Eigen::Vector2d laplacian(-2.0 * pi2 * ss, 0.0);
  const Eigen::Vector2d grad_div(
      -pi2 * ss - std::exp(x) * std::sin(y),
      pi2 * std::cos(M_PI * x) * std::cos(M_PI * y) - std::exp(x) * std::cos(y));
  return -(l.mu * laplacian + (l.lambda + l.mu) * grad_div);
}

/// The system the solver tests share: unit_square(n, p) warped by 0.04, E =
/// young (1 + 4 x y) (a factor 5 across), nu = 0.45, body force (0.3, -1), the
/// boundary sheared by u = (0.1 y, 0) and eliminated (bc_out: those conditions).
inline LinearSystem sheared_square_system(int n, int p, double young = 1.0,
                                          DirichletBC* bc_out = nullptr) {
  Mesh m = unit_square(n, p);
  const std::vector<int> boundary = square_boundary(m);
  warp(m, 0.04);
  ElasticityCoefficients c;
  c.young = [young](const QuadraturePoint& q) { return young * (1.0 + 4.0 * q.x(0) * q.x(1)); };
  c.poisson = 0.45;
  c.body_force = Eigen::Vector2d(0.3, -1.0);
  LinearSystem sys = assemble_elasticity(m, c);
  DirichletBC bc;
  for (int i : boundary) bc.fix(i, Eigen::Vector2d(0.1 * m.x(1, i), 0.0));
  if (bc_out) *bc_out = bc;
  apply_dirichlet(bc, sys);
  return sys;
}

}  // namespace homesh::fem_test
