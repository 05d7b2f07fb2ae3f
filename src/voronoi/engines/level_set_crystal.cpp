#include "voronoi/engines/level_set_crystal.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace homesh {

LevelSetCrystal::LevelSetCrystal(const GrowthField& field, const Eigen::Vector2d& seed,
                                 const Eigen::Matrix2d& M, double radius, int band,
                                 const Eigen::Matrix2d* own)
    : field_(&field), seed_(seed), M_(M), band_(std::max(band, 1)) {
  const CartesianGrid& g = field.grid();
  r_ = radius;
  double slowest = field.metric().min_speed(), fastest = field.metric().max_speed();
  if (own) {
    own_inverse_ = own->inverse();
    has_own_ = true;
    slowest = metric_min_speed(*own);
    fastest = metric_max_speed(*own);
  }
  deep_ = band_ * g.ds() / slowest;
  cell_ = g.ds() / fastest;
  // The seed ball's bounding box: half-widths r sqrt((M^-1)_kk).
  const Eigen::Matrix2d Minv = M.inverse();
  const double hx = r_ * std::sqrt(Minv(0, 0)), hy = r_ * std::sqrt(Minv(1, 1));
  const Eigen::Vector2i lo = g.nearest_node(seed - Eigen::Vector2d(hx, hy));
  const Eigen::Vector2i hi = g.nearest_node(seed + Eigen::Vector2d(hx, hy));
  inside_ = {lo.x(), lo.y(), hi.x(), hi.y()};
  fit_box(r_);
  inside_ = NodeBox{};
  for (int j = box_.j0; j <= box_.j1; ++j)
    for (int i = box_.i0; i <= box_.i1; ++i)
      if (phi(i, j) <= 0.0) inside_.extend(i, j);
  if (inside_.empty()) {
    const Eigen::Vector2i c = g.nearest_node(seed);
    inside_.extend(c.x(), c.y());
  }
}

double LevelSetCrystal::start_value(int i, int j, double t) const {
  const Eigen::Vector2d v = field_->grid().point(i, j) - seed_;
  return std::sqrt(v.dot(M_ * v)) - std::max(t, r_);
}

void LevelSetCrystal::fit_box(double t) {
  const CartesianGrid& g = field_->grid();
  const auto dilate = [&](const NodeBox& b, int by) {
    return NodeBox{std::max(b.i0 - by, 0), std::max(b.j0 - by, 0), std::min(b.i1 + by, g.nx - 1),
                   std::min(b.j1 + by, g.ny - 1)};
  };
  const NodeBox need = dilate(inside_, band_);
  if (box_.contains(need.i0, need.j0) && box_.contains(need.i1, need.j1)) return;
  NodeBox grown = dilate(need, band_);
  const bool had_box = !box_.empty();
  if (had_box) {
    grown.i0 = std::min(grown.i0, box_.i0);
    grown.j0 = std::min(grown.j0, box_.j0);
    grown.i1 = std::max(grown.i1, box_.i1);
    grown.j1 = std::max(grown.j1, box_.j1);
  }
  std::vector<double> phi(static_cast<std::size_t>(grown.width()) * grown.height());
  std::vector<std::uint8_t> frozen(phi.size(), 0);
  for (int j = grown.j0; j <= grown.j1; ++j) {
    for (int i = grown.i0; i <= grown.i1; ++i) {
      const std::size_t k =
          (i - grown.i0) + static_cast<std::size_t>(grown.width()) * (j - grown.j0);
      if (box_.contains(i, j)) {
        phi[k] = phi_[local(i, j)];
        frozen[k] = frozen_[local(i, j)];
      } else if (!had_box) {
        phi[k] = start_value(i, j, t);
      } else {
        // Extend the lag of the computed solution behind the exact start
        // value from the nearest node of the old box; a node entering the
        // box lies outside the crystal: keep it positive.
        const int ci = std::clamp(i, box_.i0, box_.i1), cj = std::clamp(j, box_.j0, box_.j1);
        const double lag = phi_[local(ci, cj)] - start_value(ci, cj, t);
        phi[k] = std::max(start_value(i, j, t) + lag, cell_);
      }
    }
  }
  box_ = grown;
  phi_.swap(phi);
  frozen_.swap(frozen);
  next_ = phi_;
}

double LevelSetCrystal::interpolate(double u, double v) const {
  const int w = box_.width(), h = box_.height();
  u = std::clamp(u, 0.0, w - 1.0);
  v = std::clamp(v, 0.0, h - 1.0);
  const int a = std::min(static_cast<int>(u), w - 2), b = std::min(static_cast<int>(v), h - 2);
  const double fu = u - a, fv = v - b;
  const double* p = &phi_[a + static_cast<std::size_t>(w) * b];
  return (1 - fv) * ((1 - fu) * p[0] + fu * p[1]) + fv * ((1 - fu) * p[w] + fu * p[w + 1]);
}

double LevelSetCrystal::speed(int node, const Eigen::Vector2d& N) const {
  return has_own_ ? metric_speed(own_inverse_, N) : field_->speed(node, N);
}

void LevelSetCrystal::advance(double dt, bool grow, const std::vector<int>& owner, int self) {
  if (dormant_) return;
  if (!grow) {
    next_ = phi_;
    return;
  }
  const CartesianGrid& g = field_->grid();
  const GrowthField& f = *field_;
  const bool dry = f.has_domain() && f.contact_kind() == Contact::dry;
  const double ds = g.ds();
  const int w = box_.width(), h = box_.height();
  for (int b = 0; b < h; ++b) {
    for (int a = 0; a < w; ++a) {
      const std::size_t k = a + static_cast<std::size_t>(w) * b;
      const double p = phi_[k];
      next_[k] = p;
      const int node = g.index(box_.i0 + a, box_.j0 + b);
      if (frozen_[k] || f.zone(node) == GrowthField::outside) continue;
      if (owner[node] != kFree && owner[node] != self) continue;
      if (p < -deep_) {
        // F |grad phi| = 1 for the metric distance phi approximates.
        next_[k] = p - dt;
        continue;
      }
      // Averaged unit normal: the mean of the non-zero one-sided unit normals
      // (Section 2.3); a missing side at the box edge repeats the other.
      double dxp = a + 1 < w ? (phi_[k + 1] - p) / g.dx : 0.0;
      double dxm = a > 0 ? (p - phi_[k - 1]) / g.dx : dxp;
      if (a + 1 >= w) dxp = dxm;
      double dyp = b + 1 < h ? (phi_[k + w] - p) / g.dy : 0.0;
      double dym = b > 0 ? (p - phi_[k - w]) / g.dy : dyp;
      if (b + 1 >= h) dyp = dym;
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      for (const double gx : {dxp, dxm})
        for (const double gy : {dyp, dym}) {
          const double len = std::sqrt(gx * gx + gy * gy);
          if (len > 0.0) sum += Eigen::Vector2d(gx, gy) / len;
        }
      const double len = sum.norm();
      if (len == 0.0) continue;
      const Eigen::Vector2d N = sum / len;
      double F = speed(node, N);
      if (dry && f.zone(node) == GrowthField::contact) {
        // Eq 2.13 with the speed convention of metric_field.h.
        const Eigen::Vector2d& Nb = f.boundary_normal(node);
        F = std::max(0.0, F - Nb.dot(N) * speed(node, Nb));
      }
      if (F == 0.0) continue;
      // Eqs 2.3-2.5: one-dimensional upwind gradient along N, values at
      // x +- ds N interpolated bilinearly.
      const double du = ds * N.x() / g.dx, dv = ds * N.y() / g.dy;
      const double Dp = (interpolate(a + du, b + dv) - p) / ds;
      const double Dm = (p - interpolate(a - du, b - dv)) / ds;
      const double up = std::max(0.0, Dm), down = std::min(0.0, Dp);
      next_[k] = p - dt * F * std::sqrt(up * up + down * down);
    }
  }
}

void LevelSetCrystal::freeze(int i, int j) {
  const int k = local(i, j);
  next_[k] = phi_[k];
  frozen_[k] = 1;
}

void LevelSetCrystal::commit(double t, int patience, std::vector<int>& newly_inside) {
  if (dormant_) return;
  const CartesianGrid& g = field_->grid();
  const std::size_t before = newly_inside.size();
  for (int j = box_.j0; j <= box_.j1; ++j) {
    for (int i = box_.i0; i <= box_.i1; ++i) {
      const int k = local(i, j);
      if (!(next_[k] <= 0.0 && phi_[k] > 0.0)) continue;
      newly_inside.push_back(g.index(i, j));
      inside_.extend(i, j);
    }
  }
  phi_.swap(next_);
  fit_box(t);
  if (t < r_) return;
  idle_ = newly_inside.size() == before ? idle_ + 1 : 0;
  if (idle_ >= patience) {
    dormant_ = true;
    next_ = phi_;
  }
}

}  // namespace homesh
