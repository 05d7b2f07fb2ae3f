#include "gmsh/views.h"

#include <gmsh.h>

#include "gmsh/model_nodes.h"
#include "gmsh/view_style.h"

namespace homesh::gmsh_adapter {
namespace {

// Gmsh's properties of the element tagged `tag`.
ElementType type_of(std::size_t tag) {
  int type = 0;
  std::vector<std::size_t> nodes;
  gmsh::model::mesh::getElement(tag, type, nodes);
  return element_type(type);
}

}  // namespace

std::vector<int> add_views(const std::vector<Field>& fields, const ModelTags& tags) {
  std::string model;
  gmsh::model::getCurrent(model);
  std::vector<int> view_tags;
  bool shown = false;
  for (const Field& f : fields) {
    if (f.values.cols() == 0) continue;  // Gmsh refuses a view without data
    const int view = gmsh::view::add(f.name);
    const auto triangles = static_cast<std::size_t>(f.values.cols());
    const bool element = f.kind == Field::Kind::Element;
    // Element data covers the points and lines (tags 1 .. first_triangle - 1) too.
    const std::size_t first = element ? 1 : tags.first_triangle;
    const std::size_t others = tags.first_triangle - first;
    std::vector<std::size_t> element_tags(others + triangles);
    std::vector<std::vector<double>> data(element_tags.size());
    for (std::size_t k = 0; k < others; ++k) {
      element_tags[k] = first + k;
      data[k] = {f.quality ? 1.0 : 0.0};
    }
    // The nodes of each kind of element (triangles or tetrahedra, quadrilaterals).
    const std::size_t n = tags.element.size(),
                      first_quad = static_cast<std::size_t>(tags.triangles);
    const ElementType kind = n > 0 ? type_of(tags.element.front()) : ElementType{"", 2, 1, 3};
    const int quad_nodes = first_quad < n ? type_of(tags.element[first_quad]).nodes : 0;
    for (std::size_t e = 0; e < triangles; ++e) {
      const std::size_t index = f.elements.empty() ? e : static_cast<std::size_t>(f.elements[e]);
      element_tags[others + e] = tags.element.at(index);
      // An element's node values are the top rows of its column (core/field.h).
      const auto col = f.values.col(static_cast<Eigen::Index>(e));
      const bool quad = index >= first_quad;
      const Eigen::Index size = element ? 1 : quad ? quad_nodes : kind.nodes;
      data[others + e].assign(col.data(), col.data() + size);
    }
    gmsh::view::addModelData(view, 0, model, element ? "ElementData" : "ElementNodeData",
                             element_tags, data);
    // Views over tetrahedra are drawn without Gmsh's adaptive grid: it refines
    // every element as the view is made (a certified minJ/maxJ view of 167148
    // tetrahedra of order 2 took 8.8 s and 2.3 GB, its adaptive data all of it).
    style_view(view, f, kind.dim == 3 ? 1 : kind.order);
    shown = shown || f.shown;
    view_tags.push_back(view);
  }
  if (shown) hide_other_views(view_tags);
  return view_tags;
}

}  // namespace homesh::gmsh_adapter
