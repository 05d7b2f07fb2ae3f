#include "gmsh/cad_curves.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>

namespace homesh::gmsh_adapter {

CadCurves::CadCurves(const Mesh& m) {
  for (int tag : m.line_entity) {
    if (curves_.count(tag)) continue;
    std::string type;
    gmsh::model::getType(1, tag, type);
    if (type.rfind("Discrete", 0) == 0) continue;
    std::vector<double> lo, hi, ends, mid;
    gmsh::model::getParametrizationBounds(1, tag, lo, hi);
    CurveRange r;
    r.a = lo[0];
    r.b = hi[0];
    gmsh::model::getValue(1, tag, {r.a, r.b}, ends);
    gmsh::model::getValue(1, tag, {0.5 * (r.a + r.b)}, mid);
    const double size = std::hypot(mid[0] - ends[0], mid[1] - ends[1]);
    r.closed = std::hypot(ends[3] - ends[0], ends[4] - ends[1]) <= 1e-9 * std::max(size, 1e-300);
    curves_[tag] = r;
  }
}

bool CadCurves::slides(int tag) const { return curves_.count(tag) > 0; }

CurveRange CadCurves::range(int tag) const { return curves_.at(tag); }

Eigen::Vector2d CadCurves::point(int tag, double u, Eigen::Vector2d* tangent) const {
  std::lock_guard<std::mutex> guard(lock_);
  gmsh::model::getValue(1, tag, {u}, buffer_);
  const Eigen::Vector2d x(buffer_[0], buffer_[1]);
  if (tangent) {
    gmsh::model::getDerivative(1, tag, {u}, buffer_);
    *tangent = Eigen::Vector2d(buffer_[0], buffer_[1]);
  }
  return x;
}

double CadCurves::parameter(int tag, const Eigen::Vector2d& x) const {
  std::lock_guard<std::mutex> guard(lock_);
  gmsh::model::getParametrization(1, tag, {x(0), x(1), 0.0}, buffer_);
  return buffer_[0];
}

}  // namespace homesh::gmsh_adapter
