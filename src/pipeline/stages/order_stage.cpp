#include "pipeline/stages/order_stage.h"

#include "core/raise_order.h"

namespace homesh {
namespace {

void run(Context& ctx, const Options& opt) {
  Mesh& m = ctx.require_mesh("order");
  const int p = opt.get_int("p", 1, kMaxOrder);
  m = raise_order(m, p);
  ctx.fields.clear();
  ctx.log.info("order: p = {}, {} nodes, {} triangles", p, m.num_nodes(), m.num_triangles());
}

}  // namespace

Stage order_stage() {
  return {"order",
          "raise (or lower) the mesh to order p with straight-sided elements",
          {{"p", "2", "element order, 1 to " + std::to_string(kMaxOrder)}},
          run};
}

}  // namespace homesh
