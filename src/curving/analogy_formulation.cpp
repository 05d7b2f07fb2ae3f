#include "curving/analogy_formulation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "curving/element_distortion.h"
#include "element/quad_lagrange_basis.h"
#include "element/quad_reference_nodes.h"
#include "element/square_quadrature.h"
#include "fem/element_tabulation.h"
#include "quality/ideal_jacobian.h"
#include "quality/shape_measures.h"

namespace homesh {
namespace {

// (min Q / max Q)^-1 per element, capped at 1e3 so that a nearly degenerate
// element gets a large but finite coefficient.
Eigen::VectorXd inverse_ratio(const Eigen::VectorXd& ratio) {
  return ratio.cwiseMax(1e-3).cwiseInverse();
}

ElasticityCoefficients base(const FormulationParams& p) {
  ElasticityCoefficients c;
  c.young = 1.0;
  c.poisson = p.poisson;
  c.reference_temperature = 1.0;
  return c;
}

// Case 1: E = 1, no added terms.
ElasticityCoefficients plain(const Mesh&, const Mesh&, const FormulationParams& p) {
  return base(p);
}

// element_distortion (curving/element_distortion.h) of the triangles followed
// by the same quantities of the quadrilaterals, in the 2D element order of
// core/mesh.h. The ideal element of a quadrilateral is the unit square, so
// W = J (as the quad quality measures, quality/mesh_quality.h): area = int det J
// over the square (square_quadrature(2p - 1), exact: det J is of degree
// 2p - 1 per variable), q17_ratio = min det J / max det J and shape = min
// Q11(J) over the order-2p lattice of the square (corners included), as the
// triangles' over theirs.
ElementDistortion distortion_2d(const Mesh& m) {
  ElementDistortion d = element_distortion(m);
  if (m.num_quads() == 0) return d;
  const int p = m.order, t = m.num_triangles(), n = m.num_elements_2d();
  const QuadLagrangeBasis basis(p);
  const Eigen::Matrix2Xd lattice = quad_reference_nodes(2 * p);
  const QuadratureRule rule = square_quadrature(2 * p - 1);
  Eigen::MatrixXd lu, lv, qu, qv;
  basis.tabulate_gradients(lattice, lu, lv);
  basis.tabulate_gradients(rule.points, qu, qv);
  d.area.conservativeResize(n);
  d.q17_ratio.conservativeResize(n);
  d.shape.conservativeResize(n);
  for (int e = 0; e < m.num_quads(); ++e) {
    const Eigen::Matrix2Xd X = m.quad_nodes(e);
    auto jacobian = [&](const Eigen::MatrixXd& du, const Eigen::MatrixXd& dv, Eigen::Index k) {
      Eigen::Matrix2d J;
      J.col(0) = X * du.col(k);
      J.col(1) = X * dv.col(k);
      return J;
    };
    double lo = INFINITY, hi = -INFINITY, shape = 1.0;
    for (Eigen::Index k = 0; k < lattice.cols(); ++k) {
      const Eigen::Matrix2d J = jacobian(lu, lv, k);
      const double v = J.determinant();
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      shape = std::min(shape, v > 0 ? condition_number_quality(J) : 0.0);
    }
    double area = 0;
    for (Eigen::Index k = 0; k < rule.points.cols(); ++k)
      area += rule.weights(k) * jacobian(qu, qv, k).determinant();
    d.q17_ratio(t + e) = hi > 0 ? lo / hi : 0.0;
    d.shape(t + e) = shape;
    d.area(t + e) = area;
  }
  return d;
}

// The A_e of the area formulations: a triangle's area, half a quadrilateral's.
// E = 1 / A_e stiffens small elements; halving a quadrilateral's area makes a
// grid of cells equally stiff whether its cells are quadrilaterals or pairs of
// triangles (measured: with whole areas the quadrilaterals of a mixed mesh were
// twice as soft as the triangles beside them and took the deformation, worst
// minJ/maxJ 0.19 against 0.55 for E = 1, tests/curving/deform_mesh_quad_test.cpp).
Eigen::VectorXd size_area(const Mesh& m) {
  Eigen::VectorXd a = distortion_2d(m).area;
  a.tail(m.num_quads()) *= 0.5;
  return a;
}

// Case 2: E = 1 / Ae (Palmerio's stiffening of small elements).
ElasticityCoefficients area(const Mesh& m, const Mesh&, const FormulationParams& p) {
  ElasticityCoefficients c = base(p);
  c.young = per_element(size_area(m).cwiseInverse());
  return c;
}

// Case 3: E = 1, f_x = f_y = heat ((min Q17 / max Q17)^-1 - 1) per element: the
// thesis' force less its undistorted value 1, so that an undistorted mesh feels
// no force (as T0 = 1 does for the heat terms).
ElasticityCoefficients force_q17(const Mesh& m, const Mesh&, const FormulationParams& p) {
  ElasticityCoefficients c = base(p);
  const Eigen::VectorXd t = inverse_ratio(distortion_2d(m).q17_ratio);
  c.body_force = [t, s = p.heat](const QuadraturePoint& q) {
    return Eigen::Vector2d::Constant(s * (t(q.element) - 1.0));
  };
  return c;
}

ElasticityCoefficients heated(const FormulationParams& p, Eigen::VectorXd temperature) {
  ElasticityCoefficients c = base(p);
  c.beta = -p.heat;
  c.temperature = per_element(std::move(temperature));
  return c;
}

// Case 4: T = (min Q17 / max Q17)^-1 per element.
ElasticityCoefficients heat_q17(const Mesh& m, const Mesh&, const FormulationParams& p) {
  return heated(p, inverse_ratio(distortion_2d(m).q17_ratio));
}

// Case 5: T = (min Q4 / max Q4)^-1, Q4 = omega^2 (Eq 3.38).
ElasticityCoefficients heat_q4(const Mesh& m, const Mesh&, const FormulationParams& p) {
  return heated(p, inverse_ratio(distortion_2d(m).q17_ratio.cwiseAbs2()));
}

// Section 4.4.2: T = 1 / Ae, scaled so the mean element is at T0 = 1.
ElasticityCoefficients heat_area(const Mesh& m, const Mesh&, const FormulationParams& p) {
  const Eigen::VectorXd a = size_area(m);
  return heated(p, a.mean() * a.cwiseInverse());
}

// Cases 6 and 7: sigma_t ~ R^T Lambda R, the metric tensor of the map at each
// quadrature point (reference->physical: J^T J; ideal->physical: W^T W, Eq 3.14),
// scaled to unit determinant so that only its shape acts (the thesis does not
// state its scaling). The thesis activates its added terms "once elements have
// undergone an extreme distortion" (Section 4.4); we take the continuous form of
// that rule: the stress is the change of the scaled metric since the start of
// the deformation, sigma_t = -heat (M^ - M^_initial), so an element the
// deformation has not distorted is stress free whatever its shape or labels.
Eigen::Matrix2d scaled_metric(const Eigen::Matrix2d& F) {
  const Eigen::Matrix2d M = F.transpose() * F;
  const double det = M.determinant();
  return det > 0 ? Eigen::Matrix2d(M / std::sqrt(det)) : Eigen::Matrix2d::Identity();
}

// The tabulations at the rules the assembly uses (coefficients are read at
// their points by QuadraturePoint::index): triangles, and quadrilaterals if m
// has any.
struct AssemblyTabulations {
  ElementTabulation triangle, quad;
};

AssemblyTabulations assembly_tabulations(const Mesh& m, const FormulationParams& p) {
  AssemblyTabulations tabs;
  const int margin = p.assembly.quadrature_margin;
  tabs.triangle = tabulate_element(m.order, stiffness_quadrature_degree(m.order, margin));
  if (m.num_quads() > 0)
    tabs.quad = tabulate_quad_element(m.order, quad_stiffness_quadrature_degree(m.order, margin));
  return tabs;
}

// The reference->physical Jacobian J of every 2D element of m at every point
// of its rule, element-major: point k of element e at start[e] + k
// (e * #points on a triangle mesh).
struct QuadratureJacobians {
  std::vector<Eigen::Matrix2d> J;
  std::vector<std::size_t> start;  // #2D elements + 1
};

QuadratureJacobians quadrature_jacobians(const Mesh& m, const AssemblyTabulations& tabs) {
  QuadratureJacobians out;
  out.start.push_back(0);
  auto add = [&](const Eigen::Matrix2Xd& X, const ElementTabulation& tab) {
    for (Eigen::Index k = 0; k < tab.rule.points.cols(); ++k) {
      Eigen::Matrix2d J;
      J.col(0) = X * tab.dNdu.col(k);
      J.col(1) = X * tab.dNdv.col(k);
      out.J.push_back(J);
    }
    out.start.push_back(out.J.size());
  };
  for (int e = 0; e < m.num_triangles(); ++e) add(m.triangle_nodes(e), tabs.triangle);
  for (int e = 0; e < m.num_quads(); ++e) add(m.quad_nodes(e), tabs.quad);
  return out;
}

ElasticityCoefficients metric(const Mesh& m, const Mesh& initial, const FormulationParams& p,
                              bool ideal) {
  ElasticityCoefficients c = base(p);
  const AssemblyTabulations tabs = assembly_tabulations(m, p);
  const QuadratureJacobians J = quadrature_jacobians(m, tabs),
                            J0 = quadrature_jacobians(initial, tabs);
  // Ideal->physical: W = J inv(J_ri) on a triangle (quality/ideal_jacobian.h);
  // W = J on a quadrilateral, whose ideal element is the unit square.
  const Eigen::Matrix2d map = ideal ? Eigen::Matrix2d(reference_to_ideal_jacobian().inverse())
                                    : Eigen::Matrix2d::Identity();
  const std::size_t quads_from = J.start[std::size_t(m.num_triangles())];
  std::vector<Eigen::Matrix2d> table(J.J.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Eigen::Matrix2d& F = i < quads_from ? map : Eigen::Matrix2d::Identity();
    table[i] = scaled_metric(J.J[i] * F) - scaled_metric(J0.J[i] * F);
  }
  c.anisotropic_stress = [table = std::move(table), start = J.start,
                          s = -p.heat](const QuadraturePoint& q) {
    return Eigen::Matrix2d(s * table[start[std::size_t(q.element)] + std::size_t(q.index)]);
  };
  return c;
}

ElasticityCoefficients metric_ref(const Mesh& m, const Mesh& initial, const FormulationParams& p) {
  return metric(m, initial, p, false);
}
ElasticityCoefficients metric_ideal(const Mesh& m, const Mesh& initial,
                                    const FormulationParams& p) {
  return metric(m, initial, p, true);
}

// Case 8: E = (min Q17 / max Q17)^-power (power 1 in the thesis), no added terms.
ElasticityCoefficients stiff_q17(const Mesh& m, const Mesh&, const FormulationParams& p) {
  ElasticityCoefficients c = base(p);
  c.young = per_element(inverse_ratio(distortion_2d(m).q17_ratio).array().pow(p.power).matrix());
  return c;
}

// homesh extension: E = (q / q0)^-power, q the worst shape quality of the
// element (Q11 = 2 / (|W|_F |W^-1|_F), Eq 3.44, over the order-2p lattice) and
// q0 its value on the initial mesh, the ratio capped to [1e-3, 1]. Unlike
// min Q17 / max Q17, which sees only the variation of det J inside an element
// and stays 1 for a uniformly sheared straight-sided element, Q11 sees the
// shear itself; dividing by q0 stiffens the elements the deformation has
// distorted, not those that started out poor. The stiffening of elements by
// their deformation follows Jacobian-based stiffening (Stein, Tezduyar and
// Benney, J. Appl. Mech. 70, 2003).
ElasticityCoefficients stiff_shape(const Mesh& m, const Mesh& initial, const FormulationParams& p) {
  ElasticityCoefficients c = base(p);
  const Eigen::VectorXd q = distortion_2d(m).shape, q0 = distortion_2d(initial).shape;
  const Eigen::VectorXd ratio = q.cwiseQuotient(q0.cwiseMax(1e-12)).cwiseMin(1.0);
  c.young = per_element(inverse_ratio(ratio).array().pow(p.power).matrix());
  return c;
}

// homesh extension (stiff_shear): the shear modulus alone stiffened, point by
// point,
//   mu = mu0 (R_e q_F)^-power,  lambda = lambda0,
// at every quadrature point of the assembly, with (lambda0, mu0) those of
// E = 1 and nu (plane strain), R_e = min Q17 / max Q17 of the element (case 8)
// and q_F = 2 det F / |F|_F^2, the condition-number quality (Q11, Eq 3.44;
// Knupp, IJNME 48, 2000) of the deformation gradient F = J J0^-1 from the
// initial mesh to the current one at that point: 1 while the deformation
// there is a rotation and uniform scaling, falling as it shears. Two
// distortions, two factors: R_e sees det J vary inside a curved element, q_F
// the shear a turning wall puts into its neighbours, which R_e does not see.
// The stiffening by a power of a local deformation measure is the
// Jacobian-based stiffening of Stein, Tezduyar and Benney (J. Appl. Mech. 70,
// 2003), there per element and applied to E. Here it acts on mu only, since
// the measures are of shape: a distorted point resists further shape change
// but keeps lambda, the resistance to area change, instead of locking as E
// and lambda grow together (its effective Poisson ratio falls towards 0).
// R_e q_F is capped below at 1e-4. Every factor is 1 on a rigid motion of a
// straight-sided initial mesh, so then E = 1 and nu as given.
ElasticityCoefficients stiff_shear(const Mesh& m, const Mesh& initial, const FormulationParams& p) {
  ElasticityCoefficients c = base(p);
  const AssemblyTabulations tabs = assembly_tabulations(m, p);
  const QuadratureJacobians J = quadrature_jacobians(m, tabs),
                            J0 = quadrature_jacobians(initial, tabs);
  const Eigen::VectorXd ratio = distortion_2d(m).q17_ratio;
  const Lame lame0 = lame_plane_strain(1.0, p.poisson);
  const double lambda = lame0.lambda;
  std::vector<double> young(J.J.size()), poisson(J.J.size());
  for (int e = 0; e + 1 < int(J.start.size()); ++e)
    for (std::size_t i = J.start[std::size_t(e)]; i < J.start[std::size_t(e) + 1]; ++i) {
      const Eigen::Matrix2d F = J.J[i] * J0.J[i].inverse();
      const double q = F.determinant() > 0 ? condition_number_quality(F) : 0.0;
      const double mu = lame0.mu * std::pow(std::max(ratio(e) * q, 1e-4), -p.power);
      young[i] = mu * (3 * lambda + 2 * mu) / (lambda + mu);
      poisson[i] = lambda / (2 * (lambda + mu));
    }
  c.young = [young = std::move(young), start = J.start](const QuadraturePoint& q) {
    return young[start[std::size_t(q.element)] + std::size_t(q.index)];
  };
  c.poisson = [poisson = std::move(poisson), start = J.start](const QuadraturePoint& q) {
    return poisson[start[std::size_t(q.element)] + std::size_t(q.index)];
  };
  return c;
}

}  // namespace

const std::vector<AnalogyFormulation>& analogy_formulations() {
  static const std::vector<AnalogyFormulation> table = {
      {"plain", "case 1: E = 1, no added terms", plain},
      {"area", "case 2: E = 1/Ae", area},
      {"force_q17", "case 3: E = 1, fx = fy = (min Q17/max Q17)^-1 - 1", force_q17},
      {"heat_q17", "case 4: E = 1, T = (min Q17/max Q17)^-1", heat_q17},
      {"heat_q4", "case 5: E = 1, T = (min Q4/max Q4)^-1", heat_q4},
      {"metric_ref", "case 6: E = 1, sigma_t ~ R^T Lambda R of the reference->physical map",
       metric_ref},
      {"metric_ideal", "case 7: E = 1, sigma_t ~ R^T Lambda R of the ideal->physical map",
       metric_ideal},
      {"stiff_q17", "case 8: E = (min Q17/max Q17)^-power (thesis: power 1), no added terms",
       stiff_q17},
      {"heat_area", "Section 4.4.2: E = 1, T = 1/Ae", heat_area},
      {"stiff_shape", "homesh: E = (min Q11 / initial min Q11)^-power, shear-aware stiffening",
       stiff_shape},
      {"stiff_shear",
       "homesh: mu = (min Q17/max Q17 * Q11(F))^-power per quadrature point, lambda kept; "
       "F = J J0^-1 (recommended power 3)",
       stiff_shear},
  };
  return table;
}

std::string analogy_formulation_names() {
  std::string names;
  for (const auto& f : analogy_formulations()) names += (names.empty() ? "" : " | ") + f.name;
  return names;
}

const AnalogyFormulation& analogy_formulation(const std::string& name) {
  std::string known;
  for (const auto& f : analogy_formulations()) {
    if (f.name == name) return f;
    known += (known.empty() ? "" : ", ") + f.name;
  }
  throw Error("unknown formulation '" + name + "' (formulations: " + known + ")");
}

}  // namespace homesh
