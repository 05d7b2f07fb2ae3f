#pragma once
// The core volume mesh (issue 24): tetrahedra of one order p with the triangles
// of their surfaces, the lines of their curves and the model points, classified
// on the CAD/discrete entities of dimension 0..3, with physical groups. Pure data
// over Eigen; the Gmsh adapter (gmsh/read_volume_model.h, gmsh/write_volume_model.h)
// fills it from, and writes it back to, a Gmsh model. The planar meshes of
// core/mesh.h stay a type of their own: every 2D stage relies on x being 2 by n.
//
// Node ordering follows Gmsh: a tetrahedron of order p as element/tet_reference_nodes.h,
// a triangle as element/reference_nodes.h (its corners, edges 0-1, 1-2, 2-0, its
// interior), a line as core/mesh.h.
#include <Eigen/Core>
#include <limits>
#include <vector>

#include "core/mesh.h"

namespace homesh {

/// Where a node of a volume mesh lives: on a model point, curve, surface or
/// volume (dim 0..3). `u` is its parameter on a curve (dim 1) or, with `v`, on
/// a surface (dim 2); NaN where unknown.
struct VolumeNodeClass {
  int dim = 3;
  int tag = -1;
  double u = std::numeric_limits<double>::quiet_NaN();
  double v = std::numeric_limits<double>::quiet_NaN();
};

struct VolumeMesh {
  int order = 1;

  /// 3 by #nodes: node coordinates.
  Eigen::Matrix3Xd x;
  /// #nodes classification of each node.
  std::vector<VolumeNodeClass> node_class;

  /// (p+1)(p+2)(p+3)/6 by #tetrahedra: node indices of each tetrahedron, Gmsh order.
  Eigen::MatrixXi tet;
  /// #tetrahedra tag of the volume each tetrahedron belongs to.
  std::vector<int> tet_entity;

  /// (p+1)(p+2)/2 by #triangles: the triangles of the model's surfaces.
  Eigen::MatrixXi tri;
  /// #triangles tag of the surface each triangle belongs to.
  std::vector<int> tri_entity;

  /// p+1 by #lines: the lines of the model's curves.
  Eigen::MatrixXi line;
  std::vector<int> line_entity;

  /// Node index and entity tag of each point element (Gmsh type 15).
  std::vector<int> point_node;
  std::vector<int> point_entity;

  /// Model entities of dimension 0..3 and physical groups.
  std::vector<Entity> entities;
  std::vector<PhysicalGroup> physicals;

  int num_nodes() const { return static_cast<int>(x.cols()); }
  int num_tetrahedra() const { return static_cast<int>(tet.cols()); }
  int num_triangles() const { return static_cast<int>(tri.cols()); }
  int num_lines() const { return static_cast<int>(line.cols()); }

  /// 3 by (p+1)(p+2)(p+3)/6 coordinates of the nodes of tetrahedron e, Gmsh order.
  Eigen::Matrix3Xd tetrahedron_nodes(int e) const;
  /// Centroid of the corners of tetrahedron e (where reports place it).
  Eigen::Vector3d corner_centroid(int e) const;
  /// The Gmsh element tag of tetrahedron e once homesh writes the mesh
  /// (gmsh/write_volume_model.h): tags 1.. go to the point elements, then the
  /// lines, the triangles, then the tetrahedra, each kind entity by entity in
  /// increasing entity tag (the order of a .msh, which meshio relies on). The
  /// tetrahedra must be grouped by entity (group_by_entity), as they are once read.
  std::size_t tetrahedron_tag(int e) const {
    return 1 + point_node.size() + static_cast<std::size_t>(num_lines()) +
           static_cast<std::size_t>(num_triangles()) + static_cast<std::size_t>(e);
  }
};

/// Highest tetrahedron order homesh handles: the highest whose det J it bounds
/// (quality/tet_bezier_jacobian.h, degree 3(p-1) <= 12), so whose validity it certifies.
constexpr int kMaxTetrahedronOrder = 5;

/// Gmsh's name of the tetrahedron of order p ("Tetrahedron 10" for p = 2), for messages.
inline std::string tetrahedron_type_name(int p) {
  return "Tetrahedron " + std::to_string(tetrahedron_node_count(p));
}

/// Orders the tetrahedra, triangles and lines of m by entity tag (stably), so
/// that each kind is written entity by entity in the order of tetrahedron_tag.
/// Returns the tetrahedra's permutation (new tetrahedron k was perm[k]), or an
/// empty vector if they were grouped already.
std::vector<int> group_by_entity(VolumeMesh& m);

}  // namespace homesh
