// libFuzzer target: the voronoi stage's seed and metric file readers
// (voronoi/voronoi_files.h) must turn any file into a value or a homesh::Error
// naming the file, never a crash, hang, leak or undefined behaviour. The first
// byte chooses the reader; the rest is the file's content.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"
#include "voronoi/voronoi_files.h"

namespace {

const std::string& scratch_path() {
  // In memory where the machine has /dev/shm: one file write per input.
  static const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  static const std::string path = dir + "/homesh-fuzz-voronoi-" + std::to_string(getpid()) + ".txt";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string& path = scratch_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    if (data[0] & 1)
      homesh::read_metric_file(path);
    else
      homesh::read_seed_file(path);
  } catch (const homesh::Error& e) {
    if (std::string(e.what()).rfind(path, 0) != 0) __builtin_trap();  // must name the file
  }
  return 0;
}
