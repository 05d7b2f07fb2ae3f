#include "fem/block_lower_assembly.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace homesh {

Eigen::SparseMatrix<double> block_lower_pattern(const Eigen::MatrixXi& unknown, int nodes) {
  // Each unknown node's elements, then its neighbours above it.
  std::vector<int> start(static_cast<std::size_t>(nodes) + 1, 0), uses;
  for (Eigen::Index e = 0; e < unknown.cols(); ++e)
    for (Eigen::Index k = 0; k < unknown.rows(); ++k)
      if (unknown(k, e) >= 0) ++start[static_cast<std::size_t>(unknown(k, e)) + 1];
  for (int v = 0; v < nodes; ++v) start[v + 1] += start[v];
  uses.resize(static_cast<std::size_t>(start.back()));
  {
    std::vector<int> next(start.begin(), start.end() - 1);
    for (Eigen::Index e = 0; e < unknown.cols(); ++e)
      for (Eigen::Index k = 0; k < unknown.rows(); ++k)
        if (unknown(k, e) >= 0) uses[next[unknown(k, e)]++] = static_cast<int>(e);
  }
  std::vector<std::vector<int>> above(static_cast<std::size_t>(nodes));
  std::vector<int> seen(static_cast<std::size_t>(nodes), -1);
  Eigen::Index entries = 0;
  for (int v = 0; v < nodes; ++v) {
    std::vector<int>& list = above[static_cast<std::size_t>(v)];
    for (int s = start[v]; s < start[v + 1]; ++s)
      for (Eigen::Index k = 0; k < unknown.rows(); ++k) {
        const int w = unknown(k, uses[s]);
        if (w > v && seen[w] != v) {
          seen[w] = v;
          list.push_back(w);
        }
      }
    std::sort(list.begin(), list.end());
    entries += 6 + 9 * static_cast<Eigen::Index>(list.size());
  }
  if (entries > std::numeric_limits<int>::max())
    throw Error("block_lower_pattern: " + std::to_string(entries) +
                " entries are more than 32-bit indices hold");
  Eigen::SparseMatrix<double> A(3 * nodes, 3 * nodes);
  A.resizeNonZeros(entries);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  int at = 0;
  for (int v = 0; v < nodes; ++v)
    for (int j = 0; j < 3; ++j) {
      outer[3 * v + j] = at;
      for (int i = j; i < 3; ++i) inner[at++] = 3 * v + i;
      for (const int w : above[static_cast<std::size_t>(v)])
        for (int i = 0; i < 3; ++i) inner[at++] = 3 * w + i;
    }
  outer[3 * nodes] = at;
  std::fill(A.valuePtr(), A.valuePtr() + entries, 0.0);
  return A;
}

void add_block_lower(Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::VectorXi>& u,
                     const Eigen::MatrixXd& Ke) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  double* value = A.valuePtr();
  for (Eigen::Index b = 0; b < u.size(); ++b) {
    const int vb = u(b);
    if (vb < 0) continue;
    for (Eigen::Index a = 0; a < u.size(); ++a) {
      const int va = u(a);
      if (va < vb) continue;
      if (va == vb) {  // the diagonal block: column 3 vb + j starts at row 3 vb + j
        for (int j = 0; j < 3; ++j)
          for (int i = j; i < 3; ++i) value[outer[3 * vb + j] + i - j] += Ke(3 * a + i, 3 * b + j);
        continue;
      }
      // va's place among vb's neighbours above it, found in column 3 vb; the
      // other two columns list the same rows after a shorter diagonal part.
      const int* first = inner + outer[3 * vb] + 3;
      const std::ptrdiff_t slot =
          std::lower_bound(first, inner + outer[3 * vb + 1], 3 * va) - first;
      for (int j = 0; j < 3; ++j) {
        double* at = value + outer[3 * vb + j] + (3 - j) + slot;
        for (int i = 0; i < 3; ++i) at[i] += Ke(3 * a + i, 3 * b + j);
      }
    }
  }
}

}  // namespace homesh
