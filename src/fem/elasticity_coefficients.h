#pragma once
// Coefficients of the augmented elastic analogy (thesis Sec 4.2.1), evaluated at
// quadrature points in the MFEM manner: a coefficient is a constant or a
// function of the point (element index, quadrature point index, physical
// coordinates), so that E, nu, f, beta, T and the anisotropic thermal stress may
// vary in space or per element (e.g. the thesis' E = 1 / Ae, T = 1 / Ae).
#include <Eigen/Core>
#include <functional>
#include <type_traits>
#include <utility>

namespace homesh {

/// A quadrature point of 2D element `element` (triangles 0..T-1, then
/// quadrilaterals T..T+Q-1, core/mesh.h): its index in the element's rule
/// (the triangle's or the quadrilateral's) and its physical coordinates
/// x = X N(u, v).
struct QuadraturePoint {
  int element = 0;
  int index = 0;
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
};

/// A constant value of type T or a function QuadraturePoint -> T; implicitly
/// built from either, so `young = 2.0` and `young = [](const QuadraturePoint& q)
/// { return 1.0 + q.x(0); }` both work. A function should return a T (declare
/// `-> Eigen::Vector2d`), not an Eigen expression of its own temporaries.
template <class T>
class Coefficient {
 public:
  using Function = std::function<T(const QuadraturePoint&)>;

  Coefficient(const T& value) : value_(value) {}  // NOLINT(google-explicit-constructor)
  // (Values convertible to T are excluded first: Eigen's operator() is not SFINAE-friendly.)
  template <class F, class = std::enable_if_t<
                         std::conjunction_v<std::negation<std::is_convertible<F, T>>,
                                            std::is_invocable_r<T, F, const QuadraturePoint&>>>>
  Coefficient(F f) : function_(std::move(f)) {}  // NOLINT(google-explicit-constructor)

  T operator()(const QuadraturePoint& q) const { return function_ ? function_(q) : value_; }

 private:
  // Zero, not T{}: Eigen's default constructor leaves the entries unset, and a
  // function coefficient's unused value_ is still copied and moved.
  static T zero() {
    if constexpr (std::is_arithmetic_v<T>)
      return T(0);
    else
      return T::Zero();
  }

  T value_ = zero();
  Function function_;
};

using ScalarCoefficient = Coefficient<double>;
using VectorCoefficient = Coefficient<Eigen::Vector2d>;
using TensorCoefficient = Coefficient<Eigen::Matrix2d>;

/// One value per 2D element: values(q.element). `values` has #triangles +
/// #quadrilaterals entries (triangles first, core/mesh.h).
ScalarCoefficient per_element(Eigen::VectorXd values);

/// The data of the elastic analogy with additional terms, Eqs 4.1-4.5:
///   div sigma + f = 0,  sigma = lambda tr(eps) I + 2 mu eps + beta (T - T0) I + S,
/// with (lambda, mu) from (E, nu) in plane strain (lame_plane_strain) and S the
/// anisotropic thermal stress of Sec 4.4.1 (the thesis' sigma_t ~ R^T Lambda R,
/// the metric tensor of the reference->physical or ideal->physical map; the
/// caller supplies it, symmetric, already scaled).
///
/// Sign: as in Eq 4.5 the thermal terms add to the stress, so a free body with
/// uniform beta (T - T0) = s > 0 contracts: u = -s / (2 (lambda + mu)) (x - x0).
struct ElasticityCoefficients {
  ScalarCoefficient young{1.0};                                   // E > 0
  ScalarCoefficient poisson{0.4};                                 // nu in (-1, 1/2); 0.4 as Sec 4.3
  VectorCoefficient body_force{Eigen::Vector2d::Zero()};          // f
  ScalarCoefficient beta{0.0};                                    // thermal coefficient beta
  ScalarCoefficient temperature{0.0};                             // T
  double reference_temperature = 0.0;                             // T0, the stress-free state
  TensorCoefficient anisotropic_stress{Eigen::Matrix2d::Zero()};  // S, symmetric
};

/// Lame's constants of an isotropic material.
struct Lame {
  double lambda = 0.0;
  double mu = 0.0;
};

/// Plane strain, the thesis' choice (Eq 4.4 and the factor E (1 - nu) /
/// ((1 + nu)(1 - 2 nu)) = lambda + 2 mu of Eqs 4.8-4.9):
///   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = E / (2 (1 + nu)).
/// Throws homesh::Error unless E > 0 and -1 < nu < 1/2.
Lame lame_plane_strain(double young, double poisson);

}  // namespace homesh
