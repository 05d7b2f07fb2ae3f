#pragma once
// A scalar field over the triangles of a mesh, written to `.msh` as a Gmsh view:
// one value per element (ElementData) or one value per node of each element in
// the element's own node order (ElementNodeData, drawn curved by Gmsh with
// AdaptVisualizationGrid).
#include <Eigen/Core>
#include <string>

namespace homesh {

struct Field {
  enum class Kind { Element, ElementNode };

  std::string name;
  Kind kind = Kind::Element;
  /// Element: 1 by #triangles. ElementNode: nodes-per-triangle by #triangles.
  Eigen::MatrixXd values;
};

}  // namespace homesh
