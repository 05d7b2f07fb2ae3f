#include "gmsh/cad_boundary.h"

#include <gmsh.h>

#include <cmath>
#include <map>

#include "element/reference_nodes.h"

namespace homesh::gmsh_adapter {
namespace {

struct Curve {
  bool cad = false;
  double a = 0, b = 0;  // parameter bounds
  bool closed = false;
};

Curve curve_info(int tag) {
  Curve c;
  std::string type;
  gmsh::model::getType(1, tag, type);
  if (type.rfind("Discrete", 0) == 0) return c;
  c.cad = true;
  std::vector<double> lo, hi, ends;
  gmsh::model::getParametrizationBounds(1, tag, lo, hi);
  c.a = lo[0];
  c.b = hi[0];
  gmsh::model::getValue(1, tag, {c.a, c.b}, ends);
  std::vector<double> mid;
  gmsh::model::getValue(1, tag, {0.5 * (c.a + c.b)}, mid);
  const double size = std::hypot(mid[0] - ends[0], mid[1] - ends[1]);
  c.closed = std::hypot(ends[3] - ends[0], ends[4] - ends[1]) <= 1e-9 * std::max(size, 1e-300);
  return c;
}

double parameter_of(const Mesh& m, int node, int tag) {
  const NodeClass& c = m.node_class[node];
  if (c.dim == 1 && c.tag == tag && std::isfinite(c.u)) return c.u;
  std::vector<double> u;
  gmsh::model::getParametrization(1, tag, {m.x(0, node), m.x(1, node), 0.0}, u);
  return u[0];
}

}  // namespace

Eigen::Matrix2Xd place_on_cad(Mesh& m) {
  Eigen::Matrix2Xd x = m.x;
  const int p = m.order;
  if (p < 2) return x;
  const Eigen::RowVectorXd r = reference_line_nodes(p);
  std::map<int, Curve> curves;
  for (int k = 0; k < m.num_lines(); ++k) {
    const int tag = m.line_entity[k];
    auto it = curves.find(tag);
    if (it == curves.end()) it = curves.emplace(tag, curve_info(tag)).first;
    const Curve& c = it->second;
    if (!c.cad) continue;

    const int n0 = m.line(0, k), n1 = m.line(1, k);
    const double u0 = parameter_of(m, n0, tag);
    double u1 = parameter_of(m, n1, tag);
    const double period = c.b - c.a;
    if (c.closed && std::abs(u1 - u0) > 0.5 * period) u1 += u1 > u0 ? -period : period;

    // Cumulative chord length along the curve between u0 and u1.
    std::vector<double> us(kArcLengthChords + 1), pts;
    for (int i = 0; i <= kArcLengthChords; ++i) us[i] = u0 + (u1 - u0) * i / kArcLengthChords;
    gmsh::model::getValue(1, tag, us, pts);
    std::vector<double> s(kArcLengthChords + 1, 0.0);
    for (int i = 1; i <= kArcLengthChords; ++i)
      s[i] = s[i - 1] + std::hypot(pts[3 * i] - pts[3 * i - 3], pts[3 * i + 1] - pts[3 * i - 2]);

    std::vector<double> targets;
    for (int j = 2; j <= p; ++j) {
      const double want = r(j) * s.back();
      int i = 1;
      while (i < kArcLengthChords && s[i] < want) ++i;
      const double t = s[i] > s[i - 1] ? (want - s[i - 1]) / (s[i] - s[i - 1]) : 0.0;
      targets.push_back(us[i - 1] + t * (us[i] - us[i - 1]));
    }
    std::vector<double> placed;
    gmsh::model::getValue(1, tag, targets, placed);
    auto wrap = [&](double u) {
      return c.closed ? c.a + std::fmod(std::fmod(u - c.a, period) + period, period) : u;
    };
    for (int j = 2; j <= p; ++j) {
      const int node = m.line(j, k);
      x(0, node) = placed[3 * (j - 2)];
      x(1, node) = placed[3 * (j - 2) + 1];
      m.node_class[node] = {1, tag, wrap(targets[j - 2])};
    }
    for (int end : {n0, n1})
      if (m.node_class[end].dim == 1 && m.node_class[end].tag == tag)
        m.node_class[end].u = wrap(end == n0 ? u0 : u1);
  }
  return x;
}

}  // namespace homesh::gmsh_adapter
