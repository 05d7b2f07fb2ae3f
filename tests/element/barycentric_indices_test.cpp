#include "element/barycentric_indices.h"

#include <catch2/catch.hpp>

#include "core/error.h"
#include "element/reference_nodes.h"
#include "element/tet_reference_nodes.h"

using namespace homesh;

TEST_CASE("barycentric_indices: weights times p of the corners at each Gmsh node",
          "[element][barycentric_indices]") {
  for (int p = 1; p <= 6; ++p) {
    INFO("p = " << p);
    const Eigen::MatrixXi line = barycentric_indices(2, p), tri = barycentric_indices(3, p),
                          tet = barycentric_indices(4, p);
    CHECK(line.cols() == p + 1);
    CHECK(tri.cols() == (p + 1) * (p + 2) / 2);
    CHECK(tet.cols() == (p + 1) * (p + 2) * (p + 3) / 6);
    for (const Eigen::MatrixXi* b : {&line, &tri, &tet}) {
      CHECK(b->minCoeff() >= 0);
      CHECK((b->colwise().sum().array() == p).all());
    }
    // The node at the weights: the reference coordinates are the last rows / p.
    const Eigen::RowVectorXd s = reference_line_nodes(p);
    const Eigen::Matrix2Xd uv = reference_nodes(p);
    const Eigen::Matrix3Xd uvw = tetrahedron_nodes(p);
    for (Eigen::Index k = 0; k < line.cols(); ++k) CHECK(line(1, k) == Approx(p * s(k)));
    for (Eigen::Index k = 0; k < tri.cols(); ++k)
      CHECK((tri.bottomRows<2>().col(k).cast<double>() - p * uv.col(k)).norm() < 1e-12);
    for (Eigen::Index k = 0; k < tet.cols(); ++k)
      CHECK((tet.bottomRows<3>().col(k).cast<double>() - p * uvw.col(k)).norm() < 1e-12);
  }
  CHECK_THROWS_AS(barycentric_indices(5, 2), Error);
  CHECK_THROWS_AS(barycentric_indices(2, 0), Error);
}
