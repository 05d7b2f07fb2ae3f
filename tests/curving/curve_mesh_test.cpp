#include "curving/curve_mesh.h"

#include <catch2/catch.hpp>
#include <cmath>

#include "../layers/layer_test_meshes.h"
#include "../quality/validity_test_support.h"
#include "quality/mesh_validity.h"

using namespace homesh;

namespace {

// The straight-sided unit square (3 by 3 squares, split) and its boundary nodes'
// targets: those of the bottom side moved onto the wave y = 0.08 sin(3 pi x), which bulges
// each of its edges by about a quarter of its length, the others where they are.
const Mesh square =
    test::channel_mesh(3, 3, [](double s, double t) { return Eigen::Vector2d(s, t); });

Eigen::Matrix2Xd on_wave(Mesh& raised) {
  Eigen::Matrix2Xd target = raised.x;
  for (int i = 0; i < raised.num_nodes(); ++i)
    if (std::abs(raised.x(1, i)) < 1e-12) target(1, i) = 0.08 * std::sin(3 * M_PI * raised.x(0, i));
  return target;
}

}  // namespace

// The curve stage writes the validity curving had at hand instead of bounding every element
// again: it must be the result's, whichever step ended the curving (the variants end it in
// step 3, step 1 polished, step 3 from the straight mesh, step 3 with every pass, step 1).
TEST_CASE("curve_mesh returns the certified validity of its result, whichever step ends it",
          "[curving]") {
  for (int p : {2, 3, 4})
    for (int variant = 0; variant < 5; ++variant) {
      CAPTURE(p, variant);
      CurveOptions opt;
      opt.order = p;
      if (variant == 1) {  // the guess kept, polished by a solve round its poor elements
        opt.accept_placed = 0.0;
        opt.polish_share = 1.0;
      }
      if (variant == 2) opt.accept_placed = 2.0;          // no guess: solved from the straight mesh
      if (variant == 3) opt.optimiser.threshold = 0.999;  // optimised, every pass
      if (variant == 4) opt.accept_placed = 0.0;          // the guess kept as it is
      const CurveResult r = curve_mesh(square, on_wave, opt);
      REQUIRE(r.validity.ratio.size() == r.mesh.num_elements_2d());
      const MeshValidity fresh = mesh_validity(r.mesh, opt.optimiser.bounds);
      test::require_same_validity(r.validity, fresh);
      CHECK(r.worst_ratio == fresh.worst);
      CHECK(fresh.invalid == 0);
    }
}
