#pragma once
// The options every stage driven by the elastic analogy shares (curve, rotate,
// layers): formulation, Poisson's ratio, added-term scale, stiffening power and
// linear solver, declared once. Their defaults are those of the library struct
// each stage fills (DeformOptions, RotateOptions, RoomOptions).
#include <functional>
#include <string>
#include <utility>

#include "curving/analogy_formulation.h"
#include "fem/linear_solver.h"
#include "fem/preconditioner.h"
#include "pipeline/option_table.h"

namespace homesh {

/// Names of the analogy's formulations, linear solvers, CG preconditioners.
std::vector<std::string> formulation_names();

/// Adds formulation, nu, heat, power, solver and preconditioner to `table`,
/// read into the members `formulation`, `params` and `solver` give (pointers
/// to data members of T or callables T& -> member&).
template <class T, class Formulation, class Params, class Solver>
void add_analogy_options(OptionTable<T>& table, Formulation formulation, Params params,
                         Solver solver) {
  const std::function<FormulationParams&(T&)> p = params;
  const std::function<LinearSolverOptions&(T&)> s = solver;
  table.add("formulation", formulation, one_of(formulation_names()), analogy_formulation_names());
  table.add(
      "nu", [p](T& o) -> double& { return p(o).poisson; }, real(-1, 0.5, "()"),
      "Poisson's ratio, in (-1, 0.5)");
  table.add(
      "heat", [p](T& o) -> double& { return p(o).heat; }, real(),
      "scale of the added force/heat terms (> 0 expands hot elements)");
  table.add(
      "power", [p](T& o) -> double& { return p(o).power; }, real(0, INFINITY, "(]"),
      "exponent of the stiffening formulations: stiff_q17 E = (min Q17/max Q17)^-power "
      "(thesis: 1); benchmarked: stiff_shape 2, stiff_shear 3");
  table.add(
      "solver", [s](T& o) -> std::string& { return s(o).method; }, one_of(linear_solver_names()),
      "linear solver: " + names_text(linear_solver_names()));
  table.add(
      "preconditioner", [s](T& o) -> std::string& { return s(o).preconditioner; },
      one_of(preconditioner_names()), "CG preconditioner: " + names_text(preconditioner_names()));
}

}  // namespace homesh
