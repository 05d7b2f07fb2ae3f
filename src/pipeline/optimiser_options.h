#pragma once
// The optimiser's options the optimise and curve stages share, declared once;
// defaults are those of the OptimiseOptions each stage fills.
#include <functional>

#include "curving/optimise_mesh.h"
#include "pipeline/option_table.h"

namespace homesh {

/// Adds threshold, sweeps, newton, newton_tol, until, lattice, patch_first and slide to `table`,
/// read into the OptimiseOptions that `optimiser` gives (a pointer to a data member of T or a
/// callable T& -> OptimiseOptions&).
template <class T, class Optimiser>
void add_optimiser_options(OptionTable<T>& table, Optimiser optimiser) {
  const std::function<OptimiseOptions&(T&)> o = optimiser;
  table.add(
      "threshold", [o](T& t) -> double& { return o(t).threshold; }, real(0, 1, "(]"),
      "elements whose certified minJ/maxJ is below this are optimised");
  table.add(
      "sweeps", [o](T& t) -> int& { return o(t).max_sweeps; }, integer(0, 10000),
      "most node-by-node Newton sweeps per patch");
  table.add(
      "newton", [o](T& t) -> int& { return o(t).newton_iterations; }, integer(0, 10000),
      "most whole-patch Newton steps per patch, before the sweeps (0: sweeps only)");
  table.add(
      "newton_tol", [o](T& t) -> double& { return o(t).newton_tolerance; }, real(0),
      "a Newton step whose predicted decrease is below this fraction of the patch energy ends "
      "the steps");
  table.add(
      "until", [o](T& t) -> OptimiseOptions::Until& { return o(t).until; },
      choice<OptimiseOptions::Until>({{"rest", OptimiseOptions::Until::rest},
                                      {"converged", OptimiseOptions::Until::converged}}),
      "a patch's Newton steps end at newton_tol, or (rest) once its moved elements all reach "
      "the worst of the mesh outside the patches");
  table.add(
      "lattice", [o](T& t) -> double& { return o(t).lattice_weight; }, real(0, 1, "[)"),
      "share of the energy's weight on the order 2(p-1) lattice (corners and edges)");
  table.add(
      "patch_first", [o](T& t) -> int& { return o(t).first_layers; }, integer(0, 100),
      "first optimise patches of this many rings only, then the elements still below the "
      "threshold with patches of the full rings (0: the full rings at once)");
  table.add(
      "slide", [o](T& t) -> OptimiseOptions::Slide& { return o(t).slide; },
      choice<OptimiseOptions::Slide>({{"all", OptimiseOptions::Slide::all},
                                      {"nodes", OptimiseOptions::Slide::edge_nodes},
                                      {"none", OptimiseOptions::Slide::none}}),
      "boundary nodes sliding along their CAD curve: all (vertices too) | nodes (the nodes the "
      "order raising added) | none (held); without CAD every boundary node is held");
}

}  // namespace homesh
