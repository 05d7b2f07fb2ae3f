#pragma once
// A scalar field over the 2D elements (triangles, quadrilaterals) of a mesh, written to `.msh` as a
// Gmsh view named `name` (gmsh/views.h): one value per element (ElementData, which meshio reads as
// cell data) or one value per node of each element in the element's own node order
// (ElementNodeData). Gmsh draws both curved (gmsh/view_style.h).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace homesh {

struct Field {
  enum class Kind { Element, ElementNode };

  std::string name;
  Kind kind = Kind::Element;
  /// Element: 1 by #2D elements (triangles, then quadrilaterals: the numbering
  /// of core/mesh.h). ElementNode: nodes-per-element by #2D elements, or by
  /// #elements if `elements` lists some; on a mesh with quadrilaterals the rows
  /// are (p+1)^2 and a triangle's (p+1)(p+2)/2 node values are the top rows of
  /// its column (the rows below are not written).
  Eigen::MatrixXd values;
  /// A quality in [0, 1], 1 ideal, <= 0 invalid: drawn on the fixed range
  /// [0, 1]; points and lines of the file get 1 in its element data. Otherwise
  /// drawn on the values' own range, points and lines get 0.
  bool quality = true;
  /// Shown when the file is opened (one field, so one colour scale, shows).
  bool shown = false;
  /// ElementNode only: the 2D elements it covers, one column of values each
  /// (empty: every triangle). A view of a few elements, to find them in Gmsh.
  std::vector<int> elements = {};
};

}  // namespace homesh
