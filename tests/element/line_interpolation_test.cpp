#include "element/line_interpolation.h"

#include <catch2/catch.hpp>

using namespace homesh;

TEST_CASE("interpolation on a line reproduces a polynomial of degree n - 1 through n points",
          "[element]") {
  auto f = [](double s) -> Eigen::Vector2d {
    return {1 - 2 * s + 3 * s * s * s, 0.5 * s * s - s * s * s};
  };
  Eigen::VectorXd t(4);
  t << 0, 1, 0.3, 0.7;  // any order, as a line's nodes in Gmsh's
  Eigen::Matrix2Xd y(2, 4);
  for (int j = 0; j < 4; ++j) y.col(j) = f(t(j));
  for (double s : {-0.5, 0.0, 0.15, 0.5, 0.9, 2.0})
    CHECK((interpolate_on_line(t, y, s) - f(s)).norm() < 1e-12);
  // One point: the constant.
  CHECK(interpolate_on_line(t.head(1), y.leftCols(1), 0.4) == y.col(0));
}
