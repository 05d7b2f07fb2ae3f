#pragma once
// Brent's principal-axis method (PRAXIS) through NLopt (NLOPT_LN_PRAXIS), as
// the thesis uses it for optimal-element searches (Section 3.8.1: t0 = 1e-5,
// h0 = 0.1).
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace homesh {

struct PraxisOptions {
  double t0 = 1e-5;  ///< tolerance: stop when x changes by less than this (xtol_abs)
  double h0 = 0.1;   ///< initial step (NLopt's initial step size)
  int max_evaluations = 100000;
  /// Seed of NLopt's random numbers (PRAXIS draws random search directions
  /// when it stalls): a fixed seed makes every run reproducible.
  unsigned long seed = 1;
};

struct PraxisResult {
  Eigen::VectorXd x;
  double value = 0;
  int evaluations = 0;  ///< objective evaluations (the thesis' iteration count N)
  /// The objective at every evaluation, in order (a convergence history).
  std::vector<double> history;
};

/// Minimises f from x0. Throws homesh::Error if NLopt fails.
PraxisResult praxis(const std::function<double(const Eigen::VectorXd&)>& f,
                    const Eigen::VectorXd& x0, const PraxisOptions& opt = {});

}  // namespace homesh
