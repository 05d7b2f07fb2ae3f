#include "gmsh/views.h"

#include <gmsh.h>

namespace homesh::gmsh_adapter {

std::vector<int> add_views(const std::vector<Field>& fields, const ModelTags& tags) {
  std::string model;
  gmsh::model::getCurrent(model);
  std::vector<int> view_tags;
  for (const Field& f : fields) {
    const int view = gmsh::view::add(f.name);
    std::vector<std::size_t> element_tags(static_cast<std::size_t>(f.values.cols()));
    std::vector<std::vector<double>> data(element_tags.size());
    for (std::size_t e = 0; e < element_tags.size(); ++e) {
      element_tags[e] = tags.first_triangle + e;
      const auto col = f.values.col(static_cast<Eigen::Index>(e));
      data[e].assign(col.data(), col.data() + col.size());
    }
    gmsh::view::addModelData(view, 0, model,
                             f.kind == Field::Kind::Element ? "ElementData" : "ElementNodeData",
                             element_tags, data);
    view_tags.push_back(view);
  }
  return view_tags;
}

}  // namespace homesh::gmsh_adapter
