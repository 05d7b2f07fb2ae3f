#include "voronoi/cleanup/valence_flips.h"

#include <algorithm>

#include "core/error.h"
#include "layers/edge_flip_sweep.h"
#include "layers/plane_geometry.h"

namespace homesh {

int flip_to_regular_valence(Mesh& m, const std::vector<char>& interior,
                            const TriangleQuality& quality, double floor, int max_sweeps) {
  if (m.order != 1) throw Error("flip_to_regular_valence: the mesh must be linear");
  if (interior.size() != static_cast<std::size_t>(m.num_nodes()))
    throw Error("flip_to_regular_valence: one interior flag per node is needed");
  std::vector<int> valence(m.num_nodes(), 0);
  for (Eigen::Index t = 0; t < m.tri.cols(); ++t)
    for (int k = 0; k < 3; ++k) ++valence[m.tri(k, t)];
  const auto energy = [&](int v, int change) {
    if (!interior[v]) return 0;
    const int d = valence[v] + change - 6;
    return d * d;
  };
  const auto q = [&](int a, int b, int c) {
    Eigen::Matrix<double, 2, 3> X;
    X << m.x.col(a), m.x.col(b), m.x.col(c);
    return layers_detail::orient(X.col(0), X.col(1), X.col(2)) > 0 ? quality(X) : -1.0;
  };
  // Triangles (a, b, c) and (b, a, d); the other diagonal gives (c, d, b) and (d, c, a).
  const auto regular = [&](int a, int b, int c, int d) {
    const int before = energy(a, 0) + energy(b, 0) + energy(c, 0) + energy(d, 0);
    const int after = energy(a, -1) + energy(b, -1) + energy(c, 1) + energy(d, 1);
    if (after >= before) return false;
    const double now = std::min(q(a, b, c), q(b, a, d));
    if (std::min(q(c, d, b), q(d, c, a)) < std::min(floor, now)) return false;
    --valence[a], --valence[b], ++valence[c], ++valence[d];
    return true;
  };
  return flip_edges_where(m, all_triangles(m), regular, max_sweeps);
}

}  // namespace homesh
