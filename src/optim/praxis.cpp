#include "optim/praxis.h"

#include <nlopt.hpp>

#include "core/error.h"

namespace homesh {

PraxisResult praxis(const std::function<double(const Eigen::VectorXd&)>& f,
                    const Eigen::VectorXd& x0, const PraxisOptions& opt) {
  const auto n = static_cast<unsigned>(x0.size());
  nlopt::srand(opt.seed);
  nlopt::opt solver(nlopt::LN_PRAXIS, n);
  PraxisResult r;
  struct Data {
    const std::function<double(const Eigen::VectorXd&)>* f;
    PraxisResult* result;
  } data{&f, &r};
  solver.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void* d) {
        auto* data = static_cast<Data*>(d);
        const double value = (*data->f)(Eigen::Map<const Eigen::VectorXd>(x.data(), x.size()));
        ++data->result->evaluations;
        data->result->history.push_back(value);
        return value;
      },
      &data);
  solver.set_xtol_abs(opt.t0);
  solver.set_initial_step(opt.h0);
  solver.set_maxeval(opt.max_evaluations);
  std::vector<double> x(x0.data(), x0.data() + n);
  double value = 0;
  try {
    solver.optimize(x, value);
  } catch (const std::exception& e) {
    throw Error(std::string("PRAXIS failed: ") + e.what());
  }
  r.x = Eigen::Map<Eigen::VectorXd>(x.data(), n);
  r.value = value;
  return r;
}

}  // namespace homesh
