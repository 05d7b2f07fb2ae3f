#include "pipeline/stages/info_stage.h"

#include <map>

namespace homesh {
namespace {

const char* dim_name(int dim) {
  return dim == 0 ? "point" : dim == 1 ? "curve" : dim == 2 ? "surface" : "volume";
}

// The counts of a volume mesh (issue 24).
void report_volume(Context& ctx) {
  const VolumeMesh& m = *ctx.volume;
  ctx.log.report("info: {} (CAD: {})", ctx.input, ctx.has_cad ? "yes" : "no");
  ctx.log.report("  order {}: {} nodes, {} tetrahedra, {} triangles, {} lines, {} points", m.order,
                 m.num_nodes(), m.num_tetrahedra(), m.num_triangles(), m.num_lines(),
                 m.point_node.size());
  int count[4] = {0, 0, 0, 0};
  for (const Entity& e : m.entities) ++count[e.dim];
  ctx.log.report("  entities: {} points, {} curves, {} surfaces, {} volumes", count[0], count[1],
                 count[2], count[3]);
  std::map<int, int> on[4];
  for (int c : m.line_entity) ++on[1][c];
  for (int s : m.tri_entity) ++on[2][s];
  for (int v : m.tet_entity) ++on[3][v];
  if (m.physicals.empty()) ctx.log.report("  physical groups: none");
  for (const PhysicalGroup& g : m.physicals) {
    int elements = 0;
    for (int e : g.entities) elements += g.dim > 0 ? on[g.dim][e] : 0;
    ctx.log.report("  physical {} {} \"{}\": {} entities, {} elements", dim_name(g.dim), g.tag,
                   g.name, g.entities.size(), elements);
  }
}

void run(Context& ctx, const NoOptions&) {
  if (ctx.volume) return report_volume(ctx);
  const Mesh& m = ctx.require_mesh("info");
  ctx.log.report("info: {} (CAD: {})", ctx.input, ctx.has_cad ? "yes" : "no");
  ctx.log.report("  order {}: {} nodes, {} triangles, {} boundary lines, {} points", m.order,
                 m.num_nodes(), m.num_triangles(), m.num_lines(), m.point_node.size());
  if (m.num_quads() > 0)
    ctx.log.report("  and {} quadrilaterals ('{}')", m.num_quads(), quad_type_name(m.order));
  int count[3] = {0, 0, 0};
  for (const Entity& e : m.entities) ++count[e.dim];
  ctx.log.report("  entities: {} points, {} curves, {} surfaces", count[0], count[1], count[2]);

  std::map<int, int> lines_on, tris_on;  // tris_on: 2D elements
  for (int c : m.line_entity) ++lines_on[c];
  for (int s : m.tri_entity) ++tris_on[s];
  for (int s : m.quad_entity) ++tris_on[s];
  if (m.physicals.empty()) ctx.log.report("  physical groups: none");
  for (const PhysicalGroup& g : m.physicals) {
    int elements = 0;
    for (int e : g.entities) elements += g.dim == 1 ? lines_on[e] : g.dim == 2 ? tris_on[e] : 0;
    ctx.log.report("  physical {} {} \"{}\": {} entities, {} elements", dim_name(g.dim), g.tag,
                   g.name, g.entities.size(), elements);
  }
}

}  // namespace

Stage info_stage() {
  return make_stage<NoOptions>("info",
                               "print counts, order, entities and physical groups of the mesh", {},
                               run, false, true, true);
}

}  // namespace homesh
