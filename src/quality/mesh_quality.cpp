#include "quality/mesh_quality.h"

#include "element/reference_nodes.h"

namespace homesh {

MeshMeasure mesh_measure(const Mesh& m, const Measure& q, int lattice, Reference ref) {
  const int p = m.order, nodes = triangle_node_count(p), n = m.num_triangles();
  const Eigen::Matrix2Xd lattice_points = reference_nodes(lattice);
  Eigen::Matrix2Xd uv(2, nodes + lattice_points.cols());
  uv << reference_nodes(p), lattice_points;
  const ElementSampling sampling(p, uv);

  MeshMeasure out;
  out.element_min.resize(n);
  out.node_values.resize(nodes, n);
  for (int e = 0; e < n; ++e) {
    const ElementQuality eq = element_quality(q, sampling, m.triangle_nodes(e), ref);
    out.element_min(e) = eq.min;
    out.node_values.col(e) = eq.values.head(nodes);
  }
  return out;
}

}  // namespace homesh
