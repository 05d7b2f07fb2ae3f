#include "pipeline/options.h"

#include <sstream>

#include "core/error.h"

namespace homesh {

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
