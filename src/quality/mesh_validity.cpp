#include "quality/mesh_validity.h"

#include "quality/mesh_quality.h"

namespace homesh {
namespace {

bool equal(const Eigen::MatrixXi& a, const Eigen::MatrixXi& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() && a == b;
}

}  // namespace

bool certified_better(int invalid, double worst, int than_invalid, double than_worst) {
  return invalid < than_invalid || (invalid == than_invalid && worst > than_worst);
}

void count_validity(MeshValidity& v) {
  v.invalid = v.unconverged = 0;
  v.worst = 1.0;
  v.worst_element = -1;
  for (Eigen::Index e = 0; e < v.ratio.size(); ++e) {
    v.invalid += v.min_det(e) > 0 ? 0 : 1;
    v.unconverged += v.converged[static_cast<std::size_t>(e)] ? 0 : 1;
    if (v.worst_element < 0 || v.ratio(e) < v.worst) {
      v.worst = v.ratio(e);
      v.worst_element = static_cast<int>(e);
    }
  }
}

MeshValidity mesh_validity(const Mesh& m, const BoundsOptions& opt) {
  return mesh_quality(m, {}, 0, Reference::ideal, opt).validity;
}

MeshValidity mesh_validity(const Mesh& m, const Mesh& before, const MeshValidity& known,
                           const BoundsOptions& opt) {
  const auto n = static_cast<Eigen::Index>(m.num_elements_2d());
  const bool same = m.order == before.order && m.x.cols() == before.x.cols() &&
                    equal(m.tri, before.tri) && equal(m.quad, before.quad) &&
                    known.ratio.size() == n && known.min_det.size() == n &&
                    known.converged.size() == std::size_t(n) &&
                    known.relative_tolerance == opt.relative_tolerance &&
                    known.max_subdivisions == opt.max_subdivisions;
  if (!same) return mesh_validity(m, opt);
  std::vector<char> moved(static_cast<std::size_t>(m.num_nodes()));
  for (int i = 0; i < m.num_nodes(); ++i) moved[i] = (m.x.col(i) != before.x.col(i)) ? 1 : 0;
  return moved_elements_validity(m, moved, known, opt);
}

MeshValidity mesh_validity(const Mesh& m, const KnownValidity& known, const BoundsOptions& opt) {
  return known.mesh && known.validity ? mesh_validity(m, *known.mesh, *known.validity, opt)
                                      : mesh_validity(m, opt);
}

}  // namespace homesh
