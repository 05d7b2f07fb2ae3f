#include "element/quadrature.h"

#include <string>

#include "core/error.h"

namespace homesh {
namespace {

// Number of Gauss points exact to `degree` in one variable: 2n - 1 >= degree.
int gauss_points(int degree, const char* what) {
  if (degree < 0) throw Error(std::string(what) + ": degree " + std::to_string(degree) + " < 0");
  return degree / 2 + 1;
}

}  // namespace

QuadratureRule triangle_quadrature(int degree) {
  const int n = gauss_points(degree, "triangle_quadrature");
  const LineQuadratureRule s = gauss_jacobi(n, 0.0, 0.0);
  const LineQuadratureRule t = gauss_jacobi(n, 1.0, 0.0);
  QuadratureRule rule;
  rule.points.resize(2, n * n);
  rule.weights.resize(n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int q = j * n + i;
      rule.points.col(q) << s.points(i) * (1.0 - t.points(j)), t.points(j);
      rule.weights(q) = s.weights(i) * t.weights(j);
    }
  }
  return rule;
}

TetQuadratureRule tetrahedron_quadrature(int degree) {
  const int n = gauss_points(degree, "tetrahedron_quadrature");
  const LineQuadratureRule r = gauss_jacobi(n, 0.0, 0.0);
  const LineQuadratureRule s = gauss_jacobi(n, 1.0, 0.0);
  const LineQuadratureRule t = gauss_jacobi(n, 2.0, 0.0);
  TetQuadratureRule rule;
  rule.points.resize(3, n * n * n);
  rule.weights.resize(n * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int q = (k * n + j) * n + i;
        const double tk = t.points(k), sj = s.points(j);
        rule.points.col(q) << r.points(i) * (1.0 - sj) * (1.0 - tk), sj * (1.0 - tk), tk;
        rule.weights(q) = r.weights(i) * s.weights(j) * t.weights(k);
      }
  return rule;
}

LineQuadratureRule line_quadrature(int degree) {
  return gauss_jacobi(gauss_points(degree, "line_quadrature"), 0.0, 0.0);
}

}  // namespace homesh
