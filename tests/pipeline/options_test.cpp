#include "pipeline/options.h"

#include <catch2/catch.hpp>

#include "core/error.h"
#include "pipeline/option_table.h"
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

namespace {

template <class V>
std::string refused(const Parser<V>& p, const std::string& text) {
  V v{};
  return p.read(text, v);
}

template <class V>
V value(const Parser<V>& p, const std::string& text) {
  V v{};
  REQUIRE(p.read(text, v).empty());
  return v;
}

}  // namespace

TEST_CASE("parsers read typed values and say why they refuse one", "[pipeline]") {
  const Parser<int> p = integer(1, 10);
  CHECK(value(p, "4") == 4);
  CHECK(value(p, "3.0") == 3);
  CHECK(value(p, "3e0") == 3);
  CHECK(refused(p, "3.5") == "not an integer");
  CHECK(refused(p, "4x") == "not an integer");
  CHECK(refused(p, "nan") == "not an integer");
  CHECK(refused(p, "") == "not an integer");
  CHECK(refused(p, "0") == "out of range [1, 10]");
  CHECK(refused(p, "1e30") == "out of range [1, 10]");
  const Parser<int> rows = integer(0, 5, {{"all", 1000}});
  CHECK(value(rows, "all") == 1000);
  CHECK(rows.show(1000) == "all");
  CHECK(rows.show(2) == "2");
  CHECK(refused(rows, "some") == "not an integer nor 'all'");

  CHECK(value(real(), "1e-3") == 1e-3);
  CHECK(refused(real(), "inf") == "not a finite number");
  CHECK(refused(real(), " 1") == "not a finite number");
  CHECK(refused(real(-1, 0.5, "()"), "0.5") == "out of range (-1, 0.5)");
  CHECK(value(real(-1, 0.5, "(]"), "0.5") == 0.5);
  CHECK(refused(real(0, INFINITY, "(]"), "0") == "must be > 0");
  CHECK(refused(real(0), "-1") == "must be >= 0");
  CHECK(real().show(0.001) == "0.001");

  CHECK(value(boolean(), "yes"));
  CHECK_FALSE(value(boolean(), "off"));
  CHECK(boolean().show(true) == "true");
  CHECK(refused(one_of({"a", "b", "c"}), "x") == "expected a, b or c");
  CHECK(refused(choice<bool>({{"fixed", true}, {"free", false}}), "x") == "expected fixed or free");
  CHECK(choice<bool>({{"fixed", true}, {"free", false}}).show(false) == "free");
  CHECK(value(list(), "a,,b") == std::vector<std::string>{"a", "b"});
  CHECK(refused(list(one_of({"a", "b"})), "a,c") == "'c': expected a or b");
  CHECK(list().show({"Q4", "Q17"}) == "Q4,Q17");
  CHECK(*value(point_or("auto"), "1,-2.5") == Eigen::Vector2d(1, -2.5));
  CHECK_FALSE(value(point_or("auto"), "auto"));
  CHECK(refused(point_or("auto"), "1") == "expected auto or two numbers x,y");
  CHECK(point_or("auto").show(std::nullopt) == "auto");
  const Parser<int> odd = where<int>(
      integer(3, 99), [](const int& n) { return n % 2; }, "must be odd");
  CHECK(refused(odd, "4") == "must be odd");
  CHECK(refused(odd, "1") == "out of range [3, 99]");
  CHECK(value(odd, "5") == 5);
}

namespace {

struct Inner {
  double nu = 0.4;
};
struct Sample {
  int p = 2;
  Inner inner;
  bool fixed = true;
};

OptionTable<Sample> sample_table() {
  OptionTable<Sample> t;
  t.add("p", &Sample::p, integer(1, 10), "order");
  t.add(
      "nu", [](Sample& s) -> double& { return s.inner.nu; }, real(-1, 0.5, "()"), "ratio");
  t.add("vertices", &Sample::fixed, choice<bool>({{"fixed", true}, {"free", false}}), "held");
  t.check([](const Sample& s) { return s.p == 7 && s.fixed ? "p = 7 needs vertices=free" : ""; });
  return t;
}

}  // namespace

TEST_CASE("an option table reads given options over the struct's defaults", "[pipeline]") {
  const OptionTable<Sample> t = sample_table();
  const std::vector<OptionSpec> specs = t.specs();
  REQUIRE(specs.size() == 3);
  CHECK(specs[0].name == "p");
  CHECK(specs[0].default_value == "2");
  CHECK(specs[1].default_value == "0.4");
  CHECK(specs[2].default_value == "fixed");
  const Sample s = t.parse("curve", {{"p", "3.0"}, {"vertices", "free"}});
  CHECK(s.p == 3);
  CHECK(s.inner.nu == 0.4);
  CHECK_FALSE(s.fixed);
  CHECK_THROWS_WITH(t.parse("curve", {{"q", "1"}}),
                    "stage 'curve': unknown option 'q' (options: p, nu, vertices)");
  CHECK_THROWS_WITH(t.parse("curve", {{"p", "3.5"}}),
                    "stage 'curve': option p=3.5: not an integer");
  CHECK_THROWS_WITH(t.parse("curve", {{"p", "3,nu=0.3"}}),
                    "stage 'curve': option p=3,nu=0.3: not an integer (options are separated "
                    "by ':', as in curve:p=3:nu=0.3)");
  CHECK_THROWS_WITH(t.parse("curve", {{"p", "7"}}), "stage 'curve': p = 7 needs vertices=free");
  CHECK(t.parse("curve", {{"p", "7"}, {"vertices", "free"}}).p == 7);
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

TEST_CASE("every stage's defaults read back as themselves", "[pipeline]") {
  // The shown defaults are what --help, Python and the README list: each must
  // be a value its parser accepts; every stage but layers (walls) needs no option.
  for (const Stage& s : stages()) {
    CAPTURE(s.name);
    const std::map<std::string, std::string> none =
        s.name == "layers" ? std::map<std::string, std::string>{{"walls", "wall"}}
                           : std::map<std::string, std::string>{};
    REQUIRE_NOTHROW(s.parse(none));
    std::map<std::string, std::string> given = none;
    for (const OptionSpec& o : s.options)
      if (!o.default_value.empty()) given[o.name] = o.default_value;
    REQUIRE_NOTHROW(s.parse(given));
  }
  REQUIRE_THROWS_WITH(stage("layers").parse({}), Catch::Contains("stage 'layers': give the walls"));
}
