#pragma once
// The options every stage driven by the elastic analogy shares (curve, rotate,
// layers): formulation, Poisson's ratio, added-term scale, stiffening power and
// linear solver, declared once and read once.
#include <string>
#include <vector>

#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"
#include "pipeline/options.h"

namespace homesh {

/// The option specs, with `formulation` defaulting to `default_formulation`
/// and `nu` to `default_nu`.
std::vector<OptionSpec> analogy_option_specs(const std::string& default_formulation = "plain",
                                             const std::string& default_nu = "0.4");

struct AnalogyChoice {
  std::string formulation;
  FormulationParams params;
  LinearSolverOptions solver;
};

/// Reads and checks the options of analogy_option_specs; homesh::Error names
/// `stage` and the bad option.
AnalogyChoice read_analogy_options(const Options& opt, const std::string& stage);

}  // namespace homesh
