#pragma once
// meshio 7 reads a MSH 4.1 file only if every entity holding elements has a
// physical group, or none has (it lists the physical tags per block of
// elements and skips the blocks of entities without one). homesh keeps every
// element in its files (Mesh.SaveAll), a model's points usually in no group:
// while a file is written, such entities get a group of their own, one per
// dimension, named kUngroupedName, which read_model skips.
#include <utility>
#include <vector>

namespace homesh::gmsh_adapter {

constexpr const char* kUngroupedName = "homesh: no group";

class UngroupedGroups {
 public:
  /// If the current model has a physical group, adds one named kUngroupedName
  /// in each dimension 0-2 holding the entities with elements and no group.
  UngroupedGroups();
  /// Removes the groups added.
  ~UngroupedGroups();
  UngroupedGroups(const UngroupedGroups&) = delete;
  UngroupedGroups& operator=(const UngroupedGroups&) = delete;

 private:
  std::vector<std::pair<int, int>> added_;  ///< (dim, tag) of each group added
};

}  // namespace homesh::gmsh_adapter
