#include "curving/boundary_reconstruction.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "element/gauss_jacobi.h"
#include "element/reference_nodes.h"

namespace homesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The C2 cubic spline through knots y.col(i) at parameters t[i], stored by its
// second derivatives M.col(i) (Press et al., Numerical Recipes, 3rd ed., 3.3).
// A closed spline repeats its first knot at the end.
struct Spline {
  std::vector<double> t;
  Eigen::Matrix2Xd y, M;

  // Position and derivative on segment i at local coordinate s in [0, 1].
  Eigen::Vector2d value(int i, double s) const {
    const double h = t[i + 1] - t[i], a = 1 - s, b = s;
    return a * y.col(i) + b * y.col(i + 1) +
           ((a * a * a - a) * M.col(i) + (b * b * b - b) * M.col(i + 1)) * (h * h / 6);
  }
  Eigen::Vector2d derivative(int i, double s) const {
    const double h = t[i + 1] - t[i], a = 1 - s, b = s;
    return (y.col(i + 1) - y.col(i)) / h +
           (-(3 * a * a - 1) * M.col(i) + (3 * b * b - 1) * M.col(i + 1)) * (h / 6);
  }
};

// Chordal spline through the columns of v; closed: periodic, the segment from
// the last column back to the first included; open: not-a-knot ends.
Spline fit_spline(const Eigen::Matrix2Xd& v, bool closed) {
  const int n = static_cast<int>(v.cols());
  const int knots = closed ? n + 1 : n;
  Spline sp;
  sp.y.resize(2, knots);
  sp.y.leftCols(n) = v;
  if (closed) sp.y.col(n) = v.col(0);
  sp.t.assign(knots, 0.0);
  for (int i = 1; i < knots; ++i) {
    const double h = (sp.y.col(i) - sp.y.col(i - 1)).norm();
    if (!(h > 0)) throw Error("boundary reconstruction: a boundary line has zero length");
    sp.t[i] = sp.t[i - 1] + h;
  }
  sp.M = Eigen::Matrix2Xd::Zero(2, knots);
  const int segments = knots - 1;
  if (segments < 2 || (closed && n < 3)) return sp;  // straight edges

  auto h = [&](int i) { return sp.t[i + 1] - sp.t[i]; };
  auto slope = [&](int i) -> Eigen::Vector2d { return (sp.y.col(i + 1) - sp.y.col(i)) / h(i); };
  const int unknowns = n;  // closed: the repeated last knot shares M with the first
  std::vector<Eigen::Triplet<double>> a;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(unknowns, 2);
  // Continuity of the first derivative at knot i between segments i - 1 and i.
  auto smooth = [&](int row, int i, int prev_seg, int next_seg, int im, int ip) {
    a.emplace_back(row, im, h(prev_seg));
    a.emplace_back(row, i, 2 * (h(prev_seg) + h(next_seg)));
    a.emplace_back(row, ip, h(next_seg));
    rhs.row(row) = 6 * (slope(next_seg) - slope(prev_seg)).transpose();
  };
  if (closed) {
    for (int i = 0; i < n; ++i) smooth(i, i, (i + n - 1) % n, i, (i + n - 1) % n, (i + 1) % n);
  } else {
    for (int i = 1; i < n - 1; ++i) smooth(i, i, i - 1, i, i - 1, i + 1);
    if (n == 3) {  // the parabola: constant second derivative
      a.insert(a.end(), {{0, 0, 1.0}, {0, 1, -1.0}, {2, 1, 1.0}, {2, 2, -1.0}});
    } else {  // not-a-knot: the third derivative is continuous at knots 1 and n - 2
      a.insert(a.end(), {{0, 0, h(1)}, {0, 1, -(h(0) + h(1))}, {0, 2, h(0)}});
      const int e = n - 1;
      a.insert(a.end(),
               {{e, e - 2, h(e - 1)}, {e, e - 1, -(h(e - 2) + h(e - 1))}, {e, e, h(e - 2)}});
    }
  }
  Eigen::SparseMatrix<double> A(unknowns, unknowns);
  A.setFromTriplets(a.begin(), a.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  if (lu.info() != Eigen::Success) throw Error("boundary reconstruction: singular spline system");
  const Eigen::MatrixX2d second = lu.solve(rhs);
  sp.M.leftCols(n) = second.transpose();
  if (closed) sp.M.col(n) = sp.M.col(0);
  return sp;
}

// Local coordinate on segment i whose arc length from the segment's start is
// the fraction f of the segment's length.
double arc_length_coordinate(const Spline& sp, int i, double f) {
  static const LineQuadratureRule rule = gauss_jacobi(8, 0, 0);
  auto length = [&](double s) {
    double l = 0;
    for (int q = 0; q < rule.points.size(); ++q)
      l += rule.weights(q) * s * sp.derivative(i, s * rule.points(q)).norm();
    return l;
  };
  const double want = f * length(1.0);
  double s = f;
  for (int it = 0; it < 50; ++it) {
    const double step = (length(s) - want) / sp.derivative(i, s).norm();
    s = std::min(1.0, std::max(0.0, s - step));
    if (std::abs(step) < 1e-15) break;
  }
  return s;
}

// A chain of boundary vertices and the lines between consecutive ones.
struct Chain {
  std::vector<int> vertices;  // closed chains do not repeat the first vertex
  std::vector<int> lines;     // lines[i] joins vertices[i] and vertices[i + 1 (mod n)]
  bool closed = false;
};

}  // namespace

bool rebuilt_corner(const Eigen::Vector2d& in, const Eigen::Vector2d& out, bool same_curve,
                    double corner_degrees) {
  return !same_curve || in.dot(out) < std::cos(corner_degrees * kPi / 180) * in.norm() * out.norm();
}

BoundaryReconstruction reconstruct_boundary(const Mesh& m,
                                            const BoundaryReconstructionOptions& opt) {
  if (!(opt.corner_degrees > 0 && opt.corner_degrees < 180))
    throw Error("boundary reconstruction: corner angle " + std::to_string(opt.corner_degrees) +
                " degrees is not in (0, 180)");
  BoundaryReconstruction out;
  out.target = m.x;

  std::unordered_map<int, std::vector<int>> incident;  // vertex -> lines
  for (int k = 0; k < m.num_lines(); ++k)
    for (int e = 0; e < 2; ++e) incident[m.line(e, k)].push_back(k);
  auto other = [&](int k, int v) { return m.line(0, k) == v ? m.line(1, k) : m.line(0, k); };

  std::unordered_map<int, bool> is_end;
  for (const auto& [v, lines] : incident) {
    bool end = lines.size() != 2 || m.line_entity[lines[0]] != m.line_entity[lines[1]];
    if (!end) {
      const Eigen::Vector2d in = m.x.col(v) - m.x.col(other(lines[0], v));
      const Eigen::Vector2d outgoing = m.x.col(other(lines[1], v)) - m.x.col(v);
      end = rebuilt_corner(in, outgoing, true, opt.corner_degrees);
      out.corners += end;
    }
    is_end[v] = end;
  }

  std::vector<bool> used(m.num_lines(), false);
  auto walk = [&](int start, int first_line) {
    Chain c;
    c.vertices.push_back(start);
    int v = start, k = first_line;
    while (true) {
      used[k] = true;
      c.lines.push_back(k);
      v = other(k, v);
      if (v == start && !is_end[v]) {
        c.closed = true;
        return c;
      }
      c.vertices.push_back(v);
      if (is_end[v]) return c;
      const auto& next = incident[v];
      k = next[0] == k ? next[1] : next[0];
    }
  };
  std::vector<Chain> chains;
  for (int k = 0; k < m.num_lines(); ++k)
    for (int e = 0; e < 2; ++e)
      if (!used[k] && is_end[m.line(e, k)]) chains.push_back(walk(m.line(e, k), k));
  for (int k = 0; k < m.num_lines(); ++k)
    if (!used[k]) chains.push_back(walk(m.line(0, k), k));

  const int p = m.order;
  const Eigen::RowVectorXd r = reference_line_nodes(p);
  for (const Chain& c : chains) {
    (c.closed ? out.closed_loops : out.chains) += 1;
    Eigen::Matrix2Xd v(2, c.vertices.size());
    for (std::size_t i = 0; i < c.vertices.size(); ++i) v.col(i) = m.x.col(c.vertices[i]);
    const Spline sp = fit_spline(v, c.closed);
    for (std::size_t i = 0; i < c.lines.size() && p > 1; ++i) {
      const int k = c.lines[i];
      const bool forward = m.line(0, k) == c.vertices[i];
      for (int j = 2; j <= p; ++j) {
        const double f = forward ? r(j) : 1 - r(j);
        out.target.col(m.line(j, k)) =
            sp.value(static_cast<int>(i), arc_length_coordinate(sp, static_cast<int>(i), f));
      }
    }
  }
  return out;
}

}  // namespace homesh
