#include "pipeline/stages/quality_stage.h"

#include <fmt/core.h>
#include <omp.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <ctime>
#include <utility>

#include "pipeline/quality_report.h"
#include "quality/mesh_quality.h"
#include "quality/volume_quality.h"
#include "quality/volume_validity.h"

namespace homesh {
namespace {

// The measure names accepted (case-insensitively, as measure() does).
bool is_measure(const std::string& name) {
  return std::any_of(measures().begin(), measures().end(), [&](const Measure& q) {
    return q.name.size() == name.size() &&
           std::equal(q.name.begin(), q.name.end(), name.begin(),
                      [](char a, char b) { return std::toupper(a) == std::toupper(b); });
  });
}

// Each measure's views (element minimum, node values) and results (its minimum
// and mean over the elements); returns the histogram lines, minJ/maxJ's first.
std::vector<std::string> measure_fields(Context& ctx, const MeshValidity& v,
                                        const std::vector<const Measure*>& chosen,
                                        std::vector<MeshMeasure>& measured) {
  std::vector<std::string> histograms = {histogram_line("minJ/maxJ", v.ratio)};
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    const std::string& name = chosen[j]->name;
    MeshMeasure& r = measured[j];
    histograms.push_back(histogram_line(name, r.element_min));
    ctx.results[name + "_min"] = r.element_min.minCoeff();
    ctx.results[name + "_mean"] = r.element_min.mean();
    ctx.set_field(
        {element_field_name(*chosen[j]), Field::Kind::Element, r.element_min.transpose()});
    ctx.set_field(
        {node_field_name(*chosen[j]), Field::Kind::ElementNode, std::move(r.node_values)});
  }
  return histograms;
}

// A view of the 2D elements whose certified minJ/maxJ is below `threshold`
// (their value on every node), so Gmsh's GUI shows where they are.
void add_poor_elements(Context& ctx, const MeshValidity& v, double threshold) {
  const Mesh& m = *ctx.mesh;
  Field f{fmt::format("homesh: elements of certified minJ/maxJ < {:g}", threshold),
          Field::Kind::ElementNode,
          {}};
  for (int e = 0; e < m.num_elements_2d(); ++e)
    if (v.ratio(e) < threshold) f.elements.push_back(e);
  f.values.resize(m.num_quads() > 0 ? m.quad.rows() : m.tri.rows(),
                  static_cast<Eigen::Index>(f.elements.size()));
  for (std::size_t k = 0; k < f.elements.size(); ++k)
    f.values.col(static_cast<Eigen::Index>(k)).setConstant(v.ratio(f.elements[k]));
  ctx.set_field(std::move(f));
}

// The quality stage on a volume mesh (issue 24): the certified validity of its
// tetrahedra, its view and report. The thesis' measures are planar so far.
void run_volume(Context& ctx, const QualityOptions& o) {
  const VolumeMesh& m = *ctx.volume;
  const auto t0 = std::chrono::steady_clock::now();
  const int used = o.threads > 0 ? o.threads : omp_get_num_procs();
  // The curve stage's certificate is reused for the tetrahedra as it left them
  // (if refined by the same options); the result is kept for the writers.
  const MeshValidity v = ctx.volume_certified
                             ? volume_validity(m, ctx.volume_certified->mesh,
                                               ctx.volume_certified->validity, o.bounds, used)
                             : volume_validity(m, o.bounds, used);
  ctx.certify_volume(v);
  std::vector<const Measure*> chosen;
  for (const auto& name : o.measures) chosen.push_back(&measure(name));
  std::vector<MeshMeasure> measured = volume_quality(
      m, chosen, o.lattice > 0 ? o.lattice : default_lattice_order(m.order), o.reference, used);
  const auto t1 = std::chrono::steady_clock::now();
  ctx.set_field({kValidityFieldName, Field::Kind::Element, v.ratio.transpose(), true, true});
  const int worst_tag =
      v.worst_element < 0 ? 0 : static_cast<int>(m.tetrahedron_tag(v.worst_element));
  // The names of api::Validity, as on planar meshes.
  ctx.results = {
      {"triangles", m.num_triangles()}, {"quadrilaterals", 0}, {"tetrahedra", m.num_tetrahedra()},
      {"invalid", v.invalid},           {"worst", v.worst},    {"worst_element", worst_tag},
      {"worst_triangle", worst_tag}};
  Field poor{fmt::format("homesh: elements of certified minJ/maxJ < {:g}", o.poor),
             Field::Kind::ElementNode,
             {}};
  for (int e = 0; e < m.num_tetrahedra(); ++e)
    if (v.ratio(e) < o.poor) poor.elements.push_back(e);
  poor.values.resize(m.tet.rows(), static_cast<Eigen::Index>(poor.elements.size()));
  for (std::size_t k = 0; k < poor.elements.size(); ++k)
    poor.values.col(static_cast<Eigen::Index>(k)).setConstant(v.ratio(poor.elements[k]));
  ctx.set_field(std::move(poor));
  const std::vector<std::string> histograms = measure_fields(ctx, v, chosen, measured);
  ctx.log.info(
      "quality: {} tetrahedra of order {} (bounds and measures {:.3f} s on {} thread(s); the "
      "measures with d = 3, W from the regular tetrahedron)",
      m.num_tetrahedra(), m.order, std::chrono::duration<double>(t1 - t0).count(), used);
  ctx.log.info("  {}", validity_line(m, v));
  ctx.log.info("  measure per element: minimum, mean, | count in 10 bins over [0, 1] |");
  for (const auto& line : histograms) ctx.log.info("{}", line);
  if (o.worst > 0)
    ctx.log.info("  worst elements by minJ/maxJ:\n{}", worst_elements(m, v.ratio, o.worst));
}

void run(Context& ctx, const QualityOptions& o) {
  if (ctx.volume) return run_volume(ctx, o);
  const Mesh& m = ctx.require_mesh("quality");
  std::vector<const Measure*> chosen;
  for (const auto& name : o.measures) chosen.push_back(&measure(name));

  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t cpu0 = std::clock();
  const int used = o.threads > 0 ? o.threads : omp_get_num_procs();
  MeshQuality quality =
      mesh_quality(m, chosen, o.lattice > 0 ? o.lattice : default_lattice_order(m.order),
                   o.reference, o.bounds, used);
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const MeshValidity& v = quality.validity;
  ctx.set_field({kValidityFieldName, Field::Kind::Element, v.ratio.transpose(), true, true});
  ctx.results = {{"triangles", m.num_triangles()},
                 {"quadrilaterals", m.num_quads()},
                 {"tetrahedra", 0},
                 {"invalid", v.invalid},
                 {"worst", v.worst},
                 {"worst_element", static_cast<int>(m.triangle_tag(v.worst_element))},
                 {"worst_triangle", static_cast<int>(m.triangle_tag(v.worst_element))}};
  const std::vector<std::string> histograms = measure_fields(ctx, v, chosen, quality.measures);
  add_poor_elements(ctx, v, o.poor);
  const auto t2 = std::chrono::steady_clock::now();
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };

  ctx.log.info(
      "quality: {} triangles{} of order {} (bounds and measures {:.3f} s, {:.3f} s CPU on {} "
      "thread(s); views {:.3f} s)",
      m.num_triangles(),
      m.num_quads() > 0 ? fmt::format(" and {} quadrilaterals", m.num_quads()) : "", m.order,
      seconds(t0, t1), cpu, used, seconds(t1, t2));
  ctx.log.info("  {}", validity_line(m, v));
  ctx.log.info("  measure per element: minimum, mean, | count in 10 bins over [0, 1] |");
  for (const auto& line : histograms) ctx.log.info("{}", line);
  if (o.worst > 0)
    ctx.log.info("  worst elements by minJ/maxJ:\n{}", worst_elements(m, v.ratio, o.worst));
}

}  // namespace

Stage quality_stage() {
  // Defaults: those of QualityOptions and BoundsOptions (quality/jacobian_bounds.h).
  using O = QualityOptions;
  OptionTable<O> t;
  t.add("measures", &O::measures,
        list(where<std::string>(text(), is_measure, "not a measure (see homesh --measures)")),
        "measures to add (Q1..Q17, see homesh --measures)");
  t.add("reference", &O::reference,
        choice<Reference>({{"element_max", Reference::element_max}, {"ideal", Reference::ideal}}),
        "normalise size measures by the element's max (thesis) or by the unit ideal");
  t.add("lattice", &O::lattice, integer(0, 60),
        "order of the sampling lattice for minima (0 = 2p)");
  t.add(
      "tolerance", [](O& o) -> double& { return o.bounds.relative_tolerance; }, real(0, 1, "()"),
      "relative tolerance of the certified Jacobian bounds");
  t.add("worst", &O::worst, integer(0, 1000), "number of worst elements to list");
  t.add("poor", &O::poor, real(-1, 1, "[]"),
        "elements of certified minJ/maxJ below this get a view of their own");
  t.add("threads", &O::threads, integer(0, 1024),
        "threads for bounds and measures (0 = one per core)");
  return make_stage<O>("quality",
                       "certified validity (minJ/maxJ) and quality measures: views and a report", t,
                       run, false, true, true);
}

}  // namespace homesh
