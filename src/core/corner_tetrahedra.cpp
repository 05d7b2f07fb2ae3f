#include "core/corner_tetrahedra.h"

namespace homesh {

CornerTetrahedra::CornerTetrahedra(const VolumeMesh& m) {
  const int n = m.num_tetrahedra();
  start.assign(static_cast<std::size_t>(m.num_nodes()) + 1, 0);
  list.resize(4 * static_cast<std::size_t>(n));
  for (int e = 0; e < n; ++e)
    for (int i = 0; i < 4; ++i) ++start[m.tet(i, e) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int e = 0; e < n; ++e)
    for (int i = 0; i < 4; ++i) list[fill[m.tet(i, e)]++] = e;
}

void grow_by_corners(const VolumeMesh& m, const CornerTetrahedra& at, int rings,
                     std::vector<char>& in) {
  for (int ring = 0; ring < rings; ++ring) {
    std::vector<char> touched(static_cast<std::size_t>(m.num_nodes()), 0);
    for (int e = 0; e < m.num_tetrahedra(); ++e)
      if (in[e])
        for (int i = 0; i < 4; ++i) touched[m.tet(i, e)] = 1;
    for (int v = 0; v < m.num_nodes(); ++v)
      if (touched[v])
        for (int k = at.start[v]; k < at.start[v + 1]; ++k) in[at.list[k]] = 1;
  }
}

}  // namespace homesh
