#pragma once
// The CLI's work: load the input through Gmsh, run each stage in turn, write
// the output `.msh` or `.vtu` (with its fields and the command line that made it).
#include <string>
#include <vector>

#include "pipeline/context.h"
#include "pipeline/options.h"

namespace homesh {

/// Opens `path` (.geo, .step/.stp, .brep, .iges/.igs, .msh) into the current
/// Gmsh model and reads the mesh it carries, if any. Throws homesh::Error
/// naming `path` if it is missing, unreadable, empty, of an unknown kind, or
/// Gmsh fails on it.
void load_input(const std::string& path, Context& ctx);

/// Runs `calls` on `ctx` in order, once every call's options are read and
/// checked (homesh::Error naming the stage, option and value before any stage
/// runs otherwise). A CAD input without a mesh is first meshed
/// with the `mesh` stage's defaults unless some call creates a mesh itself.
/// Long stages show progress on a terminal (core/progress.h: on when stderr
/// is a terminal and ctx.log is not quiet, or as HOMESH_PROGRESS says), under
/// the label "stage k/n NAME".
void run_stages(const std::vector<StageCall>& calls, Context& ctx);

/// Certifies the validity of ctx's mesh, then writes it and ctx's fields (plus
/// a minJ/maxJ field if no stage made one) to `path`, in the format its
/// extension names (pipeline/output_format.h): a `.msh` through the current
/// model (MSH 4.1, one view per field, plus `path.opt`), a `.vtu` directly
/// (io/write_vtu.h); `provenance` is recorded in the file. Throws
/// homesh::Error and writes nothing if a triangle is not certified valid,
/// unless ctx.keep_invalid.
void write_output(const std::string& path, const std::string& provenance, Context& ctx);

}  // namespace homesh
