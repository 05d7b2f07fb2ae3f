#pragma once
// Calls into Gmsh with its failures turned into homesh::Error. Gmsh 4.8's C++ API
// throws std::string (or std::exception) on some errors and only logs others, so
// each guarded call also reads Gmsh's logger for an error raised during the call.
#include <functional>
#include <string>

namespace homesh::gmsh_adapter {

/// Runs `body`; if Gmsh throws or logs an error meanwhile, throws homesh::Error
/// "<what>: <Gmsh's message>".
void gmsh_call(const std::string& what, const std::function<void()>& body);

}  // namespace homesh::gmsh_adapter
