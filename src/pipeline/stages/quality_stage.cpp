#include "pipeline/stages/quality_stage.h"

#include "core/error.h"
#include "pipeline/quality_report.h"
#include "quality/mesh_quality.h"
#include "quality/mesh_validity.h"

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
  BoundsOptions bounds;
  bounds.relative_tolerance = opt.get_double("tolerance");
  if (!(bounds.relative_tolerance > 0 && bounds.relative_tolerance < 1))
    throw Error("stage 'quality': option tolerance must be in (0, 1)");
  std::vector<const Measure*> chosen;
  for (const auto& name : opt.get_list("measures")) chosen.push_back(&measure(name));

  const MeshValidity v = mesh_validity(m, bounds);
  ctx.set_field({"minJ/maxJ", Field::Kind::Element, v.ratio.transpose()});
  ctx.log.info("quality: {} triangles of order {}", m.num_triangles(), m.order);
  ctx.log.info("  {}", validity_line(m, v));
  ctx.log.info("  measure per element: minimum, mean, | count in 10 bins over [0, 1] |");
  ctx.log.info("{}", histogram_line("minJ/maxJ", v.ratio));
  for (const Measure* q : chosen) {
    const MeshMeasure mm =
        mesh_measure(m, *q, lattice > 0 ? lattice : default_lattice_order(m.order), ref);
    ctx.set_field({q->name + " min", Field::Kind::Element, mm.element_min.transpose()});
    ctx.set_field({q->name, Field::Kind::ElementNode, mm.node_values});
    ctx.log.info("{}", histogram_line(q->name, mm.element_min));
  }
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
           {"worst", "5", "number of worst elements to list"}},
          run};
}

}  // namespace homesh
