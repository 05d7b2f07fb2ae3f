#pragma once
// What a `.msh` file says of itself before its data: its version, encoding and
// the numbers of nodes and elements its $Nodes and $Elements sections declare
// (MSH 2.2 and 4.x, ASCII and binary). Gmsh's reader drops some elements
// without a word (e.g. a linear and a quadratic triangle in one entity keep
// only one kind); comparing what the file declares with what Gmsh has read
// catches every such loss.
#include <cstdint>
#include <optional>
#include <string>

namespace homesh::gmsh_adapter {

struct MshHeader {
  double version = 0;  ///< 2.2, 4.1, ...
  bool binary = false;
  std::optional<std::uint64_t> nodes;     ///< declared in $Nodes, if the section is there
  std::optional<std::uint64_t> elements;  ///< declared in $Elements, if the section is there
};

/// Reads the header numbers of `path`. Throws homesh::Error naming `path` if
/// it does not start with a $MeshFormat section, or a count is malformed.
MshHeader read_msh_header(const std::string& path);

/// Throws homesh::Error naming `path` and the line if an element of its
/// ASCII $Elements section names a node tag that is not positive. Gmsh 4.8's
/// MSH 4.1 reader indexes its node table with such a tag unchecked: it crashes
/// or, depending on memory layout, silently takes another node. (Binary files
/// pass unchecked: they go through the child read alone.)
void check_element_node_tags(const std::string& path);

}  // namespace homesh::gmsh_adapter
