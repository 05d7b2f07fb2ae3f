#include "pipeline/stages/order_stage.h"

#include "core/raise_order.h"
#include "core/raise_volume_order.h"

namespace homesh {
namespace {

void run(Context& ctx, const OrderOptions& o) {
  if (ctx.volume) {
    VolumeMesh& v = *ctx.volume;
    v = raise_volume_order(v, o.order);
    ctx.fields.clear();
    ctx.log.info("order: p = {}, {} nodes, {} tetrahedra, {} triangles", o.order, v.num_nodes(),
                 v.num_tetrahedra(), v.num_triangles());
    return;
  }
  Mesh& m = ctx.require_mesh("order");
  m = raise_order(m, o.order);
  ctx.fields.clear();
  ctx.log.info("order: p = {}, {} nodes, {} triangles, {} quadrilaterals", o.order, m.num_nodes(),
               m.num_triangles(), m.num_quads());
}

}  // namespace

Stage order_stage() {
  OptionTable<OrderOptions> t;
  t.add("p", &OrderOptions::order, integer(1, kMaxOrder),
        "element order, 1 to " + std::to_string(kMaxOrder));
  return make_stage<OrderOptions>(
      "order", "raise (or lower) the mesh to order p with straight-sided elements", t, run,
      /*creates_mesh=*/false, /*handles_quads=*/true, /*handles_volumes=*/true);
}

}  // namespace homesh
