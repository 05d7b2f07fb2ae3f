#include "optim/thesis_tables.h"

#include <catch2/catch.hpp>

#include "core/error.h"

using namespace homesh;

TEST_CASE("thesis tables: CSV cells by row and column, empty cells kept", "[study]") {
  const ThesisTable t =
      read_thesis_table(std::string(HOMESH_REFERENCE_DIR) + "/table_3_3_3_5_praxis_iterations.csv");
  CHECK(t.rows.size() == 16);
  CHECK(t.at("Q3", "quadratic_interior_N") == "451");
  CHECK(t.at("Q10", "cubic_interior_N") == "692");
  CHECK(t.at("Q5", "cubic_interior_N").empty());
  CHECK_FALSE(t.has("Q15", "cubic_interior_N"));
  CHECK_THROWS_AS(t.at("Q3", "no_column"), Error);
  CHECK_THROWS_AS(read_thesis_table("no/such/table.csv"), Error);
}

TEST_CASE("thesis tables: the Table 3.6 orderings with their ties", "[study]") {
  const SensitivityOrderings o = read_sensitivity_orderings(std::string(HOMESH_REFERENCE_DIR) +
                                                            "/table_3_6_curvature_sensitivity.txt");
  size_t convex = 0, concave = 0;
  for (const auto& group : o.convex) convex += group.size();
  for (const auto& group : o.concave) concave += group.size();
  CHECK(convex == 16);
  CHECK(concave == 16);
  CHECK(o.convex.front() == std::vector<std::string>{"Q10"});
  CHECK(o.concave.front() == std::vector<std::string>{"Q8", "Q16"});
  CHECK(o.concave.back() == std::vector<std::string>{"Q13"});
}
