#include "voronoi/metric/metric_field.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "voronoi/metric/wall_layer.h"

namespace homesh {
namespace {

Eigen::Vector2d eigenvalues(const Eigen::Matrix2d& M) {
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(M, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace

Eigen::Matrix2d metric_from_axes(double theta, double h1, double h2) {
  if (!(h1 > 0.0 && h2 > 0.0)) throw Error("metric_from_axes: semi-axes must be positive");
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d R;
  R << c, s, -s, c;
  const Eigen::Vector2d lambda(1.0 / (h1 * h1), 1.0 / (h2 * h2));
  return R.transpose() * lambda.asDiagonal() * R;
}

double metric_max_speed(const Eigen::Matrix2d& M) { return 1.0 / std::sqrt(eigenvalues(M)(0)); }
double metric_min_speed(const Eigen::Matrix2d& M) { return 1.0 / std::sqrt(eigenvalues(M)(1)); }

bool MetricField::same_tensors(const MetricField& o) const {
  if (tensors_ == o.tensors_) return true;
  if (a_ && o.a_) return tensors_->a == o.tensors_->a;
  if (!a_ && !o.a_) return tensors_->M == o.tensors_->M;
  for (int k = 0; k < coarse_.node_count(); ++k)
    if (metric(k) != o.metric(k)) return false;
  return true;
}

bool MetricField::operator==(const MetricField& o) const {
  const CartesianGrid &a = coarse_, &b = o.coarse_;
  return a.origin == b.origin && a.dx == b.dx && a.dy == b.dy && a.nx == b.nx && a.ny == b.ny &&
         same_tensors(o) && layer_ == o.layer_;
}

MetricField MetricField::with_layer(std::shared_ptr<const WallLayer> layer) const {
  MetricField out = *this;
  out.anisotropy_ = std::max(anisotropy_, layer->aspect());
  out.min_speed_ = std::min(min_speed_, layer->iso().min_speed() / layer->aspect());
  out.uniform_ = false;
  out.layer_ = std::move(layer);
  return out;
}

MetricField::MetricField(const CartesianGrid& coarse, std::vector<Eigen::Matrix2d> M)
    : MetricField(coarse, [&M] {
        auto t = std::make_shared<Tensors>();
        t->M = std::move(M);
        return t;
      }()) {}

MetricField MetricField::isotropic(const CartesianGrid& coarse, std::vector<double> a) {
  auto t = std::make_shared<Tensors>();
  t->a = std::move(a);
  return MetricField(coarse, std::move(t));
}

MetricField::MetricField(const CartesianGrid& coarse, std::shared_ptr<Tensors> t)
    : coarse_(coarse) {
  const bool iso = t->M.empty();
  const std::size_t count = iso ? t->a.size() : t->M.size();
  if (static_cast<int>(count) != coarse_.node_count())
    throw Error("MetricField: " + std::to_string(count) + " metrics for " +
                std::to_string(coarse_.node_count()) + " coarse nodes");
  M_ = iso ? nullptr : t->M.data();
  a_ = iso ? t->a.data() : nullptr;
  tensors_ = std::move(t);
  max_speed_ = 0.0;
  min_speed_ = std::numeric_limits<double>::infinity();
  for (int k = 0; k < static_cast<int>(count); ++k) {
    const Eigen::Matrix2d m = metric(k);
    // An isotropic tensor (the iso metric's at every node) has its diagonal
    // as eigenvalues: Eigen's solver gives exactly that, at some 100 ns a node.
    const bool isotropic = m(0, 1) == 0.0 && m(1, 0) == 0.0 && m(0, 0) == m(1, 1);
    const Eigen::Vector2d lambda = a_          ? Eigen::Vector2d(a_[k], a_[k])
                                   : isotropic ? Eigen::Vector2d(m(0, 0), m(0, 0))
                                               : eigenvalues(m);
    if (std::abs(m(0, 1) - m(1, 0)) > 1e-12 * m.norm() || !(lambda(0) > 0.0))
      throw Error("MetricField: metric at coarse node " + std::to_string(k) +
                  " is not symmetric positive definite");
    max_speed_ = std::max(max_speed_, 1.0 / std::sqrt(lambda(0)));
    min_speed_ = std::min(min_speed_, 1.0 / std::sqrt(lambda(1)));
    anisotropy_ = std::max(anisotropy_, std::sqrt(lambda(1) / lambda(0)));
    uniform_ = uniform_ && m == metric(0);
  }
}

const std::vector<Eigen::Matrix2d>& MetricField::inverses() const {
  const Tensors& t = *tensors_;
  std::call_once(t.inverted, [this, &t] {
    const int n = coarse_.node_count();
    t.Minv.reserve(n);
    for (int k = 0; k < n; ++k) t.Minv.push_back(metric(k).inverse());
  });
  return t.Minv;
}

MetricField MetricField::constant(const Eigen::Matrix2d& M) {
  return MetricField(CartesianGrid::spanning({0.0, 0.0}, {1.0, 1.0}, 2, 2), {M, M, M, M});
}

ShepardStencil MetricField::stencil(const Eigen::Vector2d& p) const {
  const CartesianGrid& g = coarse_;
  const double u = std::clamp((p.x() - g.origin.x()) / g.dx, 0.0, g.nx - 1.0);
  const double v = std::clamp((p.y() - g.origin.y()) / g.dy, 0.0, g.ny - 1.0);
  const int i = std::min(static_cast<int>(u), g.nx - 2);
  const int j = std::min(static_cast<int>(v), g.ny - 2);
  ShepardStencil s;
  const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
  double sum = 0.0;
  for (int k = 0; k < 4; ++k) {
    s.node[k] = g.index(i + di[k], j + dj[k]);
    const double ex = (u - (i + di[k])) * g.dx, ey = (v - (j + dj[k])) * g.dy;
    const double d2 = ex * ex + ey * ey;
    if (d2 == 0.0) {
      s.w = {0.0, 0.0, 0.0, 0.0};
      s.w[k] = 1.0;
      return s;
    }
    s.w[k] = 1.0 / d2;
    sum += s.w[k];
  }
  for (double& w : s.w) w /= sum;
  return s;
}

double MetricField::stencil_speed(const ShepardStencil& s, const Eigen::Vector2d& N) const {
  const std::vector<Eigen::Matrix2d>& Minv = inverses();
  double F = 0.0;
  for (int k = 0; k < 4; ++k)
    if (s.w[k] != 0.0) F += s.w[k] * metric_speed(Minv[s.node[k]], N);
  return F;
}

Eigen::Matrix2d MetricField::metric_at(const Eigen::Vector2d& p) const {
  if (layer_) return layer_->at(p);
  // stencil(p)'s weights 1/d_k^2, normalised, as products with a single
  // division: w_k = prod_{l != k} d_l^2 / sum_m prod_{l != m} d_l^2 (the
  // distances in units of dx, the weights being scale-free). The fast
  // marching engine takes one metric per fine node.
  const CartesianGrid& g = coarse_;
  const double u = std::clamp((p.x() - g.origin.x()) / g.dx, 0.0, g.nx - 1.0);
  const double v = std::clamp((p.y() - g.origin.y()) / g.dy, 0.0, g.ny - 1.0);
  const int i = std::min(static_cast<int>(u), g.nx - 2);
  const int j = std::min(static_cast<int>(v), g.ny - 2);
  const double ratio = g.dy / g.dx;
  const double x0 = u - i, x1 = 1.0 - x0, y0 = (v - j) * ratio, y1 = ratio - y0;
  // Corners counter-clockwise from (i, j), as in stencil().
  const double d[4] = {x0 * x0 + y0 * y0, x1 * x1 + y0 * y0, x1 * x1 + y1 * y1, x0 * x0 + y1 * y1};
  const int node[4] = {g.index(i, j), g.index(i + 1, j), g.index(i + 1, j + 1), g.index(i, j + 1)};
  for (int k = 0; k < 4; ++k)
    if (d[k] == 0.0) return metric(node[k]);
  const double d01 = d[0] * d[1], d23 = d[2] * d[3];
  const double w[4] = {d[1] * d23, d[0] * d23, d01 * d[3], d01 * d[2]};
  const double scale = 1.0 / (w[0] + w[1] + w[2] + w[3]);
  if (a_) {  // the diagonal entry of the tensors' sum below, in the same order
    double a = w[0] * a_[node[0]];
    for (int k = 1; k < 4; ++k) a += w[k] * a_[node[k]];
    return Eigen::Matrix2d::Identity() * (a * scale);
  }
  Eigen::Matrix2d M = w[0] * M_[node[0]];
  for (int k = 1; k < 4; ++k) M += w[k] * M_[node[k]];
  return M * scale;
}

}  // namespace homesh
