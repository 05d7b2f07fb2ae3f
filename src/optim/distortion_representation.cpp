#include "optim/distortion_representation.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>

#include "element/quadrature.h"
#include "element/reference_nodes.h"
#include "optim/rank_correlation.h"
#include "quality/distortion.h"
#include "quality/element_quality.h"
#include "quality/ideal_jacobian.h"

namespace homesh {
namespace {

// Differences below this are rounding: W, H and Theta of the ideal element
// are exact to O(1e-15).
constexpr double kRounding = 1e-9;

bool constant(const Eigen::VectorXd& v) {
  return v.maxCoeff() - v.minCoeff() <= kRounding * std::max(1.0, v.cwiseAbs().maxCoeff());
}

}  // namespace

double hencky_distortion(const Eigen::Matrix2d& W) {
  if (!(W.determinant() > 0.0)) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d s = Eigen::JacobiSVD<Eigen::Matrix2d>(W).singularValues();
  return std::hypot(std::log(s[0]), std::log(s[1]));
}

RepresentationCell assess_representation(const Measure& m, const GalleryElement& e,
                                         const RepresentationCriterion& c) {
  RepresentationCell cell;
  cell.measure = m.name;
  cell.element = e.name;
  const ElementSampling rule(e.order, triangle_quadrature(c.distortion.quadrature_degree));
  cell.f = distortion_function(m, rule, e.nodes, c.distortion.r, c.distortion.reference);

  const ElementSampling samples(e.order, reference_nodes(c.lattice_order));
  const Eigen::VectorXd q = element_quality(m, samples, e.nodes, c.distortion.reference).values;
  Eigen::VectorXd theta(samples.size()), hencky(samples.size()), w(4 * samples.size());
  for (int k = 0; k < samples.size(); ++k) {
    const Eigen::Matrix2d W = ideal_jacobian(samples.jacobian(e.nodes, k));
    theta[k] = distortion(q[k]);
    hencky[k] = hencky_distortion(W);
    w.segment<4>(4 * k) = Eigen::Map<const Eigen::Vector4d>(W.data());
  }
  cell.distorted = hencky.maxCoeff() > kRounding;
  cell.affine = true;
  for (int i = 0; i < 4; ++i) {
    cell.affine =
        cell.affine && constant(Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<4>>(
                           w.data() + i, samples.size()));
  }
  cell.correlation = spearman(theta, hencky, kRounding);
  cell.detected = cell.f > c.detection;
  cell.distributes = cell.affine || !constant(theta);
  cell.inverted = !cell.affine && cell.correlation <= -c.inversion;
  if (cell.distorted) {
    cell.detects = cell.detected;
    cell.detects_and_distributes = cell.detected && cell.distributes;
    cell.represents = cell.detects_and_distributes && !cell.inverted;
  } else {
    cell.detects = cell.detects_and_distributes = cell.represents = !cell.detected;
  }
  return cell;
}

std::vector<RepresentationCell> distortion_representation(
    const std::vector<GalleryElement>& gallery, const RepresentationCriterion& c) {
  std::vector<RepresentationCell> cells;
  for (const Measure& m : measures()) {
    for (const GalleryElement& e : gallery) cells.push_back(assess_representation(m, e, c));
  }
  return cells;
}

TableAgreement compare_with_thesis(const std::vector<RepresentationCell>& cells,
                                   const ThesisTable& table, bool RepresentationCell::*tick) {
  TableAgreement result;
  for (const RepresentationCell& cell : cells) {
    if (!table.has(cell.measure, cell.element)) continue;
    ++result.compared;
    if ((cell.*tick) == (table.at(cell.measure, cell.element) == "1")) {
      ++result.agree;
    } else {
      result.disagreements.push_back(&cell);
    }
  }
  return result;
}

}  // namespace homesh
