#include "fem/symmetric_product.h"

#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "core/error.h"

using namespace homesh;

TEST_CASE("SymmetricProduct multiplies by the matrix its lower triangle stands for",
          "[fem][symmetric_product]") {
  // Small (one run) and large enough to be shared among threads (>= 2e5 entries).
  for (const int n : {50, 20000}) {
    INFO("n = " << n);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_int_distribution<int> offset(1, 400);
    std::vector<Eigen::Triplet<double>> t;
    for (int c = 0; c < n; ++c) {
      t.emplace_back(c, c, 5.0 + value(rng));
      for (int k = 0; k < 12; ++k) {
        const int r = c + offset(rng);
        if (r < n) t.emplace_back(r, c, value(rng));
      }
    }
    Eigen::SparseMatrix<double> lower(n, n);
    lower.setFromTriplets(t.begin(), t.end());
    const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
    const Eigen::VectorXd x = Eigen::VectorXd::Random(n);
    const SymmetricProduct K(lower);
    Eigen::VectorXd y;
    for (int repeat = 0; repeat < 2; ++repeat) {  // its buffers are reused
      K.apply(x, y);
      CHECK((y - full * x).norm() <= 1e-13 * (full * x).norm());
    }
  }
  Eigen::SparseMatrix<double> rectangular(3, 2);
  rectangular.makeCompressed();
  CHECK_THROWS_AS(SymmetricProduct(rectangular), Error);
}
