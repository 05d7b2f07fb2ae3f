// The registry of quality measures: names, lookup, errors, documentation.
#include "quality/measure_registry.h"

#include <catch2/catch.hpp>
#include <set>

#include "core/error.h"

namespace homesh {

TEST_CASE("the registry lists Q1 .. Q17 without Q15, in order", "[quality]") {
  std::vector<std::string> names;
  for (const Measure& m : measures()) names.push_back(m.name);
  CHECK(names == std::vector<std::string>{"Q1", "Q2", "Q3", "Q4", "Q5", "Q6", "Q7", "Q8", "Q9",
                                          "Q10", "Q11", "Q12", "Q13", "Q14", "Q16", "Q17"});
}

TEST_CASE("every entry is documented and has the functions its kind needs", "[quality]") {
  std::set<std::string> titles;
  for (const Measure& m : measures()) {
    INFO(m.name);
    CHECK(!m.formula.empty());
    CHECK(!m.normalisation.empty());
    CHECK(m.source.rfind("Eq 3.", 0) == 0);
    CHECK(titles.insert(m.title).second);
    CHECK(m.raw != nullptr);
    CHECK(m.pointwise() == (m.element == nullptr));
    CHECK(m.pointwise() == (m.name != "Q1"));
  }
  // The thesis normalises by the element maximum exactly these (Eq 3.49 text).
  std::vector<std::string> max_normalised;
  for (const Measure& m : measures()) {
    if (m.thesis_max_normalised) max_normalised.push_back(m.name);
  }
  CHECK(max_normalised == std::vector<std::string>{"Q2", "Q3", "Q4", "Q5", "Q17"});
}

TEST_CASE("measure() finds names case-insensitively", "[quality]") {
  CHECK(&measure("Q7") == &measures()[6]);
  CHECK(measure("q17").name == "Q17");
}

TEST_CASE("measure() rejects unknown names, listing the valid ones", "[quality]") {
  REQUIRE_THROWS_AS(measure("Q99"), Error);
  try {
    measure("Q99");
  } catch (const Error& e) {
    const std::string message = e.what();
    CHECK(message.find("'Q99'") != std::string::npos);
    CHECK(message.find("Q1, Q2, Q3") != std::string::npos);
    CHECK(message.find("Q16, Q17") != std::string::npos);
  }
  try {
    measure("Q15");
    FAIL("Q15 accepted");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("Salem") != std::string::npos);
  }
}

}  // namespace homesh
