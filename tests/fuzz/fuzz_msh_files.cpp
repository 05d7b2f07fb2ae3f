// libFuzzer target: whole `.msh` files (MSH 2.2 and 4.1, ASCII and binary)
// through the CLI's input path (pipeline/run_pipeline.h: load_input), which
// reads them in a child process first (gmsh/read_in_child.h), checks what
// Gmsh read against what the file declares, and reads and checks the mesh.
// Any file must give a mesh or a homesh::Error naming the file: never a
// crash, hang, leak or undefined behaviour in homesh.
#include <gmsh.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"
#include "pipeline/run_pipeline.h"

namespace {

const std::string& scratch_path() {
  static const std::string dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
  static const std::string path = dir + "/homesh-fuzz-msh-" + std::to_string(getpid()) + ".msh";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::option::setNumber("General.AbortOnError", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratch_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    homesh::Context ctx;
    ctx.log.quiet = true;
    homesh::load_input(path, ctx);
  } catch (const homesh::Error& e) {
    if (std::string(e.what()).find(path) == std::string::npos)
      __builtin_trap();  // must name the file
  }
  return 0;
}
