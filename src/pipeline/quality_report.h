#pragma once
// Text reports of mesh validity and quality, for a user to act on.
#include <Eigen/Core>
#include <string>

#include "core/mesh.h"
#include "core/volume_mesh.h"
#include "quality/mesh_validity.h"

namespace homesh {

/// One line: invalid count (certified) and the worst minJ/maxJ with its
/// triangle (its Gmsh element tag, Mesh::triangle_tag) and centroid.
/// `worst_tag` (0: Mesh::triangle_tag of the worst) names it otherwise.
std::string validity_line(const Mesh& m, const MeshValidity& v, std::size_t worst_tag = 0);

/// validity_line of a volume mesh: its tetrahedra, the worst named by
/// VolumeMesh::tetrahedron_tag (or `worst_tag`) and its corners' centroid.
std::string validity_line(const VolumeMesh& m, const MeshValidity& v, std::size_t worst_tag = 0);

/// "name  min .. mean .. | counts of 10 bins over [0, 1] |" for per-element values.
std::string histogram_line(const std::string& name, const Eigen::VectorXd& values);

/// The `count` elements with the smallest values: Gmsh element tag
/// (Mesh::triangle_tag), centroid and value, one per line.
std::string worst_elements(const Mesh& m, const Eigen::VectorXd& values, int count);

/// worst_elements of a volume mesh's tetrahedra (VolumeMesh::tetrahedron_tag).
std::string worst_elements(const VolumeMesh& m, const Eigen::VectorXd& values, int count);

}  // namespace homesh
