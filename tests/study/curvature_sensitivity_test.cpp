// Curvature of a boundary edge (thesis Figs 3.30-3.32, Table 3.6).
#include "optim/curvature_sensitivity.h"

#include <catch2/catch.hpp>
#include <map>
#include <set>

using namespace homesh;

TEST_CASE("curvature: f = 0 for the straight edge (chi = 0) for every measure", "[study]") {
  for (const Measure& m : measures()) {
    INFO(m.name);
    CHECK(curvature_distortion(m, 0.0) < 1e-12);
    CHECK(curvature_distortion(m, 0.05) > 1e-3);
    CHECK(curvature_distortion(m, -0.05) > 1e-3);
  }
}

TEST_CASE("curvature: concave costs more than convex, except Q3, Q10 (and Q2, Q5 beyond 0.1)",
          "[study]") {
  // The thesis finds f(concave) > f(convex) at equal |chi| for every measure
  // (Table 3.6 note). Ours agrees for twelve at every |chi|. Q3 and Q10 are
  // larger on the convex side from |chi| = 0.05 on (Q10 keeps the exponent
  // 2/3 in 2D, so a shrinking element offsets its shape distortion), and Q2,
  // Q5 (Q / Qmax, which the thesis says barely tell the two apart) from 0.15.
  const std::map<double, std::set<std::string>> exceptions = {{0.05, {"Q3", "Q10"}},
                                                              {0.1, {"Q3", "Q10"}},
                                                              {0.15, {"Q2", "Q3", "Q5", "Q10"}},
                                                              {0.2, {"Q2", "Q3", "Q5", "Q10"}}};
  for (const auto& [chi, names] : exceptions) {
    for (const Measure& m : measures()) {
      INFO(m.name << " chi = " << chi);
      const bool concave_larger = curvature_distortion(m, chi) > curvature_distortion(m, -chi);
      CHECK(concave_larger == (names.count(m.name) == 0));
    }
  }
}

TEST_CASE("curvature: our sensitivity orderings follow Table 3.6", "[study]") {
  const SensitivityOrderings thesis = read_sensitivity_orderings(
      std::string(HOMESH_REFERENCE_DIR) + "/table_3_6_curvature_sensitivity.txt");
  const Ordering convex = rank_by_value(curvature_distortions(-0.2));
  const Ordering concave = rank_by_value(curvature_distortions(0.2));
  CHECK(ordering_correlation(convex, thesis.convex) > 0.9);
  CHECK(ordering_correlation(concave, thesis.concave) > 0.6);
  // Algebraic identities show as ties: Q2 = Q5 and Q6 = Q7 = Q11 = Q12.
  const auto tied = [](const Ordering& o, const std::set<std::string>& names) {
    for (const auto& group : o) {
      if (std::set<std::string>(group.begin(), group.end()) == names) return true;
    }
    return false;
  };
  CHECK(tied(convex, {"Q2", "Q5"}));
  CHECK(tied(convex, {"Q6", "Q7", "Q11", "Q12"}));
  CHECK(tied(concave, {"Q2", "Q5"}));
  // The most sensitive to concave edges: Q8 first, as in the thesis, then Q4.
  CHECK(concave[0] == std::vector<std::string>{"Q8"});
  CHECK(concave[1] == std::vector<std::string>{"Q4"});
  CHECK(ordering_correlation(thesis.convex, thesis.convex) == Approx(1.0));
  CHECK(to_string(Ordering{{"Q8", "Q16"}, {"Q4"}}) == "Q8 = Q16 > Q4");
}
