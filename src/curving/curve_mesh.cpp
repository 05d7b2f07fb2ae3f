#include "curving/curve_mesh.h"

#include "core/raise_order.h"

namespace homesh {

CurveResult curve_mesh(const Mesh& m, const std::function<Eigen::Matrix2Xd(Mesh& raised)>& place,
                       const CurveOptions& opt) {
  Mesh raised = raise_order(m, opt.order);
  Eigen::Matrix2Xd target = place(raised);
  const std::vector<bool> boundary = boundary_nodes(raised);
  std::vector<bool> held = boundary;
  if (opt.fixed_vertices) {
    const std::vector<bool> vertex = vertex_nodes(raised);
    for (int i = 0; i < raised.num_nodes(); ++i)
      if (vertex[i] && !held[i]) {
        held[i] = true;
        target.col(i) = raised.x.col(i);
      }
  }
  CurveResult r;
  r.deform = deform_mesh(raised, target, held, opt.deform);
  const bool restricted = opt.fixed_vertices || opt.deform.reach > 0 || opt.deform.layers > 0;
  if (!r.deform.complete && restricted) {
    r.fell_back = true;
    r.restricted_reached = r.deform.reached;
    DeformOptions whole = opt.deform;
    whole.reach = 0;
    whole.layers = 0;
    r.deform = deform_mesh(raised, target, boundary, whole);
  }
  return r;
}

}  // namespace homesh
