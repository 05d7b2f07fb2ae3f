#pragma once
// What a nodal basis on a 2D reference element offers, from the one function each
// basis defines, evaluate(uv, N, dNdu, dNdv) (writes the size() values and/or first
// derivatives at uv; null outputs are skipped): values and derivatives at a point, or
// tabulated at many. CRTP, so the evaluation inlines (element/lagrange_basis.h on the
// triangle, element/quad_lagrange_basis.h on the square).
#include <Eigen/Core>

namespace homesh {

template <class Basis>
class NodalBasis {
 public:
  int order() const { return p_; }
  int size() const { return static_cast<int>(nodes_.cols()); }
  /// 2 by size() reference nodes.
  const Eigen::Matrix2Xd& nodes() const { return nodes_; }

  /// size() values N_k(u, v).
  Eigen::VectorXd values(const Eigen::Vector2d& uv) const {
    Eigen::VectorXd N(size());
    self().evaluate(uv, N.data(), nullptr, nullptr);
    return N;
  }
  /// 2 by size() derivatives: row 0 dN_k/du, row 1 dN_k/dv.
  Eigen::Matrix2Xd gradients(const Eigen::Vector2d& uv) const {
    Eigen::VectorXd du(size()), dv(size());
    self().evaluate(uv, nullptr, du.data(), dv.data());
    Eigen::Matrix2Xd dN(2, size());
    dN.row(0) = du.transpose();
    dN.row(1) = dv.transpose();
    return dN;
  }
  /// size() by #points values at the columns of the 2 by #points matrix `uv`.
  Eigen::MatrixXd tabulate_values(const Eigen::Matrix2Xd& uv) const {
    Eigen::MatrixXd N(size(), uv.cols());
    for (Eigen::Index q = 0; q < uv.cols(); ++q)
      self().evaluate(uv.col(q), N.col(q).data(), nullptr, nullptr);
    return N;
  }
  /// size() by #points dN/du and dN/dv at the columns of `uv` (resized here).
  void tabulate_gradients(const Eigen::Matrix2Xd& uv, Eigen::MatrixXd& dNdu,
                          Eigen::MatrixXd& dNdv) const {
    dNdu.resize(size(), uv.cols());
    dNdv.resize(size(), uv.cols());
    for (Eigen::Index q = 0; q < uv.cols(); ++q)
      self().evaluate(uv.col(q), nullptr, dNdu.col(q).data(), dNdv.col(q).data());
  }

 protected:
  explicit NodalBasis(int p) : p_(p) {}

  int p_;
  Eigen::Matrix2Xd nodes_;

 private:
  const Basis& self() const { return static_cast<const Basis&>(*this); }
};

}  // namespace homesh
