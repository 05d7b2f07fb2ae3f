#pragma once
// The CAD curves of the current Gmsh model as a CurveEvaluator
// (curving/curve_evaluator.h), for the optimiser's boundary nodes sliding
// along their curve. Curve ranges are read once, at construction; points,
// tangents and parameters are Gmsh's (getValue, getDerivative,
// getParametrization), one call at a time under a lock (Gmsh's model is not
// documented as safe for concurrent calls).
#include <map>
#include <mutex>
#include <vector>

#include "core/mesh.h"
#include "curving/curve_evaluator.h"

namespace homesh::gmsh_adapter {

class CadCurves : public CurveEvaluator {
 public:
  /// The curves the lines of m lie on; discrete curves (no parametrisation)
  /// do not slide.
  explicit CadCurves(const Mesh& m);
  bool slides(int tag) const override;
  CurveRange range(int tag) const override;
  Eigen::Vector2d point(int tag, double u, Eigen::Vector2d* tangent = nullptr) const override;
  double parameter(int tag, const Eigen::Vector2d& x) const override;

 private:
  std::map<int, CurveRange> curves_;  // the CAD curves only
  mutable std::mutex lock_;
  mutable std::vector<double> buffer_;
};

}  // namespace homesh::gmsh_adapter
