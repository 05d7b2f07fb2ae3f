// libFuzzer target: the `-m name:key=value:...` parser and every stage's typed
// option getters must turn any input into a value or a homesh::Error, never a
// crash, hang, leak or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/error.h"
#include "pipeline/options.h"
#include "pipeline/stage_registry.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const homesh::StageCall call = homesh::parse_stage_call(text);
    for (const homesh::Stage& s : homesh::stages()) {
      try {
        const homesh::Options o(s.name, s.options, call.given);
        for (const auto& spec : s.options) {
          for (auto get : {+[](const homesh::Options& x, const std::string& k) { x.get_double(k); },
                           +[](const homesh::Options& x, const std::string& k) { x.get_int(k, -5, 5); },
                           +[](const homesh::Options& x, const std::string& k) { x.get_bool(k); },
                           +[](const homesh::Options& x, const std::string& k) { x.get_list(k); }}) {
            try {
              get(o, spec.name);
            } catch (const homesh::Error&) {
            }
          }
        }
      } catch (const homesh::Error&) {
      }
    }
  } catch (const homesh::Error&) {
  }
  return 0;
}
