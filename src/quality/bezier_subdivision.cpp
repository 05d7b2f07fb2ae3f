#include "quality/bezier_subdivision.h"

#include "quality/bezier_triangle.h"

namespace homesh {
namespace {

// Coefficient array of degree d; row k holds c(j, k) for j = 0..d-k contiguously
// (j, k = exponents of l1, l2; the exponent of l0 is i = d - j - k).
//
// Each function below runs the one-dimensional de Casteljau algorithm at 1/2
// on every line of coefficients along one edge direction at once, replacing a
// vertex V by the midpoint of the edge V-W: after it, c(e) is the blossom with
// V's exponent spent on the midpoint. The loops are ordered so that every
// update reads values of the previous de Casteljau level, row by row.
struct Net {
  int d;
  double* c;
  double* row(int k) const { return c + k * (d + 1) - k * (k - 1) / 2; }
};

// Vertex 1 -> midpoint of edge 0-1: c(j,k) <- (c(j-1,k) + c(j,k)) / 2.
void halve_1_to_0(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = 0; k <= n.d - it; ++k) {
      double* r = n.row(k);
      for (int j = n.d - k; j >= it; --j) r[j] = 0.5 * (r[j - 1] + r[j]);
    }
  }
}
// Vertex 2 -> midpoint of edge 0-2: c(j,k) <- (c(j,k-1) + c(j,k)) / 2.
void halve_2_to_0(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = n.d; k >= it; --k) {
      double *r = n.row(k), *below = n.row(k - 1);
      for (int j = 0; j <= n.d - k; ++j) r[j] = 0.5 * (below[j] + r[j]);
    }
  }
}
// Vertex 0 -> midpoint of edge 1-0: c(j,k) <- (c(j,k) + c(j+1,k)) / 2.
void halve_0_to_1(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = 0; k <= n.d - it; ++k) {
      double* r = n.row(k);
      for (int j = 0; j <= n.d - k - it; ++j) r[j] = 0.5 * (r[j] + r[j + 1]);
    }
  }
}
// Vertex 2 -> midpoint of edge 1-2: c(j,k) <- (c(j+1,k-1) + c(j,k)) / 2.
void halve_2_to_1(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = n.d; k >= it; --k) {
      double *r = n.row(k), *below = n.row(k - 1);
      for (int j = 0; j <= n.d - k; ++j) r[j] = 0.5 * (below[j + 1] + r[j]);
    }
  }
}
// Vertex 0 -> midpoint of edge 2-0: c(j,k) <- (c(j,k) + c(j,k+1)) / 2.
void halve_0_to_2(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = 0; k <= n.d - it; ++k) {
      double *r = n.row(k), *above = n.row(k + 1);
      for (int j = 0; j <= n.d - k - it; ++j) r[j] = 0.5 * (r[j] + above[j]);
    }
  }
}
// Vertex 1 -> midpoint of edge 2-1: c(j,k) <- (c(j-1,k+1) + c(j,k)) / 2.
void halve_1_to_2(const Net& n) {
  for (int it = 1; it <= n.d; ++it) {
    for (int k = 0; k <= n.d - it; ++k) {
      double *r = n.row(k), *above = n.row(k + 1);
      for (int j = n.d - k; j >= it; --j) r[j] = 0.5 * (above[j - 1] + r[j]);
    }
  }
}

// Vertex 0 (V0) -> V1 + V2 - V0, by d affine de Casteljau steps: at step t
// every c(j,k) with i >= t becomes c(j+1,k) + c(j,k+1) - c(j,k).
void reflect_vertex_0(const Net& n) {
  for (int t = 1; t <= n.d; ++t) {
    for (int k = 0; k <= n.d - t; ++k) {
      double *r = n.row(k), *above = n.row(k + 1);
      for (int j = 0; j <= n.d - t - k; ++j) r[j] = r[j + 1] + above[j] - r[j];
    }
  }
}

}  // namespace

void bezier_subdivide(int d, const Eigen::Ref<const Eigen::VectorXd>& c,
                      Eigen::Ref<Eigen::MatrixXd> sub) {
  for (int s = 0; s < 3; ++s) sub.col(s) = c;
  const Net s0{d, sub.col(0).data()}, s1{d, sub.col(1).data()}, s2{d, sub.col(2).data()},
      s3{d, sub.col(3).data()};
  halve_1_to_0(s0);
  halve_2_to_0(s0);
  halve_0_to_1(s1);
  halve_2_to_1(s1);
  halve_0_to_2(s2);
  halve_1_to_2(s2);
  // S3 = (M12, M20, M01): S0 = (P0, M01, M20) with vertices 1 and 2 swapped,
  // then P0 replaced by M20 + M01 - P0 = M12.
  for (int k = 0; k <= d; ++k) {
    for (int j = 0; j + k <= d; ++j) s3.row(k)[j] = s0.row(j)[k];
  }
  reflect_vertex_0(s3);
}

}  // namespace homesh
