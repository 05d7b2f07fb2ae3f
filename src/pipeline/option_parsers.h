#pragma once
// Typed parsers of stage option values, as written on the command line
// (`-m curve:p=3:nu=0.45`), in the C++ API ({"p", "3"}) or from Python
// keyword arguments (p=3.0 arrives as "3.0"). Each parser reads a text into a
// value and shows a value as text (the defaults of `--help STAGE`, Python's
// homesh.stages() and the README reference are shown values of the options
// structs). A parser never throws: it returns why a text is refused, and the
// option table (pipeline/option_table.h) names the stage, option and value.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace homesh {

template <class V>
struct Parser {
  /// Stores the value of `text` in `out` and returns "", or returns why the
  /// text is refused ("not an integer") and leaves `out` unchanged.
  std::function<std::string(const std::string& text, V& out)> read;
  /// The text of a value, which read accepts.
  std::function<std::string(const V& value)> show;
};

/// An integer in [lo, hi]; "3" and "3.0" (or "3e0") read as 3, "3.5" is refused.
/// `words` name special values ({"all", kAllFrontRows}), shown by name.
Parser<int> integer(int lo, int hi, std::vector<std::pair<std::string, int>> words = {});

/// A finite number between lo and hi, each bound included or not as `bounds`
/// says: "[]", "()", "[)" or "(]" (infinite bounds: no limit).
Parser<double> real(double lo = -INFINITY, double hi = INFINITY, const char* bounds = "[]");

/// true/false, also 1/0, yes/no, on/off.
Parser<bool> boolean();

/// Any text, as given.
Parser<std::string> text();

/// One of `names` (exactly).
Parser<std::string> one_of(std::vector<std::string> names);

/// A comma-separated list (empty entries dropped), each entry read by `item`.
Parser<std::vector<std::string>> list(Parser<std::string> item = text());

/// "x,y" (two finite numbers), or `word` for none.
Parser<std::optional<Eigen::Vector2d>> point_or(std::string word);

/// "a | b | c", for help texts.
std::string names_text(const std::vector<std::string>& names);

/// One of the names of `choices`, read as its value (bool, enum, ...).
template <class V>
Parser<V> choice(std::vector<std::pair<std::string, V>> choices) {
  Parser<V> p;
  p.read = [choices](const std::string& s, V& out) -> std::string {
    std::string expected;
    for (std::size_t k = 0; k < choices.size(); ++k) {
      if (choices[k].first == s) {
        out = choices[k].second;
        return "";
      }
      expected += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k].first;
    }
    return "expected " + expected;
  };
  p.show = [choices](const V& v) -> std::string {
    for (const auto& [name, value] : choices)
      if (value == v) return name;
    return "?";
  };
  return p;
}

/// `p`, also refusing the values where !ok(value), saying `why` ("must be odd").
template <class V>
Parser<V> where(Parser<V> p, std::function<bool(const V&)> ok, std::string why) {
  auto read = p.read;
  p.read = [read, ok, why](const std::string& s, V& out) -> std::string {
    V v = out;
    const std::string refused = read(s, v);
    if (!refused.empty()) return refused;
    if (!ok(v)) return why;
    out = v;
    return "";
  };
  return p;
}

}  // namespace homesh
