#include "element/quad_reference_nodes.h"

#include <string>

#include "core/error.h"
#include "core/mesh.h"

namespace homesh {
namespace {

// Fills columns [first, first + (p+1)^2) of `ij` with the integer node
// coordinates of a quadrilateral of order p >= 0, shifted by (shift, shift).
void fill_quad_indices(int p, int shift, int first, Eigen::Matrix2Xi& ij) {
  int k = first;
  auto put = [&](int i, int j) { ij.col(k++) << i + shift, j + shift; };
  put(0, 0);
  if (p == 0) return;
  put(p, 0);
  put(p, p);
  put(0, p);
  for (int i = 1; i < p; ++i) put(i, 0);      // edge 0-1
  for (int i = 1; i < p; ++i) put(p, i);      // edge 1-2
  for (int i = 1; i < p; ++i) put(p - i, p);  // edge 2-3
  for (int i = 1; i < p; ++i) put(0, p - i);  // edge 3-0
  if (p >= 2) fill_quad_indices(p - 2, shift + 1, k, ij);
}

}  // namespace

Eigen::Matrix2Xi quad_reference_node_indices(int p) {
  if (p < 1)
    throw Error("quad_reference_node_indices: order " + std::to_string(p) + " must be >= 1");
  Eigen::Matrix2Xi ij(2, quad_node_count(p));
  fill_quad_indices(p, 0, 0, ij);
  return ij;
}

Eigen::Matrix2Xd quad_reference_nodes(int p) {
  return quad_reference_node_indices(p).cast<double>() * (1.0 / p);
}

}  // namespace homesh
