#include "element/reference_nodes.h"

#include <string>

#include "core/error.h"
#include "core/mesh.h"

namespace homesh {
namespace {

void check_reference_order(int p, const char* what) {
  if (p < 1) throw Error(std::string(what) + ": order " + std::to_string(p) + " must be >= 1");
}

// Fills columns [first, first + (p+1)(p+2)/2) of `ij` with the integer node
// coordinates of a triangle of order p >= 0, shifted by (shift, shift).
void fill_triangle_indices(int p, int shift, int first, Eigen::Matrix2Xi& ij) {
  int k = first;
  auto put = [&](int i, int j) { ij.col(k++) << i + shift, j + shift; };
  put(0, 0);
  if (p == 0) return;
  put(p, 0);
  put(0, p);
  for (int i = 1; i < p; ++i) put(i, 0);      // edge 0-1
  for (int i = 1; i < p; ++i) put(p - i, i);  // edge 1-2
  for (int i = 1; i < p; ++i) put(0, p - i);  // edge 2-0
  if (p >= 3) fill_triangle_indices(p - 3, shift + 1, k, ij);
}

}  // namespace

Eigen::Matrix2Xi reference_node_indices(int p) {
  check_reference_order(p, "reference_node_indices");
  Eigen::Matrix2Xi ij(2, triangle_node_count(p));
  fill_triangle_indices(p, 0, 0, ij);
  return ij;
}

Eigen::Matrix2Xd reference_nodes(int p) {
  check_reference_order(p, "reference_nodes");
  return reference_node_indices(p).cast<double>() * (1.0 / p);
}

Eigen::RowVectorXd reference_line_nodes(int p) {
  check_reference_order(p, "reference_line_nodes");
  const double h = 1.0 / p;
  Eigen::RowVectorXd t(p + 1);
  t(0) = 0.0;
  t(1) = p * h;
  for (int i = 1; i < p; ++i) t(i + 1) = i * h;
  return t;
}

}  // namespace homesh
