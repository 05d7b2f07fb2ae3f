#include "pipeline/group_context_by_entity.h"

#include "core/group_by_entity.h"

namespace homesh {

void group_context_by_entity(Context& ctx) {
  if (!ctx.mesh) return;
  const std::vector<int> perm = group_by_entity(*ctx.mesh);
  if (perm.empty()) return;
  std::vector<int> position(perm.size());  // old -> new
  for (std::size_t k = 0; k < perm.size(); ++k) position[perm[k]] = static_cast<int>(k);
  for (Field& f : ctx.fields) {
    if (!f.elements.empty()) {
      for (int& e : f.elements) e = position[e];
      continue;
    }
    Eigen::MatrixXd values(f.values.rows(), f.values.cols());
    for (std::size_t k = 0; k < perm.size(); ++k)
      values.col(static_cast<Eigen::Index>(k)) = f.values.col(perm[k]);
    f.values = std::move(values);
  }
}

}  // namespace homesh
