#include "fem/block_lower_assembly.h"

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace homesh {

namespace {

// For each unknown node v in [lo, hi), its neighbours (unknown nodes sharing an
// element) w with keep(v, w), sorted.
template <class Keep>
std::vector<std::vector<int>> neighbours(const Eigen::MatrixXi& unknown, int nodes, int lo, int hi,
                                         Keep keep) {
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
  std::vector<std::vector<int>> out(static_cast<std::size_t>(std::max(0, hi - lo)));
  std::vector<int> seen(static_cast<std::size_t>(nodes), -1);
  for (int v = lo; v < hi; ++v) {
    std::vector<int>& list = out[static_cast<std::size_t>(v - lo)];
    for (int s = start[v]; s < start[v + 1]; ++s)
      for (Eigen::Index k = 0; k < unknown.rows(); ++k) {
        const int w = unknown(k, uses[s]);
        if (w >= 0 && keep(v, w) && seen[w] != v) {
          seen[w] = v;
          list.push_back(w);
        }
      }
    std::sort(list.begin(), list.end());
  }
  return out;
}

}  // namespace

Eigen::SparseMatrix<double> block_lower_pattern(const Eigen::MatrixXi& unknown, int nodes) {
  const std::vector<std::vector<int>> above =
      neighbours(unknown, nodes, 0, nodes, [](int v, int w) { return w > v; });
  Eigen::Index entries = 0;
  for (const std::vector<int>& list : above)
    entries += 6 + 9 * static_cast<Eigen::Index>(list.size());
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

Eigen::SparseMatrix<double, Eigen::RowMajor> block_rows_pattern(const Eigen::MatrixXi& unknown,
                                                                int nodes, int first, int count) {
  if (first < 0 || count < 0 || first + count > 3 * nodes)
    throw Error("block_rows_pattern: rows " + std::to_string(first) + " to " +
                std::to_string(first + count) + " of " + std::to_string(3 * nodes));
  const int lo = first / 3, hi = count > 0 ? (first + count - 1) / 3 + 1 : lo;
  const std::vector<std::vector<int>> near =
      neighbours(unknown, nodes, lo, hi, [](int, int) { return true; });
  Eigen::Index entries = 0;
  for (int row = first; row < first + count; ++row)
    entries += 3 * static_cast<Eigen::Index>(near[static_cast<std::size_t>(row / 3 - lo)].size());
  if (entries > std::numeric_limits<int>::max())
    throw Error("block_rows_pattern: " + std::to_string(entries) +
                " entries are more than 32-bit indices hold");
  Eigen::SparseMatrix<double, Eigen::RowMajor> A(count, 3 * nodes);
  A.resizeNonZeros(entries);
  int* outer = A.outerIndexPtr();
  int* inner = A.innerIndexPtr();
  int at = 0;
  for (int row = first; row < first + count; ++row) {
    outer[row - first] = at;
    for (const int w : near[static_cast<std::size_t>(row / 3 - lo)])
      for (int j = 0; j < 3; ++j) inner[at++] = 3 * w + j;
  }
  outer[count] = at;
  std::fill(A.valuePtr(), A.valuePtr() + entries, 0.0);
  return A;
}

void add_block_rows(Eigen::SparseMatrix<double, Eigen::RowMajor>& A, int first,
                    const Eigen::Ref<const Eigen::VectorXi>& u, const Eigen::MatrixXd& Ke) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  double* value = A.valuePtr();
  const int last = first + static_cast<int>(A.rows());
  for (Eigen::Index a = 0; a < u.size(); ++a) {
    const int va = u(a);
    if (va < 0 || 3 * va + 2 < first || 3 * va >= last) continue;
    for (int i = 0; i < 3; ++i) {
      const int row = 3 * va + i - first;
      if (row < 0 || row >= A.rows()) continue;
      for (Eigen::Index b = 0; b < u.size(); ++b) {
        const int vb = u(b);
        if (vb < 0) continue;
        const int* at = std::lower_bound(inner + outer[row], inner + outer[row + 1], 3 * vb);
        const std::ptrdiff_t pos = at - inner;
        // The entry as the lower triangle has it (Ke need not be symmetric to
        // the last bit), so these rows are those of block_lower_pattern's
        // matrix made symmetric, bit for bit.
        for (int j = 0; j < 3; ++j)
          value[pos + j] +=
              3 * va + i >= 3 * vb + j ? Ke(3 * a + i, 3 * b + j) : Ke(3 * b + j, 3 * a + i);
      }
    }
  }
}

}  // namespace homesh
