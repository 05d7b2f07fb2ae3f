#pragma once
// The small volume mesh the core volume tests share.
#include "core/volume_mesh.h"

namespace homesh::test {

// Two linear tetrahedra sharing the face 1-2-3, the second with its corners in
// another rotation of that face, the face 0-1-2 of the first a surface triangle
// (tag 5, corners with surface parameters u = x, v = y) with the line 0-1 on
// curve 4 (corner 0 at u = 0, corner 1 at u = 2, both on that curve):
// V = 5, E = 9, F = 7, T = 2.
inline VolumeMesh two_tetrahedra() {
  VolumeMesh m;
  m.x.resize(3, 5);
  m.x << 0.0, 2.0, 0.3, 0.2, 1.4,  //
      0.0, 0.1, 1.7, 0.4, 1.2,     //
      0.0, 0.0, 0.1, 1.6, 1.5;
  m.node_class = {{1, 4, 0.0}, {1, 4, 2.0}, {2, 5, 0.3, 1.7}, {3, 1}, {3, 1}};
  m.tet.resize(4, 2);
  m.tet << 0, 2,  //
      1, 3,       //
      2, 1,       //
      3, 4;
  m.tet_entity = {1, 1};
  m.tri.resize(3, 1);
  m.tri << 0, 1, 2;
  m.tri_entity = {5};
  m.line.resize(2, 1);
  m.line << 0, 1;
  m.line_entity = {4};
  m.entities = {{1, 4, {}}, {2, 5, {4}}, {3, 1, {5}}};
  m.physicals = {{3, 9, "solid", {1}}};
  return m;
}

}  // namespace homesh::test
