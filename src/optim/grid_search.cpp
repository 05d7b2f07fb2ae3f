#include "optim/grid_search.h"

#include <cmath>
#include <limits>

#include "core/error.h"

namespace homesh {
namespace {

// Visits the n^d points of the grid on [lo, hi], keeping the smallest f.
void search_level(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& lo,
                  const Eigen::VectorXd& hi, int n, GridSearchResult& best) {
  const auto d = lo.size();
  const Eigen::VectorXd h = (hi - lo) / (n - 1);
  Eigen::VectorXi index = Eigen::VectorXi::Zero(d);
  Eigen::VectorXd x(d);
  while (true) {
    x = lo + h.cwiseProduct(index.cast<double>());
    const double value = f(x);
    ++best.evaluations;
    if (value < best.value) {
      best.value = value;
      best.x = x;
    }
    Eigen::Index axis = 0;
    while (axis < d && ++index[axis] == n) index[axis++] = 0;
    if (axis == d) break;
  }
  best.spacing = h.maxCoeff();
}

}  // namespace

GridSearchResult grid_search(const std::function<double(const Eigen::VectorXd&)>& f,
                             const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                             const GridSearchOptions& opt) {
  if (lo.size() == 0 || lo.size() != hi.size() || !(lo.array() < hi.array()).all()) {
    throw Error("grid search needs a box with lo < hi in every coordinate");
  }
  if (opt.points_per_axis < 2 || opt.refinements < 0) {
    throw Error("grid search needs at least 2 points per axis and refinements >= 0");
  }
  GridSearchResult best;
  best.value = std::numeric_limits<double>::infinity();
  best.x = lo;
  Eigen::VectorXd a = lo, b = hi;
  for (int level = 0; level <= opt.refinements; ++level) {
    search_level(f, a, b, opt.points_per_axis, best);
    const Eigen::VectorXd h = (b - a) / (opt.points_per_axis - 1);
    a = best.x - 2.0 * h;
    b = best.x + 2.0 * h;
  }
  return best;
}

}  // namespace homesh
