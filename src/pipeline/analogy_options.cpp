#include "pipeline/analogy_options.h"

#include "core/error.h"
#include "fem/preconditioner.h"

namespace homesh {
namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : " | ") + n;
  return out;
}

}  // namespace

std::vector<OptionSpec> analogy_option_specs(const std::string& default_formulation,
                                             const std::string& default_nu) {
  return {{"formulation", default_formulation, analogy_formulation_names()},
          {"nu", default_nu, "Poisson's ratio, in (-1, 0.5)"},
          {"heat", "1", "scale of the added force/heat terms (> 0 expands hot elements)"},
          {"power", "1",
           "exponent of the stiffening formulations: stiff_q17 E = (min Q17/max Q17)^-power "
           "(thesis: 1); benchmarked: stiff_shape 2, stiff_shear 3"},
          {"solver", "cholmod", "linear solver: " + joined(linear_solver_names())},
          {"preconditioner", "ichol", "CG preconditioner: " + joined(preconditioner_names())}};
}

AnalogyChoice read_analogy_options(const Options& opt, const std::string& stage) {
  AnalogyChoice c;
  c.formulation = analogy_formulation(opt.get_string("formulation")).name;
  c.params.poisson = opt.get_double("nu");
  if (!(c.params.poisson > -1 && c.params.poisson < 0.5))
    throw Error("stage '" + stage + "': option nu must be in (-1, 0.5)");
  c.params.heat = opt.get_double("heat");
  c.params.power = opt.get_double("power");
  if (!(c.params.power > 0)) throw Error("stage '" + stage + "': option power must be > 0");
  c.solver.method = opt.get_string("solver");
  c.solver.preconditioner = opt.get_string("preconditioner");
  return c;
}

}  // namespace homesh
