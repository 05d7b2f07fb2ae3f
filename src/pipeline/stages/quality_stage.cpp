#include "pipeline/stages/quality_stage.h"

#include <omp.h>

#include <chrono>
#include <ctime>
#include <utility>

#include "core/error.h"
#include "pipeline/quality_report.h"
#include "quality/mesh_quality.h"

namespace homesh {
namespace {

void run(Context& ctx, const Options& opt) {
  const Mesh& m = ctx.require_mesh("quality");
  const std::string reference = opt.get_string("reference");
  if (reference != "element_max" && reference != "ideal")
    throw Error("stage 'quality': option reference=" + reference +
                ": expected element_max or ideal");
  const Reference ref = reference == "ideal" ? Reference::ideal : Reference::element_max;
  const int lattice = opt.get_int("lattice", 0, 60);
  const int worst = opt.get_int("worst", 0, 1000);
  const int threads = opt.get_int("threads", 0, 1024);
  BoundsOptions bounds;
  bounds.relative_tolerance = opt.get_double("tolerance");
  if (!(bounds.relative_tolerance > 0 && bounds.relative_tolerance < 1))
    throw Error("stage 'quality': option tolerance must be in (0, 1)");
  std::vector<const Measure*> chosen;
  for (const auto& name : opt.get_list("measures")) chosen.push_back(&measure(name));

  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const int used = threads > 0 ? threads : omp_get_num_procs();
  MeshQuality quality = mesh_quality(
      m, chosen, lattice > 0 ? lattice : default_lattice_order(m.order), ref, bounds, used);
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const MeshValidity& v = quality.validity;
  ctx.set_field({"minJ/maxJ", Field::Kind::Element, v.ratio.transpose()});
  ctx.results = {{"triangles", m.num_triangles()},
                 {"invalid", v.invalid},
                 {"worst_minJ_maxJ", v.worst},
                 {"worst_triangle", v.worst_element + 1}};
  std::vector<std::string> histograms = {histogram_line("minJ/maxJ", v.ratio)};
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    const std::string& name = chosen[j]->name;
    MeshMeasure& r = quality.measures[j];
    histograms.push_back(histogram_line(name, r.element_min));
    ctx.results[name + "_min"] = r.element_min.minCoeff();
    ctx.results[name + "_mean"] = r.element_min.mean();
    ctx.set_field({name + " min", Field::Kind::Element, r.element_min.transpose()});
    ctx.set_field({name, Field::Kind::ElementNode, std::move(r.node_values)});
  }
  const auto t2 = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };

  ctx.log.info(
      "quality: {} triangles of order {} (bounds and measures {:.3f} s, {:.3f} s CPU on {} "
      "thread(s); views {:.3f} s)",
      m.num_triangles(), m.order, seconds(t0, t1), cpu, used, seconds(t1, t2));
  ctx.log.info("  {}", validity_line(m, v));
  ctx.log.info("  measure per element: minimum, mean, | count in 10 bins over [0, 1] |");
  for (const auto& line : histograms) ctx.log.info("{}", line);
  if (worst > 0)
    ctx.log.info("  worst elements by minJ/maxJ:\n{}", worst_elements(m, v.ratio, worst));
}

}  // namespace

Stage quality_stage() {
  return {"quality",
          "certified validity (minJ/maxJ) and quality measures: views and a report",
          {{"measures", "Q4,Q17,Q11", "measures to add (Q1..Q17, see homesh --measures)"},
           {"reference", "element_max",
            "normalise size measures by the element's max (thesis) or by the unit ideal"},
           {"lattice", "0", "order of the sampling lattice for minima (0 = 2p)"},
           {"tolerance", "1e-3", "relative tolerance of the certified Jacobian bounds"},
           {"worst", "5", "number of worst elements to list"},
           {"threads", "0", "threads for bounds and measures (0 = one per core)"}},
          run};
}

}  // namespace homesh
