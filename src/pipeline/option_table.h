#pragma once
// A stage's options, declared once: each row ties a key to a member of the
// options struct the stage hands to its library entry point, with a typed
// parser (pipeline/option_parsers.h) and a help text. The struct's default
// member values are the defaults: `--help STAGE`, Python's homesh.stages() and
// the README reference (scripts/gen_reference.py) show them through the table
// (NekMesh's ConfigOption, with typed members instead of strings).
//
//   OptionTable<LayerOptions> t;
//   t.add("n", &LayerOptions::layers, integer(1, 1000), "number of layers");
//   t.add("nu", [](LayerOptions& o) -> double& { return o.room.params.poisson; },
//         real(-1, 0.5, "()"), "Poisson's ratio");
//   LayerOptions o = t.parse("layers", {{"n", "15"}});   // the rest: defaults
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "pipeline/option_parsers.h"
#include "pipeline/options.h"

namespace homesh {

template <class T>
class OptionTable {
 public:
  /// Adds option `key` read by `parser` into the member `member` gives: a
  /// pointer to a data member of T, or a callable T& -> V&.
  template <class V, class Member>
  OptionTable& add(std::string key, Member member, Parser<V> parser, std::string help) {
    const std::function<V&(T&)> at = member;
    rows_.push_back(
        {std::move(key), std::move(help),
         [at, read = parser.read](T& o, const std::string& s) { return read(s, at(o)); },
         [at, show = parser.show](T& o) { return show(at(o)); }});
    return *this;
  }

  /// Adds a check of the options together (e.g. size_min <= size_max): "" if
  /// they are acceptable, else why not.
  OptionTable& check(std::function<std::string(const T&)> whole) {
    checks_.push_back(std::move(whole));
    return *this;
  }

  /// The defaults of T with the `given` options read over them. Throws
  /// homesh::Error naming `stage`, the option and its value if a key is
  /// unknown or a value refused, or naming the stage if a check fails.
  T parse(const std::string& stage, const std::map<std::string, std::string>& given) const {
    T o{};
    for (const auto& [key, value] : given) {
      const Row* row = find(key);
      if (!row) {
        std::string known;
        for (const Row& r : rows_) known += (known.empty() ? "" : ", ") + r.key;
        throw Error("stage '" + stage + "': unknown option '" + key +
                    "' (options: " + (known.empty() ? "none" : known) + ")");
      }
      const std::string refused = row->read(o, value);
      if (!refused.empty())
        throw Error("stage '" + stage + "': option " + key + "=" + value + ": " + refused +
                    separator_hint(stage, key, value));
    }
    for (const auto& whole : checks_) {
      const std::string refused = whole(o);
      if (!refused.empty()) throw Error("stage '" + stage + "': " + refused);
    }
    return o;
  }

  /// Key, default (shown from T()) and help of every option, in table order.
  std::vector<OptionSpec> specs() const {
    std::vector<OptionSpec> out;
    T defaults = T();  // not T{}: GCC 12 warns falsely (maybe-uninitialized) on its strings
    for (const Row& r : rows_) out.push_back({r.key, r.show(defaults), r.help});
    return out;
  }

 private:
  struct Row {
    std::string key;
    std::string help;
    std::function<std::string(T&, const std::string&)> read;
    std::function<std::string(T&)> show;
  };

  const Row* find(const std::string& key) const {
    for (const Row& r : rows_)
      if (r.key == key) return &r;
    return nullptr;
  }

  // "p=3,nu=0.3" is one value: if a comma is followed by another option's
  // key=, say how options are separated.
  std::string separator_hint(const std::string& stage, const std::string& key,
                             const std::string& value) const {
    std::string fixed = value;
    bool found = false;
    for (auto c = fixed.find(','); c != std::string::npos; c = fixed.find(',', c + 1)) {
      const auto eq = fixed.find('=', c);
      if (eq != std::string::npos && find(fixed.substr(c + 1, eq - c - 1))) {
        fixed[c] = ':';
        found = true;
      }
    }
    return found ? " (options are separated by ':', as in " + stage + ":" + key + "=" + fixed + ")"
                 : "";
  }

  std::vector<Row> rows_;
  std::vector<std::function<std::string(const T&)>> checks_;
};

}  // namespace homesh
