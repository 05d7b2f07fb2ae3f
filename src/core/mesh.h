#pragma once
// The core mesh: planar triangles and quadrilaterals of one order p, with the
// CAD/discrete entities and physical groups they are classified on. Pure data over Eigen; the Gmsh
// adapter (src/gmsh/) fills it from, and writes it back to, a Gmsh model.
//
// Node ordering follows Gmsh (see element/reference_nodes.h): a triangle of
// order p lists its 3 corners, the p-1 nodes of edges 0-1, 1-2, 2-0 (each from
// its first to its second corner), then its interior nodes recursively as a
// triangle of order p-3. A quadrilateral of order p (complete Lagrange, (p+1)^2
// nodes) lists its 4 corners counter-clockwise, the p-1 nodes of edges 0-1,
// 1-2, 2-3, 3-0 (each from its first to its second corner), then its interior
// nodes recursively as a quadrilateral of order p-2 (element/quad_reference_nodes.h).
// A line of order p lists its 2 end nodes, then its p-1 interior nodes from
// the first end to the second.
//
// The 2D elements are numbered triangles first, then quadrilaterals: element e
// of a per-element field (core/field.h) is triangle e for e < num_triangles(),
// else quadrilateral e - num_triangles().
#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

namespace homesh {

/// Where a node lives: on a model point (dim 0), curve (dim 1) or surface (dim 2).
/// `u` is the parametric coordinate on the curve for dim 1 nodes (NaN if unknown).
struct NodeClass {
  int dim = 2;
  int tag = -1;
  double u = std::numeric_limits<double>::quiet_NaN();
};

/// A model entity of dimension 0, 1 or 2 with the tags of its boundary entities
/// (signed for orientation, as Gmsh's getBoundary returns them).
struct Entity {
  int dim = 0;
  int tag = -1;
  std::vector<int> boundary;
};

/// A named physical group: dimension, tag, name and the entity tags it gathers.
struct PhysicalGroup {
  int dim = 0;
  int tag = -1;
  std::string name;
  std::vector<int> entities;
};

/// Triangles, quadrilaterals, boundary lines and model points of one order,
/// with classification.
struct Mesh {
  int order = 1;

  /// 2 by #nodes: node coordinates (the plane z = 0).
  Eigen::Matrix2Xd x;
  /// #nodes classification of each node.
  std::vector<NodeClass> node_class;

  /// (p+1)(p+2)/2 by #triangles: node indices of each triangle, Gmsh order.
  Eigen::MatrixXi tri;
  /// #triangles tag of the surface each triangle belongs to.
  std::vector<int> tri_entity;

  /// (p+1)^2 by #quads: node indices of each quadrilateral, Gmsh order.
  Eigen::MatrixXi quad;
  /// #quads tag of the surface each quadrilateral belongs to.
  std::vector<int> quad_entity;

  /// p+1 by #lines: node indices of each boundary/embedded line, Gmsh order.
  Eigen::MatrixXi line;
  /// #lines tag of the curve each line belongs to.
  std::vector<int> line_entity;

  /// Node index and entity tag of each point element (Gmsh type 15).
  std::vector<int> point_node;
  std::vector<int> point_entity;

  /// Model entities of dimension 0..2 and physical groups.
  std::vector<Entity> entities;
  std::vector<PhysicalGroup> physicals;

  int num_nodes() const { return static_cast<int>(x.cols()); }
  int num_triangles() const { return static_cast<int>(tri.cols()); }
  int num_lines() const { return static_cast<int>(line.cols()); }
  int num_quads() const { return static_cast<int>(quad.cols()); }
  /// Triangles and quadrilaterals.
  int num_elements_2d() const { return num_triangles() + num_quads(); }

  /// 2 by (p+1)(p+2)/2 coordinates of the nodes of triangle e, Gmsh order.
  Eigen::Matrix2Xd triangle_nodes(int e) const;
  /// 2 by (p+1)^2 coordinates of the nodes of quadrilateral e, Gmsh order.
  Eigen::Matrix2Xd quad_nodes(int e) const;
  /// Centroid of the corners of 2D element e (where reports place it):
  /// triangle e, or quadrilateral e - num_triangles() beyond the triangles.
  Eigen::Vector2d corner_centroid(int e) const;
  /// The Gmsh element tag of 2D element e (triangle e, or quadrilateral
  /// e - num_triangles()) once homesh writes the mesh into a model or a file
  /// (gmsh/write_model.h): tags 1.. go to the point elements, then the lines,
  /// then the 2D elements surface by surface in increasing entity tag, each
  /// surface's triangles before its quadrilaterals. That is the order Gmsh
  /// writes them in a .msh, and a view's element data is written in tag
  /// order: meshio, which pairs them by position, needs the two to agree. On a
  /// mesh without quadrilaterals triangle e has tag 1 + #points + #lines + e;
  /// with some, the 2D elements must be grouped by entity (core/group_by_entity.h),
  /// as they are once read and after every stage. Reports name elements by
  /// it, so a user finds them in the GUI and through the API.
  std::size_t triangle_tag(int e) const;
  /// The Gmsh element tag of quadrilateral q: triangle_tag(num_triangles() + q).
  std::size_t quad_tag(int q) const { return triangle_tag(num_triangles() + q); }
};

/// The node indices of 2D element e of m (triangle e, or quadrilateral
/// e - #triangles), Gmsh order: its 3 or 4 corners first.
inline Eigen::MatrixXi::ConstColXpr element_node_indices(const Mesh& m, int e) {
  return e < m.num_triangles() ? m.tri.col(e) : m.quad.col(e - m.num_triangles());
}

/// Highest element order homesh supports (the basis stays accurate to ~1e-10).
constexpr int kMaxOrder = 10;

/// Number of nodes of a triangle of order p: (p+1)(p+2)/2.
constexpr int triangle_node_count(int p) { return (p + 1) * (p + 2) / 2; }

/// Number of nodes of a tetrahedron of order p: (p+1)(p+2)(p+3)/6.
constexpr int tetrahedron_node_count(int p) { return (p + 1) * (p + 2) * (p + 3) / 6; }

/// Number of nodes of a complete quadrilateral of order p: (p+1)^2.
constexpr int quad_node_count(int p) { return (p + 1) * (p + 1); }

/// Gmsh's name of the complete quadrilateral of order p ("Quadrilateral 9"
/// for p = 2), for messages.
inline std::string quad_type_name(int p) {
  return "Quadrilateral " + std::to_string(quad_node_count(p));
}

}  // namespace homesh
