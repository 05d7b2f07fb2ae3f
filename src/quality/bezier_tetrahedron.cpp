#include "quality/bezier_tetrahedron.h"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>

#include "core/error.h"

namespace homesh {
namespace {

void check_degree(int d, const char* who) {
  if (d < 0 || d > kMaxTetBezierDegree)
    throw Error(std::string(who) + ": degree " + std::to_string(d) + " out of range 0.." +
                std::to_string(kMaxTetBezierDegree));
}

// All n Bernstein functions of degree d at the barycentric point l (l[1..3] = u, v, w).
Eigen::RowVectorXd bernstein(int d, const Eigen::Matrix3Xi& idx, const double l[4]) {
  double pw[4][kMaxTetBezierDegree + 1];
  for (int r = 0; r < 4; ++r) {
    pw[r][0] = 1;
    for (int e = 1; e <= d; ++e) pw[r][e] = pw[r][e - 1] * l[r];
  }
  double fact[kMaxTetBezierDegree + 1];
  fact[0] = 1;
  for (int e = 1; e <= d; ++e) fact[e] = fact[e - 1] * e;
  Eigen::RowVectorXd B(idx.cols());
  for (Eigen::Index k = 0; k < idx.cols(); ++k) {
    const int i = idx(0, k), j = idx(1, k), t = idx(2, k), m = d - i - j - t;
    B(k) = fact[d] / (fact[i] * fact[j] * fact[t] * fact[m]) * pw[1][i] * pw[2][j] * pw[3][t] *
           pw[0][m];
  }
  return B;
}

Eigen::RowVectorXd bernstein_at(int d, const Eigen::Matrix3Xi& idx, const Eigen::Vector3d& x) {
  const double l[4] = {1 - x.sum(), x(0), x(1), x(2)};
  return bernstein(d, idx, l);
}

// Per degree: the multi-indices, the inverse collocation matrix and the children's matrices.
struct Tables {
  Eigen::Matrix3Xi idx;
  Eigen::MatrixXd from_values;           // n by n: lattice values -> coefficients
  std::array<Eigen::MatrixXd, 8> child;  // n by n: parent coefficients -> child's
};

const Tables& tables(int d) {
  static std::array<std::unique_ptr<Tables>, kMaxTetBezierDegree + 1> made;
  static std::array<std::once_flag, kMaxTetBezierDegree + 1> once;
  std::call_once(once[d], [d] {
    auto t = std::make_unique<Tables>();
    t->idx = tetrahedron_bezier_indices(d);
    const Eigen::Index n = t->idx.cols();
    const Eigen::Matrix3Xd lattice = t->idx.cast<double>() / std::max(d, 1);
    Eigen::MatrixXd C(n, n);  // C(i, k) = B_k(lattice point i)
    for (Eigen::Index i = 0; i < n; ++i) C.row(i) = bernstein_at(d, t->idx, lattice.col(i));
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(C);
    t->from_values = lu.inverse();
    for (int s = 0; s < 8; ++s) {
      const Eigen::Matrix<double, 3, 4> W = tetrahedron_child(s);
      Eigen::MatrixXd E(n, n);  // the parent's basis at the child's lattice points
      for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d y = lattice.col(i);
        const Eigen::Vector3d x =
            W.col(0) * (1 - y.sum()) + W.col(1) * y(0) + W.col(2) * y(1) + W.col(3) * y(2);
        E.row(i) = bernstein_at(d, t->idx, x);
      }
      t->child[s] = lu.solve(E);
    }
    made[d] = std::move(t);
  });
  return *made[d];
}

}  // namespace

Eigen::Matrix3Xi tetrahedron_bezier_indices(int d) {
  check_degree(d, "tetrahedron_bezier_indices");
  Eigen::Matrix3Xi idx(3, tetrahedron_bezier_size(d));
  int k = 0;
  for (int s = 0; s <= d; ++s)  // i + j + l = s
    for (int l = 0; l <= s; ++l)
      for (int j = 0; j <= s - l; ++j) idx.col(k++) << s - j - l, j, l;
  return idx;
}

Eigen::VectorXd tetrahedron_bezier_from_values(int d, const Eigen::Ref<const Eigen::VectorXd>& f) {
  check_degree(d, "tetrahedron_bezier_from_values");
  if (f.size() != tetrahedron_bezier_size(d))
    throw Error("tetrahedron_bezier_from_values: degree " + std::to_string(d) + " needs " +
                std::to_string(tetrahedron_bezier_size(d)) + " values, got " +
                std::to_string(f.size()));
  return tables(d).from_values * f;
}

double tetrahedron_bezier_value(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                const Eigen::Vector3d& uvw) {
  check_degree(d, "tetrahedron_bezier_value");
  return bernstein_at(d, tables(d).idx, uvw).dot(c);
}

void tetrahedron_bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                                  Eigen::Ref<Eigen::MatrixXd> sub) {
  const Tables& t = tables(d);
  for (int s = 0; s < 8; ++s) sub.col(s).noalias() = t.child[s] * c;
}

Eigen::Matrix<double, 3, 4> tetrahedron_child(int s) {
  const Eigen::Vector3d v[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  auto mid = [&](int a, int b) -> Eigen::Vector3d { return 0.5 * (v[a] + v[b]); };
  const Eigen::Vector3d m01 = mid(0, 1), m02 = mid(0, 2), m03 = mid(0, 3), m12 = mid(1, 2),
                        m13 = mid(1, 3), m23 = mid(2, 3);
  Eigen::Matrix<double, 3, 4> W;
  switch (s) {
    case 0:
      W << v[0], m01, m02, m03;
      break;
    case 1:
      W << m01, v[1], m12, m13;
      break;
    case 2:
      W << m02, m12, v[2], m23;
      break;
    case 3:
      W << m03, m13, m23, v[3];
      break;
    // The octahedron round its diagonal m02-m13: m01, m12, m23, m03 in turn.
    case 4:
      W << m02, m13, m01, m12;
      break;
    case 5:
      W << m02, m13, m12, m23;
      break;
    case 6:
      W << m02, m13, m23, m03;
      break;
    case 7:
      W << m02, m13, m03, m01;
      break;
    default:
      throw Error("tetrahedron_child: child " + std::to_string(s) + " out of range 0..7");
  }
  return W;
}

}  // namespace homesh
