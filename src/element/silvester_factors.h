#pragma once
// The one-variable factors of Silvester's Lagrange basis on simplices (1969,
// "High-order polynomial triangular finite elements for potential problems"):
//
//   R_m(l) = prod_{s=0}^{m-1} (p l - s) / (s + 1),   m = 0..p,
//
// which vanish at l = 0, 1/p, ..., (m-1)/p and are 1 at l = m/p. The triangle's and
// the tetrahedron's bases (element/lagrange_basis.h, element/tet_lagrange_basis.h)
// are products of them, one per barycentric coordinate.

namespace homesh {

/// R[m] = R_m(l) and dR[m] = R_m'(l) for m = 0..p (p + 1 entries each).
inline void silvester_factors(int p, double l, double* R, double* dR) {
  const double pl = p * l;
  R[0] = 1.0;
  dR[0] = 0.0;
  for (int m = 1; m <= p; ++m) {
    const double f = (pl - (m - 1)) / m;
    dR[m] = dR[m - 1] * f + R[m - 1] * (static_cast<double>(p) / m);
    R[m] = R[m - 1] * f;
  }
}

}  // namespace homesh
