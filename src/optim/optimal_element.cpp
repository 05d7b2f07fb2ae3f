#include "optim/optimal_element.h"

#include <cmath>

namespace homesh {

OptimalElement optimise_praxis(const FreeNodeDistortion& f, const PraxisOptions& opt) {
  const auto walled = [&f](const Eigen::VectorXd& x) {
    const double value = f(x);
    return std::isfinite(value) ? value : kInvalidDistortion;
  };
  const PraxisResult r = praxis(walled, f.start(), opt);
  OptimalElement best;
  best.nodes = f.element(r.x);
  best.f0 = f(f.start());
  best.f = f(r.x);
  best.evaluations = r.evaluations;
  best.history = r.history;
  return best;
}

OptimalElement optimise_grid(const FreeNodeDistortion& f, const Eigen::VectorXd& lo,
                             const Eigen::VectorXd& hi, const GridSearchOptions& opt) {
  const GridSearchResult r =
      grid_search([&f](const Eigen::VectorXd& x) { return f(x); }, lo, hi, opt);
  OptimalElement best;
  best.nodes = f.element(r.x);
  best.f0 = f(f.start());
  best.f = r.value;
  best.evaluations = r.evaluations;
  return best;
}

}  // namespace homesh
