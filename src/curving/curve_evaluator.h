#pragma once
// The model's curves as the high-order optimiser (curving/optimise_mesh.h)
// sees them: a point and a tangent of curve `tag` at parameter u. The
// optimiser slides boundary nodes along their curve by parameter (Toulorge,
// Geuzaine, Remacle & Lambrechts, JCP 254, 2013, Sec 3.3; Turner, Peiro &
// Moxey, CAD 103, 2018, Sec 5) and stays free of Gmsh: the Gmsh adapter
// (gmsh/cad_curves.h) implements this on the CAD of the current model, tests
// on analytic curves. Implementations must be safe to call from several
// threads at once (the optimiser's patches run in parallel).
#include <Eigen/Core>
#include <cmath>

namespace homesh {

/// Parameter range of a curve; a closed curve is periodic in u with period b - a.
struct CurveRange {
  double a = 0, b = 1;
  bool closed = false;
};

/// u wrapped into [a, b) on a closed curve; u itself on an open one.
inline double wrap_parameter(const CurveRange& r, double u) {
  if (!r.closed) return u;
  const double period = r.b - r.a;
  return r.a + std::fmod(std::fmod(u - r.a, period) + period, period);
}

class CurveEvaluator {
 public:
  virtual ~CurveEvaluator() = default;
  /// Whether nodes classified on curve `tag` may slide along it (a CAD curve
  /// with a parametrisation; false for discrete curves and unknown tags).
  virtual bool slides(int tag) const = 0;
  /// Parameter range of curve `tag` (only asked where slides(tag)).
  virtual CurveRange range(int tag) const = 0;
  /// The point C(u) of curve `tag` and, if `tangent` is given, dC/du there.
  virtual Eigen::Vector2d point(int tag, double u, Eigen::Vector2d* tangent = nullptr) const = 0;
  /// The parameter of the point of curve `tag` nearest x (for nodes whose
  /// classification carries no parameter).
  virtual double parameter(int tag, const Eigen::Vector2d& x) const = 0;
};

}  // namespace homesh
