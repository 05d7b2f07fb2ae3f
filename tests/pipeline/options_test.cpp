#include "pipeline/options.h"

#include <catch2/catch.hpp>

#include "core/error.h"
#include "pipeline/stage_registry.h"

using namespace homesh;

TEST_CASE("stage calls parse name and key=value pairs", "[pipeline]") {
  const StageCall c = parse_stage_call("layers:walls=aerofoil,hole:n=15:first=1e-3");
  REQUIRE(c.name == "layers");
  REQUIRE(c.given.size() == 3);
  REQUIRE(c.given.at("walls") == "aerofoil,hole");
  REQUIRE(c.given.at("first") == "1e-3");
  REQUIRE(parse_stage_call("info").given.empty());
  REQUIRE_THROWS_WITH(parse_stage_call(":p=2"), Catch::Contains("empty stage name"));
  REQUIRE_THROWS_WITH(parse_stage_call("order:p"), Catch::Contains("expected key=value"));
  REQUIRE_THROWS_WITH(parse_stage_call("order:p=2:p=3"), Catch::Contains("given twice"));
}

TEST_CASE("options fall back to defaults and reject bad values by name", "[pipeline]") {
  const std::vector<OptionSpec> specs = {{"p", "2", ""}, {"r", "0.5", ""}, {"m", "Q4,Q17", ""},
                                         {"keep", "false", ""}};
  const Options o("order", specs, {{"p", "4"}});
  REQUIRE(o.get_int("p", 1, 10) == 4);
  REQUIRE(o.get_double("r") == 0.5);
  REQUIRE(o.get_list("m") == std::vector<std::string>{"Q4", "Q17"});
  REQUIRE_FALSE(o.get_bool("keep"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"q", "1"}}),
                      Catch::Contains("unknown option 'q'") && Catch::Contains("p, r, m, keep"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"p", "0"}}).get_int("p", 1, 10),
                      Catch::Contains("p=0") && Catch::Contains("out of range [1, 10]"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"p", "4x"}}).get_int("p", 1, 10),
                      Catch::Contains("not an integer"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"r", "nan"}}).get_double("r"),
                      Catch::Contains("not a finite number"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"r", ""}}).get_double("r"),
                      Catch::Contains("not a number"));
  REQUIRE_THROWS_WITH(Options("order", specs, {{"keep", "maybe"}}).get_bool("keep"),
                      Catch::Contains("not a boolean"));
  const std::vector<OptionSpec> choice = {{"v", "fixed", ""}};
  REQUIRE(Options("curve", choice, {}).get_choice("v", {"fixed", "free"}) == "fixed");
  REQUIRE(Options("curve", choice, {{"v", "free"}}).get_choice("v", {"fixed", "free"}) == "free");
  REQUIRE_THROWS_WITH(Options("curve", choice, {{"v", "x"}}).get_choice("v", {"fixed", "free"}),
                      Catch::Contains("stage 'curve': option v=x: expected fixed or free"));
  REQUIRE_THROWS_WITH(Options("curve", choice, {{"v", "x"}}).get_choice("v", {"a", "b", "c"}),
                      Catch::Contains("expected a, b or c"));
}

TEST_CASE("the stage registry lists each stage once with documented options", "[pipeline]") {
  std::vector<std::string> names;
  for (const Stage& s : stages()) {
    REQUIRE_FALSE(s.summary.empty());
    for (const auto& o : s.options) REQUIRE_FALSE(o.help.empty());
    REQUIRE(std::find(names.begin(), names.end(), s.name) == names.end());
    names.push_back(s.name);
    REQUIRE(&stage(s.name) == &s);
  }
  for (const char* required : {"mesh", "order", "info"})
    REQUIRE(std::find(names.begin(), names.end(), required) != names.end());
  std::string listed;
  for (const auto& n : names) listed += (listed.empty() ? "" : ", ") + n;
  REQUIRE_THROWS_WITH(stage("curv"), Catch::Contains("unknown stage 'curv'") &&
                                         Catch::Contains("(stages: " + listed + ")"));
}
