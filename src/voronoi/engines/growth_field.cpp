#include "voronoi/engines/growth_field.h"

namespace homesh {

GrowthField::GrowthField(const VoronoiProblem& problem)
    : grid_(problem.grid),
      metric_(problem.metric),
      contact_(problem.contact),
      domain_(problem.domain) {
  check_domain_size(problem);
  const CartesianGrid& g = grid_;
  const int n = g.node_count();
  if (!metric_.uniform()) {
    stencil_.resize(n);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) stencil_[g.index(i, j)] = metric_.stencil(g.point(i, j));
  }
  inside_count_ = n;
  if (!has_domain()) return;
  // The contact band: one cell into the boundary crystal, so that a wall of
  // three cells or more has a core no crystal enters.
  const double width = g.ds();
  zone_.assign(n, inside);
  normal_.assign(n, Eigen::Vector2d::Zero());
  inside_count_ = 0;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int k = g.index(i, j);
      const double d = domain_(k);
      if (d <= 0.0) {
        ++inside_count_;
        continue;
      }
      zone_[k] = d <= width ? contact : outside;
      const int il = i > 0 ? i - 1 : i, ir = i + 1 < g.nx ? i + 1 : i;
      const int jl = j > 0 ? j - 1 : j, jr = j + 1 < g.ny ? j + 1 : j;
      const Eigen::Vector2d grad(
          (domain_(g.index(ir, j)) - domain_(g.index(il, j))) / ((ir - il) * g.dx),
          (domain_(g.index(i, jr)) - domain_(g.index(i, jl))) / ((jr - jl) * g.dy));
      if (grad.norm() > 0.0) normal_[k] = grad.normalized();
    }
  }
}

double GrowthField::speed(int node, const Eigen::Vector2d& N) const {
  return metric_.uniform() ? metric_speed(metric_.inverse(0), N)
                           : metric_.stencil_speed(stencil_[node], N);
}

}  // namespace homesh
