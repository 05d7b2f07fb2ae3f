#pragma once
// The 1D Lagrange polynomials of degree p at the equispaced points t = 0,
// 1/p, ..., 1 (the nodes of a Gmsh line of order p, and the factors of the
// tensor-product quadrilateral basis):
//
//   L_i(t) = prod_{s != i} (p t - s) / (i - s),   i = 0..p,
//
// with their derivatives.

namespace homesh {

/// L[i] = L_i(t) and dL[i] = L_i'(t) for i = 0..p (arrays of p + 1).
void line_lagrange(int p, double t, double* L, double* dL);

}  // namespace homesh
