#include "curving/curve_mesh.h"

#include <algorithm>
#include <chrono>

#include "core/heap_prefault.h"
#include "core/raise_order.h"
#include "curving/interior_blending.h"
#include "curving/wall_propagation.h"
#include "curving/wall_turn.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

constexpr double kPassGain = 0.02;  // least lift of the worst minJ/maxJ worth another pass

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

CurveResult curve_mesh(const Mesh& m, const std::function<Eigen::Matrix2Xd(Mesh& raised)>& place,
                       const CurveOptions& opt, const CurveEvaluator* curves) {
  const auto start = std::chrono::steady_clock::now();
  // Its fresh memory faulted in by another core meanwhile (core/heap_prefault.h): about
  // 256 bytes per element and p^2, what the corpus's p = 2-5 runs first touch (0.013-0.074
  // pages each). Fresh processes, medians of 6, without / with: circles6_nolayer p = 5
  // 92 / 71 ms, circle_voronoi p = 4 21 / 17 ms, star1_bl_1e-3 p = 5 157 / 136 ms,
  // 15 runs 652 / 572 ms; 512 bytes gained no more, 1024 lost.
  const HeapPrefault prefault(std::min<std::size_t>(
      std::size_t(256) * m.num_elements_2d() * opt.order * opt.order, std::size_t(48) << 20));
  CurveResult r;
  // The optimiser's threshold: coarse_threshold where the linear wall is coarse for its
  // curvature, if that is lower.
  OptimiseOptions optimiser = opt.optimiser;
  r.wall_turn = largest_wall_turn(m, curves, opt.boundary.corner_degrees);
  if (r.wall_turn >= opt.coarse_turn)
    optimiser.threshold = std::min(optimiser.threshold, opt.coarse_threshold);
  r.threshold = optimiser.threshold;
  Mesh raised = raise_order(m, opt.order);
  Eigen::Matrix2Xd target = place(raised);
  const std::vector<bool> boundary = boundary_nodes(raised);
  r.place_seconds = since(start);
  std::vector<int> local_region;  // step 1's poor elements and their rings
  Mesh placed;                    // step 1's best guess, if step 1 ran
  MeshValidity placed_validity;   // its certified validity (by opt.optimiser.bounds)
  const std::vector<bool> vertex = vertex_nodes(raised);
  std::vector<bool> held = boundary;
  if (opt.fixed_vertices) {
    for (int i = 0; i < raised.num_nodes(); ++i)
      if (vertex[i] && !held[i]) {
        held[i] = true;
        target.col(i) = raised.x.col(i);
      }
  }
  // The elastic solve on `region` (2D elements) only: every node but those inside it (on
  // none of the elements outside) prescribed at step 1's guess, solved from the straight
  // mesh to it.
  auto solve_round = [&](const std::vector<int>& region) {
    std::vector<bool> outside(raised.num_nodes(), false);
    std::vector<bool> in_region(raised.num_elements_2d(), false);
    for (int e : region) in_region[e] = true;
    for (int e = 0; e < raised.num_elements_2d(); ++e)
      if (!in_region[e])
        for (const int n : element_node_indices(raised, e)) outside[n] = true;
    std::vector<bool> prescribed = held;
    for (int i = 0; i < raised.num_nodes(); ++i) prescribed[i] = prescribed[i] || outside[i];
    DeformOptions around = opt.deform;
    around.region = region;
    return deform_mesh(raised, placed.x, prescribed, around, {&placed, &placed_validity});
  };
  const bool rings = opt.placed_rings > 0 && opt.order >= opt.placed_rings_from_order;
  auto poor_region = [&](const MeshValidity& v, double bar) {
    std::vector<bool> poor_nodes(placed.num_nodes(), false);
    for (int e = 0; e < placed.num_elements_2d(); ++e)
      if (v.ratio(e) < bar)
        for (const int n : element_node_indices(placed, e)) poor_nodes[n] = true;
    return moving_region(placed, poor_nodes, opt.placed_rings);
  };
  // The polish's bar: `polish`, or where more than polish_share of the elements are below
  // it, the ratio below which the polish_share worst lie (polish_worst), else none (0).
  auto polish_bar = [&](const MeshValidity& v) {
    const int n = placed.num_elements_2d();
    int below = 0;
    for (int e = 0; e < n; ++e) below += v.ratio(e) < opt.polish;
    if (below <= opt.polish_share * n) return opt.polish;
    if (!opt.polish_worst) return 0.0;
    // The polish_share worst: below the ratio of the element at that rank.
    std::vector<double> ratios(v.ratio.data(), v.ratio.data() + n);
    const auto k = ratios.begin() + static_cast<std::ptrdiff_t>(opt.polish_share * n);
    std::nth_element(ratios.begin(), k, ratios.end());
    return *k > v.worst ? *k : 0.0;  // none below it: no polish
  };

  // 1. Placed: the boundary nodes at their targets, the interior blended from the wall
  // elements' edges, or else moved with the wall near it; the better guess is kept.
  if (opt.accept_placed <= 1) {
    const auto guessing = std::chrono::steady_clock::now();
    // One mesh holds the guesses in turn (they differ in their nodes only): the blended
    // guess, then the propagated one's nodes swapped in; the better is kept.
    placed = raised;
    for (int i = 0; i < placed.num_nodes(); ++i)
      if (boundary[i]) placed.x.col(i) = target.col(i);
    Eigen::Matrix2Xd other;  // the propagated guess's nodes
    if (opt.propagate > 0) {
      // From the straight interior: propagation moves every free node near the wall.
      std::vector<bool> free(raised.num_nodes());
      for (int i = 0; i < raised.num_nodes(); ++i)
        free[i] = !boundary[i] && !(opt.fixed_vertices && vertex[i]);
      other = placed.x + propagate_wall_displacement(raised, target, free, opt.propagate);
    }
    if (opt.blend) blend_interiors(placed, boundary);
    placed_validity = mesh_validity(placed, opt.optimiser.bounds);
    r.guess = opt.blend ? "blended" : "straight";
    const auto good = [&](const MeshValidity& w) {
      return w.invalid == 0 && w.worst >= opt.accept_placed;
    };
    if (opt.propagate > 0 && !good(placed_validity)) {
      placed.x.swap(other);
      MeshValidity w = mesh_validity(placed, opt.optimiser.bounds);
      if (certified_better(w.invalid, w.worst, placed_validity.invalid, placed_validity.worst)) {
        placed_validity = std::move(w);
        r.guess = "propagated";
      } else {
        placed.x.swap(other);
      }
    }
    const MeshValidity& v = placed_validity;
    r.placed_worst = v.invalid == 0 ? v.worst : 0;
    r.guess_seconds = since(guessing);
    if (v.invalid == 0 && v.worst >= opt.accept_placed) {
      r.placed = true;
      r.worst_ratio = v.worst;
      // Good enough, not yet `polish`: a solve round the elements below it, kept if better.
      const double bar = opt.placed_rings > 0 && v.worst < opt.polish ? polish_bar(v) : 0.0;
      if (bar > 0) {
        const auto t = std::chrono::steady_clock::now();
        DeformResult d = solve_round(poor_region(v, bar));
        r.elastic_seconds = since(t);
        if (d.complete && d.worst_ratio > v.worst) {
          r.placed = false;
          r.polished = true;
          r.polish_bar = bar;
          r.worst_ratio = d.worst_ratio;
          r.deform = std::move(d);
          r.mesh = std::move(r.deform.mesh);
          r.validity = r.deform.validity;
          r.seconds = since(start);
          return r;
        }
      }
      r.mesh = std::move(placed);
      r.validity = std::move(placed_validity);
      r.seconds = since(start);
      return r;
    }
    // Poor or invalid somewhere: step 2 first solves only round those elements.
    if (rings) local_region = poor_region(v, opt.accept_placed);
  }

  // 2. Elastic.
  const auto elastic = std::chrono::steady_clock::now();
  bool local = false;
  if (!local_region.empty()) {
    r.deform = solve_round(local_region);
    local = r.deform.complete && r.deform.worst_ratio >= opt.accept_local;
    // Kept at accept_placed or better, but below `polish`: solved again round its elements
    // below that, from it (a poorer result is left to the optimiser).
    if (local && r.deform.worst_ratio >= opt.accept_placed && r.deform.worst_ratio < opt.polish) {
      placed_validity =
          mesh_validity(r.deform.mesh, {&r.deform.mesh, &r.deform.validity}, opt.optimiser.bounds);
      placed = r.deform.mesh;
      if (const double bar = polish_bar(placed_validity); bar > 0) {
        DeformResult d = solve_round(poor_region(placed_validity, bar));
        if (d.complete && d.worst_ratio > r.deform.worst_ratio) {
          d.solved_triangles += r.deform.solved_triangles;
          d.solves += r.deform.solves;
          r.deform = std::move(d);
          r.polished = true;
          r.polish_bar = bar;
        }
      }
    }
  }
  if (!local) r.deform = deform_mesh(raised, target, held, opt.deform);
  const bool restricted = opt.fixed_vertices || opt.deform.reach > 0 || opt.deform.layers > 0;
  if (!r.deform.complete && restricted) {
    r.fell_back = true;
    r.restricted_reached = r.deform.reached;
    // First the vertices freed within the same region (flap_gap02_bl_1e-4 p = 4: the held
    // solve reaches 62 % of the motion; the whole mesh with 7771 triangles took 9 s).
    if (opt.fixed_vertices && (opt.deform.reach > 0 || opt.deform.layers > 0))
      r.deform = deform_mesh(raised, target, boundary, opt.deform);
  }
  if (!r.deform.complete && restricted) {
    r.fell_back_whole = true;
    DeformOptions whole = opt.deform;
    whole.reach = 0;
    whole.layers = 0;
    whole.region.clear();
    r.deform = deform_mesh(raised, target, boundary, whole);
  }
  r.elastic_seconds = since(elastic);
  // Complete means valid with every boundary node at its target: a solve posed on no
  // element (an all-quadrilateral mesh to a triangle-only solve) reported complete with
  // none moved, and one posed on a region can break elements outside it.
  const double scale = (raised.x.rowwise().maxCoeff() - raised.x.rowwise().minCoeff()).norm();
  auto sound = [&](const DeformResult& d) {
    if (!d.complete || !(d.worst_ratio > 0)) return false;
    for (int i = 0; i < raised.num_nodes(); ++i)
      if (boundary[i] && (d.mesh.x.col(i) - target.col(i)).norm() > 1e-12 * scale) return false;
    return true;
  };
  r.deform.complete = sound(r.deform);
  // Step 1's valid guess, where it beats the solve: in place of a solve that fell short,
  // else a second start for step 3, the better result kept. Neither start wins everywhere
  // on issue 16's corpus (optimised from the guess / from the solve: naca0012_bl_1e-4 p = 3
  // 0.951 / 0.842, plate_holes_layers_1e-3 p = 3 0.808 / 0.931).
  DeformResult guess_start;
  if (r.placed_worst > 0 && !(r.deform.complete && r.deform.worst_ratio >= r.placed_worst)) {
    // The solve's statistics with the guess's mesh and validity (the solve's mesh and
    // validity set aside meanwhile, not copied).
    Mesh solved = std::move(r.deform.mesh);
    MeshValidity solved_validity = std::move(r.deform.validity);
    guess_start = r.deform;
    r.deform.mesh = std::move(solved);
    r.deform.validity = std::move(solved_validity);
    guess_start.mesh = std::move(placed);
    guess_start.complete = true;
    guess_start.reached = 1;
    guess_start.worst_ratio = r.placed_worst;
    guess_start.validity = std::move(placed_validity);
  }
  if (!r.deform.complete && guess_start.complete) {
    r.deform = std::move(guess_start);
    guess_start.complete = false;
    r.guess_over_solve = true;
  }
  r.worst_ratio = r.deform.worst_ratio;
  if (!(opt.optimise && r.deform.complete && r.deform.worst_ratio < optimiser.threshold)) {
    if (guess_start.complete) {  // better than the solve, and no optimisation to come
      r.deform = std::move(guess_start);
      r.worst_ratio = r.deform.worst_ratio;
      r.guess_over_solve = true;
    }
    r.mesh = std::move(r.deform.mesh);
    r.validity = std::move(r.deform.validity);
    r.seconds = since(start);
    return r;
  }

  // 3. Optimised, where the elastic result is valid and leaves poor elements (triangles and
  // quadrilaterals: a linear mesh's poor quads are lifted by moving the vertices too).
  const std::vector<bool> none(raised.num_nodes(), false);
  // Passes of the optimiser from the current solve, each from where the last stopped, while
  // elements stay below the threshold and a pass still lifts the worst by kPassGain.
  auto optimise = [&] {
    const auto t = std::chrono::steady_clock::now();
    // An empty validity (no increment accepted) is bounded afresh by the optimiser.
    OptimiseResult o = optimise_mesh(r.deform.mesh, none, optimiser, curves, &r.deform.validity);
    for (int pass = 1; pass < opt.optimise_passes && o.worst_after < optimiser.threshold; ++pass) {
      OptimiseResult next = optimise_mesh(o.mesh, none, optimiser, curves, &o.validity);
      const bool gained = next.worst_after > o.worst_after + kPassGain;
      next.worst_before = o.worst_before;
      next.poor_before = o.poor_before;
      next.patches += o.patches;
      next.accepted += o.accepted;
      next.sweeps += o.sweeps;
      o = std::move(next);
      if (!gained) break;
    }
    r.optimise_seconds += since(t);
    return o;
  };
  r.optimised = true;
  r.optimisation = optimise();
  // Still poor from a solve with the vertices held: solved again with them free and
  // optimised from there, the better kept. Neither start wins everywhere
  // (ellipse10_bl_1e-4 p = 2 / 3: 0.78 / 0.61 from the held solve, 0.85 / 0.70 from the
  // free one; naca0012_voronoi p = 4: 0.975 from the held one, 0.84 from the free one).
  if (r.optimisation.worst_after < optimiser.threshold && opt.fixed_vertices && !r.fell_back) {
    const auto t = std::chrono::steady_clock::now();
    DeformResult freed = deform_mesh(raised, target, boundary, opt.deform);
    r.elastic_seconds += since(t);
    if (sound(freed)) {
      DeformResult held_result = std::move(r.deform);
      r.deform = std::move(freed);
      OptimiseResult o = optimise();
      if (o.worst_after > r.optimisation.worst_after) {
        r.optimisation = std::move(o);
        r.freed_vertices = true;
      } else {
        r.deform = std::move(held_result);
      }
    }
  }
  // The guess beat the solve: optimised from it too, if what the solve gave is still poor
  // or below the guess itself.
  if (guess_start.complete && (r.optimisation.worst_after < optimiser.threshold ||
                               guess_start.worst_ratio > r.optimisation.worst_after)) {
    std::swap(r.deform, guess_start);
    OptimiseResult o = optimise();
    if (o.worst_after > r.optimisation.worst_after) {
      r.optimisation = std::move(o);
      r.guess_over_solve = true;
      r.freed_vertices = false;
    } else {
      std::swap(r.deform, guess_start);
    }
  }
  r.mesh = std::move(r.optimisation.mesh);
  r.validity = r.optimisation.validity;
  r.worst_ratio = r.optimisation.worst_after;
  r.seconds = since(start);
  return r;
}

}  // namespace homesh
