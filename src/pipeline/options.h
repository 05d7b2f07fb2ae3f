#pragma once
// Stage options: `name:key=value:key=value` on the command line, each key
// declared by its stage with a default and a help text.
#include <map>
#include <string>
#include <vector>

namespace homesh {

/// One option a stage accepts.
struct OptionSpec {
  std::string name;
  std::string default_value;
  std::string help;
};

/// The options given to one stage, checked against its specs: typed getters
/// fall back to the declared default and throw homesh::Error naming the stage,
/// the option and the bad value.
class Options {
 public:
  Options() = default;
  Options(std::string stage, const std::vector<OptionSpec>& specs,
          const std::map<std::string, std::string>& given);

  std::string get_string(const std::string& key) const;
  double get_double(const std::string& key) const;
  /// An integer in [lo, hi].
  int get_int(const std::string& key, int lo, int hi) const;
  bool get_bool(const std::string& key) const;
  /// One of `choices` ("expected a or b" otherwise).
  std::string get_choice(const std::string& key, const std::vector<std::string>& choices) const;
  /// A comma-separated list (empty entries dropped).
  std::vector<std::string> get_list(const std::string& key) const;

 private:
  [[noreturn]] void bad(const std::string& key, const std::string& why) const;
  std::string stage_;
  std::map<std::string, std::string> values_;
};

/// A stage call parsed from "name:key=value:...": the stage name and the given pairs.
struct StageCall {
  std::string text;
  std::string name;
  std::map<std::string, std::string> given;
};

/// Parses one `-m` argument; throws homesh::Error on an empty name, an entry
/// without '=' or a repeated key.
StageCall parse_stage_call(const std::string& text);

}  // namespace homesh
