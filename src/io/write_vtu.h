#pragma once
// `.vtu` output: the mesh and its fields as a VTK XML UnstructuredGrid, for
// ParaView and every VTK-based tool. Curved elements stay curved: triangles
// of order p >= 2 are VTK_LAGRANGE_TRIANGLE (69) cells, quadrilaterals
// VTK_LAGRANGE_QUADRILATERAL (70) cells, nodes in VTK's order
// (io/vtk_node_order.h), which ParaView draws curved with its "Nonlinear
// Subdivision Level" (2 or more). Boundary lines are VTK_POLY_LINE (4) cells
// through their nodes in order, since VTK 9.1 and ParaView 5.11 crash on
// nonlinear 1D cells at those levels. Order 1 writes VTK_TRIANGLE (5),
// VTK_QUAD (9) and VTK_LINE (3).
//
// Layout (VTK XML 1.0, appended nowhere: every array inline, base64 of
// little-endian bytes after a UInt64 byte count, so values round-trip exactly
// and NaN is representable):
// - Points: the mesh's nodes, in homesh's node order (z = 0).
// - Cells: the triangles (cell k = triangle k), the quadrilaterals, then the
//   boundary lines (cell k = 2D element k of core/mesh.h, then the lines).
//   Model points (Gmsh's point elements) are not written.
// - CellData:
//   - "gmsh:element": the cell's Gmsh element tag, as in the .msh of the same
//     mesh (reports name elements by it);
//   - "gmsh:geometrical": the tag of the surface or curve the cell lies on;
//   - "gmsh:physical": the tag of a physical group of the cell's dimension
//     holding that entity (the smallest, if several do), 0 if none (the
//     names meshio gives these fields, so a conversion keeps them);
//   - every Element field, named as its Gmsh view ("homesh: certified
//     minJ/maxJ", "homesh: Q4 Equal volume, element minimum", ...), NaN on
//     lines;
//   - every ElementNode field F under its name ("homesh: Q4 Equal volume, at
//     nodes"): one component per node of the element, in VTK's node order:
//     the exact, per-element values (on a mesh with quadrilaterals, (p+1)^2
//     components, a triangle's last ones NaN);
//   - a field of a few elements (Field::elements) is NaN on the others; a
//     field of no element is left out (Gmsh's views, too).
// - PointData: every ElementNode field F as point_field_name(F): at each
//   point, the smallest value over the elements sharing it (NaN at a point
//   of no element). Such fields (the quality measures at the nodes) are per
//   element and jump across element edges; VTK's point data is one value per
//   point, so the point field shows the worst element at each node, drawn
//   curved and continuous, while the cell field keeps every element's own.
#include <string>
#include <vector>

#include "core/field.h"
#include "core/mesh.h"
#include "core/volume_mesh.h"

namespace homesh {

/// The point-data name of ElementNode field `field`: "<field>, smallest at the point".
inline std::string point_field_name(const std::string& field) {
  return field + ", smallest at the point";
}

/// The Gmsh element tags of a mesh's 2D elements and lines, for
/// "gmsh:element" when the mesh was read from a model that numbers them its
/// own way. Empty: the tags homesh writes the mesh with (Mesh::triangle_tag).
struct ElementTags {
  std::vector<std::size_t> triangles;  ///< #2D elements (triangles, quadrilaterals), or empty
  std::vector<std::size_t> lines;      ///< #lines, or empty
};

/// The `.vtu` text of `mesh` and `fields` (each 1 or nodes-per-element by
/// #2D elements, see core/field.h), with `provenance` (e.g. the command line)
/// in an XML comment after the declaration. Throws homesh::Error if a field's
/// or the tags' size does not match the mesh.
std::string vtu_text(const Mesh& mesh, const std::vector<Field>& fields,
                     const std::string& provenance, const ElementTags& tags = {});

/// Writes vtu_text(mesh, fields, provenance, tags) to `path` atomically
/// (core/atomic_file.h), every step checked; throws homesh::Error naming
/// `path` and the cause, the previous file then untouched.
void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<Field>& fields,
               const std::string& provenance, const ElementTags& tags = {});

/// The `.vtu` text of a volume mesh (issue 24): as above, with the tetrahedra
/// first (VTK_TETRA (10), or VTK_LAGRANGE_TETRAHEDRON (71) of order p >= 2 in
/// VTK's node order, io/vtk_node_order.h), then the surface triangles and the
/// curve lines. Fields are over the tetrahedra (NaN on the triangles and lines);
/// "gmsh:element" holds the tags of VolumeMesh::tetrahedron_tag and those
/// write_volume_model gives the triangles and lines; "gmsh:physical" the groups
/// of each cell's dimension.
/// `tet_tags` (#tetrahedra, or empty) names the tetrahedra as a model that
/// numbers them its own way does.
std::string vtu_text(const VolumeMesh& mesh, const std::vector<Field>& fields,
                     const std::string& provenance, const std::vector<std::size_t>& tet_tags = {});

/// Writes vtu_text(mesh, fields, provenance, tet_tags) of a volume mesh to `path` atomically.
void write_vtu(const std::string& path, const VolumeMesh& mesh, const std::vector<Field>& fields,
               const std::string& provenance, const std::vector<std::size_t>& tet_tags = {});

}  // namespace homesh
