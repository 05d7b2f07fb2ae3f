// libFuzzer target: the `-m name:key=value:...` parser and every stage's
// option table must turn any input into options or a homesh::Error, never a
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
        s.parse(call.given);
      } catch (const homesh::Error&) {
      }
    }
  } catch (const homesh::Error&) {
  }
  return 0;
}
