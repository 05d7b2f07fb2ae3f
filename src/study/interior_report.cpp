#include "study/interior_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "optim/ideal_element.h"
#include "optim/interior_optimum.h"
#include "optim/rank_correlation.h"
#include "optim/thesis_tables.h"

namespace homesh {
namespace {

constexpr int kLandscapePoints = 81;  // per axis, over [0, 1] x [-1/2, 1/2]

std::string landscape(const OptimisationCase& c) {
  std::string csv = "measure,x,y,f\n";
  for (const char* name : {"Q2", "Q8"}) {
    const FreeNodeDistortion f(measure(name), c.start, c.order, c.free_nodes);
    for (int i = 0; i < kLandscapePoints; ++i) {
      for (int j = 0; j < kLandscapePoints; ++j) {
        const Eigen::Vector2d x(i / (kLandscapePoints - 1.0), -0.5 + j / (kLandscapePoints - 1.0));
        csv += fmt::format("{},{},{},{}\n", name, number(x[0]), number(x[1]), number(f(x)));
      }
    }
  }
  return csv;
}

}  // namespace

std::string report_interior(const StudyInputs& in, const StudyOutput& out) {
  const ThesisTable thesis =
      read_thesis_table(in.reference + "/table_3_3_3_5_praxis_iterations.csv");
  const OptimisationCase cases[] = {quadratic_interior_case(), cubic_interior_case()};
  const char* thesis_columns[] = {"quadratic_interior_N", "cubic_interior_N"};
  std::string csv =
      "case,measure,start_x,start_y,ideal_x,ideal_y,thesis_N,praxis_N,f0,praxis_f,praxis_error,"
      "grid_evaluations,grid_f,grid_error\n";
  std::string histories = "case,measure,evaluation,f\n";
  std::string md = fmt::format(
      "## Optimal interior elements (Section 3.8.2, Tables 3.3-3.5)\n\n"
      "PRAXIS (NLopt LN_PRAXIS, t0 = 1e-5, h0 = 0.1) from the deformed element, f = Eq 3.48 "
      "(r = 2, Q / Qmax for Q1-Q5, Q17, Gauss rule of degree 6), verified by brute force (grid "
      "of 101 x 101 over the element's bounding box grown by 1/2, three zoom-ins). "
      "Cases: {}; {}. error = distance of the free node from its position in the equilateral "
      "element. N counts objective evaluations; NLopt's PRAXIS (a C translation with its own "
      "line searches and stopping test) does not count as the thesis's Fortran PRAXIS, so "
      "compare orders of magnitude and rankings, not values.\n\n"
      "| measure | quadratic N thesis | ours | f0 | PRAXIS error | grid error "
      "| cubic N thesis | ours | f0 | PRAXIS error | grid error |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n",
      cases[0].description, cases[1].description);
  double worst_error = 0;
  std::vector<std::vector<double>> thesis_n(2), our_n(2);
  std::vector<std::string> rows(measures().size());
  for (int ci = 0; ci < 2; ++ci) {
    for (size_t mi = 0; mi < measures().size(); ++mi) {
      const Measure& m = measures()[mi];
      const InteriorOptimum r = find_interior_optimum(m, cases[ci]);
      const std::string n =
          thesis.has(m.name, thesis_columns[ci]) ? thesis.at(m.name, thesis_columns[ci]) : "";
      worst_error = std::max({worst_error, r.praxis_error, r.grid_error});
      if (!n.empty()) {
        thesis_n[ci].push_back(std::stod(n));
        our_n[ci].push_back(r.praxis.evaluations);
      }
      const Eigen::Vector2d start = cases[ci].start.col(cases[ci].free_nodes.front());
      const Eigen::Vector2d ideal =
          equilateral_element(cases[ci].order).col(cases[ci].free_nodes.front());
      csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", cases[ci].name, m.name,
                         number(start[0]), number(start[1]), number(ideal[0]), number(ideal[1]), n,
                         r.praxis.evaluations, number(r.praxis.f0), number(r.praxis.f),
                         number(r.praxis_error), r.grid.evaluations, number(r.grid.f),
                         number(r.grid_error));
      for (size_t k = 0; k < r.praxis.history.size(); ++k) {
        histories += fmt::format("{},{},{},{}\n", cases[ci].name, m.name, k + 1,
                                 number(r.praxis.history[k]));
      }
      if (ci == 0) rows[mi] = "| " + m.name + " ";
      rows[mi] += fmt::format("| {} | {} | {:.3g} | {:.1e} | {:.1e} ", n.empty() ? "-" : n,
                              r.praxis.evaluations, r.praxis.f0, r.praxis_error, r.grid_error);
    }
  }
  for (const std::string& row : rows) md += row + "|\n";
  out.write("interior_optimum.csv", csv);
  out.write("praxis_histories.csv", histories);
  out.write("interior_landscape.csv", landscape(cases[0]));
  const auto rho = [](const std::vector<double>& a, const std::vector<double>& b) {
    return spearman(Eigen::Map<const Eigen::VectorXd>(a.data(), a.size()),
                    Eigen::Map<const Eigen::VectorXd>(b.data(), b.size()));
  };
  return md +
         fmt::format(
             "\nEvery measure reaches the equilateral element: largest distance of the "
             "free node from it, PRAXIS or grid, **{:.1e}**. Rank correlation (Spearman) "
             "of our N with the thesis's: quadratic {:.2f} ({} measures), cubic {:.2f} "
             "({} measures). Convergence histories: `praxis_histories.csv`, "
             "`praxis_histories.png`; Fig 3.27(d), (f) analogue: `interior_landscape.png`.\n\n",
             worst_error, rho(thesis_n[0], our_n[0]), thesis_n[0].size(),
             rho(thesis_n[1], our_n[1]), thesis_n[1].size());
}

}  // namespace homesh
