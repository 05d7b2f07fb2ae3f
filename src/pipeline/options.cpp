#include "pipeline/options.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace homesh {

Options::Options(std::string stage, const std::vector<OptionSpec>& specs,
                 const std::map<std::string, std::string>& given)
    : stage_(std::move(stage)) {
  for (const auto& s : specs) values_[s.name] = s.default_value;
  for (const auto& [key, value] : given) {
    if (!values_.count(key)) {
      std::string known;
      for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.name;
      throw Error("stage '" + stage_ + "': unknown option '" + key + "' (options: " +
                  (known.empty() ? "none" : known) + ")");
    }
    values_[key] = value;
  }
}

void Options::bad(const std::string& key, const std::string& why) const {
  throw Error("stage '" + stage_ + "': option " + key + "=" + values_.at(key) + ": " + why);
}

std::string Options::get_string(const std::string& key) const { return values_.at(key); }

double Options::get_double(const std::string& key) const {
  const std::string& s = values_.at(key);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || errno == ERANGE) bad(key, "not a number");
  if (!std::isfinite(v)) bad(key, "not a finite number");
  return v;
}

int Options::get_int(const std::string& key, int lo, int hi) const {
  const std::string& s = values_.at(key);
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s.c_str(), &end, 10);
  if (s.empty() || *end != '\0' || errno == ERANGE) bad(key, "not an integer");
  if (v < lo || v > hi)
    bad(key, "out of range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v);
}

bool Options::get_bool(const std::string& key) const {
  const std::string& s = values_.at(key);
  if (s == "1" || s == "true" || s == "yes" || s == "on") return true;
  if (s == "0" || s == "false" || s == "no" || s == "off") return false;
  bad(key, "not a boolean (true/false)");
}

std::string Options::get_choice(const std::string& key,
                                const std::vector<std::string>& choices) const {
  const std::string& s = values_.at(key);
  if (std::find(choices.begin(), choices.end(), s) != choices.end()) return s;
  std::string expected;
  for (std::size_t k = 0; k < choices.size(); ++k)
    expected += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k];
  bad(key, "expected " + expected);
}

std::vector<std::string> Options::get_list(const std::string& key) const {
  std::vector<std::string> out;
  std::stringstream ss(values_.at(key));
  for (std::string item; std::getline(ss, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

StageCall parse_stage_call(const std::string& text) {
  StageCall call{text, {}, {}};
  std::stringstream ss(text);
  std::getline(ss, call.name, ':');
  if (call.name.empty()) throw Error("stage '" + text + "': empty stage name");
  for (std::string item; std::getline(ss, item, ':');) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error("stage '" + text + "': expected key=value, got '" + item + "'");
    const std::string key = item.substr(0, eq);
    if (!call.given.emplace(key, item.substr(eq + 1)).second)
      throw Error("stage '" + text + "': option '" + key + "' given twice");
  }
  return call;
}

}  // namespace homesh
