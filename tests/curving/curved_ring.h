#pragma once
// A thin curved boundary layer for the optimiser's tests: a linear ring mesh
// between the circles of radius 1 (curve tag 1) and 1.5 (tag 2), raised to
// order p and its boundary nodes moved onto the circles by the plain elastic
// analogy (E = 1, nu = 0.4, one increment, the whole mesh) with the linear
// vertices held: valid, but the thin elements at the wall take most of the bulge.
#include <catch2/catch.hpp>
#include <limits>

#include "../layers/layer_test_meshes.h"
#include "core/raise_order.h"
#include "curving/deform_mesh.h"
#include "curving/optimise_mesh.h"

namespace homesh::test {

/// forget_parameters: the boundary nodes' curve parameters set to NaN (a
/// CurveEvaluator then finds them).
inline Mesh curved_ring(const Mesh& linear, int p, bool forget_parameters = false) {
  Mesh m = raise_order(linear, p);
  Eigen::Matrix2Xd target = m.x;
  for (int i = 0; i < m.num_nodes(); ++i)
    if (m.node_class[i].dim == 1) {
      target.col(i) *= (m.node_class[i].tag == 1 ? 1.0 : 1.5) / m.x.col(i).norm();
      if (forget_parameters) m.node_class[i].u = std::numeric_limits<double>::quiet_NaN();
    }
  std::vector<bool> held = boundary_nodes(m);
  const std::vector<bool> vertex = vertex_nodes(m);
  for (int i = 0; i < m.num_nodes(); ++i) held[i] = held[i] || vertex[i];
  DeformOptions d;
  d.formulation = "plain";
  d.params.poisson = 0.4;
  d.reach = 0;
  d.increments = 1;
  const DeformResult curved = deform_mesh(m, target, held, d);
  REQUIRE(curved.complete);
  return curved.mesh;
}

}  // namespace homesh::test
