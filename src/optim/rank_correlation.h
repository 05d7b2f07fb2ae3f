#pragma once
// Spearman's rank correlation, used to compare where two distortion fields are
// large over an element (Table 3.2 criterion, distortion_representation.h) and
// two orderings of the measures (Table 3.6, curvature_sensitivity.h).
#include <Eigen/Core>

namespace homesh {

/// Ranks 1..n of the entries of v (ascending); entries within
/// `relative_tie` * max|v| of their neighbour in sorted order form a tie and
/// share their mean rank.
Eigen::VectorXd ranks(const Eigen::VectorXd& v, double relative_tie = 1e-12);

/// Spearman's rho of a and b (same size n >= 2): the Pearson correlation of
/// their ranks, in [-1, 1]. NaN if either is constant (every entry tied): no
/// association can be measured. Throws homesh::Error on a size mismatch.
double spearman(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double relative_tie = 1e-12);

}  // namespace homesh
