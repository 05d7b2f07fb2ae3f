#include "quality/mesh_validity.h"

#include <vector>

namespace homesh {

MeshValidity mesh_validity(const Mesh& m, const BoundsOptions& opt) {
  const int n = m.num_triangles();
  MeshValidity v;
  v.ratio.resize(n);
  v.min_det.resize(n);
  v.relative_tolerance = opt.relative_tolerance;
  std::vector<char> valid(static_cast<std::size_t>(n)), converged(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(dynamic, 256)
  for (int e = 0; e < n; ++e) {
    const JacobianBounds b = jacobian_bounds(m.triangle_nodes(e), m.order, opt);
    v.ratio(e) = scaled_jacobian_ratio(b);
    v.min_det(e) = b.min_lower;
    valid[e] = b.valid_certified;
    converged[e] = b.converged;
  }
  for (int e = 0; e < n; ++e) {
    v.invalid += valid[e] ? 0 : 1;
    v.unconverged += converged[e] ? 0 : 1;
    if (v.worst_element < 0 || v.ratio(e) < v.worst) {
      v.worst = v.ratio(e);
      v.worst_element = e;
    }
  }
  return v;
}

}  // namespace homesh
