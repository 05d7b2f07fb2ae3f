// The gallery of thesis Fig 3.12 as kept in geo/gallery_t1_t12.csv: the twelve
// elements with the orders and properties their descriptions require.
#include "optim/gallery.h"

#include <Eigen/LU>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "../support/temp_dir.h"
#include "core/error.h"
#include "element/reference_nodes.h"
#include "optim/ideal_element.h"
#include "quality/element_sampling.h"
#include "quality/jacobian_bounds.h"

using namespace homesh;

namespace {

const std::vector<GalleryElement>& gallery() {
  static const std::vector<GalleryElement> g =
      read_gallery(std::string(HOMESH_SOURCE_DIR) + "/geo/gallery_t1_t12.csv");
  return g;
}

// det J / det J of the ideal element at the order-18 lattice: (min, max).
std::pair<double, double> area_ratio_range(const GalleryElement& e) {
  const ElementSampling s(e.order, reference_nodes(18));
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k < s.size(); ++k) {
    const double omega = s.jacobian(e.nodes, k).determinant() / (std::sqrt(3.0) / 2);
    lo = std::min(lo, omega);
    hi = std::max(hi, omega);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("gallery: T1-T12 with the orders of Section 3.7.2, all valid", "[study]") {
  const std::vector<int> orders = {2, 2, 2, 2, 2, 2, 2, 3, 4, 3, 4, 4};
  REQUIRE(gallery().size() == 12);
  for (size_t i = 0; i < gallery().size(); ++i) {
    const GalleryElement& e = gallery()[i];
    INFO(e.name);
    CHECK(e.name == "T" + std::to_string(i + 1));
    CHECK(e.order == orders[i]);
    CHECK(e.description.rfind(e.name + " - ", 0) == 0);
    const JacobianBounds b = jacobian_bounds(e.nodes, e.order);
    CHECK(b.valid_certified);
  }
}

TEST_CASE("gallery: the elements are what their descriptions say", "[study]") {
  // T1 is the ideal element, T2 an affine shear at the ideal area.
  CHECK((gallery_element(gallery(), "T1").nodes - equilateral_element(2)).norm() < 1e-15);
  const auto t2 = area_ratio_range(gallery_element(gallery(), "T2"));
  CHECK(t2.first == Approx(1.0));
  CHECK(t2.second == Approx(1.0));
  // T3: det J of the ideal scaled by 0.16 at one corner, 1.6 at the others.
  const auto t3 = area_ratio_range(gallery_element(gallery(), "T3"));
  CHECK(t3.first == Approx(0.16));
  CHECK(t3.second == Approx(1.6));
  // T7: det J close to zero at one vertex (0.04 of the ideal).
  CHECK(area_ratio_range(gallery_element(gallery(), "T7")).first == Approx(0.04));
  // T4, T11: small vertex angles, so det J well below the ideal everywhere.
  CHECK(area_ratio_range(gallery_element(gallery(), "T4")).second < 0.6);
  CHECK(area_ratio_range(gallery_element(gallery(), "T11")).second < 0.8);
  // T8, T9: straight edges, only interior nodes moved.
  for (const char* name : {"T8", "T9"}) {
    const GalleryElement& e = gallery_element(gallery(), name);
    const Eigen::Matrix2Xd straight = equilateral_element(e.order);
    const int boundary_nodes = 3 * e.order;
    CHECK((e.nodes.leftCols(boundary_nodes) - straight.leftCols(boundary_nodes)).norm() < 1e-12);
    CHECK((e.nodes - straight).norm() > 0.05);
  }
}

TEST_CASE("gallery files are checked", "[study]") {
  const test::TempDir dir;
  const std::string path = dir / "bad_gallery.csv";
  const auto rejects = [&](const std::string& text) {
    std::ofstream(path) << text;
    CHECK_THROWS_AS(read_gallery(path), Error);
  };
  rejects("element,order,node,x\nT1,1,0,0\n");
  rejects("element,order,node,x,y\nT1,1,0,0,0\nT1,1,1,1,0\n");              // too few nodes
  rejects("element,order,node,x,y\nT1,1,0,0,0\nT1,1,2,1,0\nT1,1,1,0,1\n");  // out of order
  rejects("element,order,node,x,y\nT1,1,0,0,zero\n");
  CHECK_THROWS_AS(read_gallery("no/such/gallery.csv"), Error);
  CHECK_THROWS_AS(gallery_element(gallery(), "T13"), Error);
}
