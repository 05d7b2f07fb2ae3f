#include "layers/insert_layers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "core/error.h"
#include "core/raise_order.h"
#include "layers/clear_room.h"
#include "layers/front_split.h"
#include "layers/plane_geometry.h"
#include "layers/radius_ratio.h"
#include "layers/stack_fit.h"
#include "layers/star_smoothing.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

using layers_detail::number_text;
using layers_detail::orient;
using layers_detail::point_text;

// New triangles and quadrilaterals with their surface and layer.
struct Triangles {
  std::vector<std::array<int, 3>> nodes;
  std::vector<int> entity, layer;
  std::vector<std::array<int, 4>> quads;
  std::vector<int> quad_entity, quad_layer;

  void add(const std::array<int, 3>& t, int surface, int k) {
    nodes.push_back(t);
    entity.push_back(surface);
    layer.push_back(k);
  }
};

double worst_ratio(const Eigen::Matrix2Xd& x, const std::array<int, 3>& a,
                   const std::array<int, 3>& b) {
  auto q = [&](const std::array<int, 3>& t) {
    Eigen::Matrix<double, 2, 3> X;
    for (int i = 0; i < 3; ++i) X.col(i) = x.col(t[i]);
    return orient(X.col(0), X.col(1), X.col(2)) > 0 ? radius_ratio(X) : -1.0;
  };
  return std::min(q(a), q(b));
}

// Quad p0 p1 p2 p3 (counter-clockwise) as itself (`quads`) or as two triangles: the
// diagonal with the better worst radius ratio, a valid one if there is one.
void add_quad(const Eigen::Matrix2Xd& x, int p0, int p1, int p2, int p3, int surface, int k,
              bool quads, Triangles& out) {
  if (quads) {
    out.quads.push_back({p0, p1, p2, p3});
    out.quad_entity.push_back(surface);
    out.quad_layer.push_back(k);
    return;
  }
  const std::array<int, 3> a0{p0, p1, p2}, a1{p0, p2, p3}, b0{p0, p1, p3}, b1{p1, p2, p3};
  if (worst_ratio(x, a0, a1) >= worst_ratio(x, b0, b1)) {
    out.add(a0, surface, k);
    out.add(a1, surface, k);
  } else {
    out.add(b0, surface, k);
    out.add(b1, surface, k);
  }
}

// The normal line of node i of a loop (its first, for a fan) among `lines`, which
// list the loops' normals in order.
int line_of(const std::vector<std::vector<std::vector<int>>>& front, std::size_t loop, int i) {
  int k = 0;
  for (std::size_t l = 0; l < loop; ++l)
    for (const auto& f : front[l]) k += static_cast<int>(f.size());
  for (int j = 0; j < i; ++j) k += static_cast<int>(front[loop][j].size());
  return k;
}

// At each end of an open wall: the layer and front nodes on the normal line lie
// on the adjacent boundary line, which is split at them (n + 1 lines, its curve
// and direction kept), and they are classified on its curve, the parameter
// interpolated linearly between the line's ends (NaN unless both are on it).
void split_end_lines(const std::vector<WallLoop>& loops,
                     const std::vector<std::vector<std::vector<int>>>& front,
                     const std::vector<LayerLine>& lines, Mesh& out) {
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const WallLoop& loop = loops[l];
    if (loop.closed) continue;
    for (int end = 0; end < 2; ++end) {
      const int i = end == 0 ? 0 : loop.size() - 1;
      const int k = loop.end_lines[end], c = out.line_entity[k];
      const LayerLine& line = lines[line_of(front, l, i)];
      std::vector<int> chain = line.nodes;
      chain.push_back(loop.ends[end]);
      auto param = [&](int v) {
        const NodeClass& nc = out.node_class[v];
        return nc.dim == 1 && nc.tag == c ? nc.u : std::numeric_limits<double>::quiet_NaN();
      };
      const Eigen::Vector2d p0 = out.x.col(chain.front()), p1 = out.x.col(chain.back());
      const double u0 = param(chain.front()), u1 = param(chain.back());
      for (std::size_t j = 1; j + 1 < chain.size(); ++j) {
        const double t = (out.x.col(chain[j]) - p0).norm() / (p1 - p0).norm();
        out.node_class[chain[j]] = {1, c, (1 - t) * u0 + t * u1};
      }
      if (out.line(0, k) != chain.front()) std::reverse(chain.begin(), chain.end());
      const int segments = static_cast<int>(chain.size()) - 1, lines0 = out.num_lines();
      out.line.conservativeResize(2, lines0 + segments - 1);
      out.line.col(k) << chain[0], chain[1];
      for (int j = 1; j < segments; ++j) {
        out.line.col(lines0 + j - 1) << chain[j], chain[j + 1];
        out.line_entity.push_back(c);
      }
    }
  }
}

// v > 0 rounded down to 2 significant digits, for a suggestion that works.
double round_down(double v) {
  const double unit = std::pow(10.0, std::floor(std::log10(v)) - 1);
  return std::floor(v / unit) * unit;
}

}  // namespace

std::vector<double> layer_depths(double first, double ratio, int n) {
  if (n < 1 || n > 1000) throw Error("layers: the number of layers n must be in [1, 1000]");
  if (!(first > 0)) throw Error("layers: the first layer's thickness must be > 0");
  if (!(ratio > 0)) throw Error("layers: the growth ratio must be > 0");
  std::vector<double> d(n + 1, 0.0);
  double h = first;
  for (int k = 1; k <= n; ++k, h *= ratio) d[k] = d[k - 1] + h;
  return d;
}

LayerResult insert_layers(const Mesh& input, const LayerOptions& opt) {
  const int n = opt.layers;
  const std::vector<double> d = layer_depths(opt.first, opt.ratio, n);
  LayerResult r;
  r.thickness = d[n];
  r.from_corners = input.order > 1;
  const Mesh m = r.from_corners ? raise_order(input, 1) : input;
  const int invalid = mesh_validity(m).invalid;
  if (invalid > 0)
    throw Error("layers: the input mesh has " + std::to_string(invalid) +
                " triangles not certified valid");

  const std::vector<WallLoop> loops = wall_loops(m, wall_curves(m, opt.walls));
  std::vector<std::vector<WallNormal>> normals;
  for (const WallLoop& loop : loops) {
    normals.push_back(wall_normals(m, loop, opt.normals));
    r.wall_edges += loop.edges();
    for (std::size_t i = 0; i < loop.nodes.size(); ++i) {
      const WallNormal& w = normals.back()[i];
      r.fan_nodes += w.directions.size() > 1 ? 1 : 0;
      if (w.angle > r.sharpest_angle) {
        r.sharpest_angle = w.angle;
        r.sharpest_node = loop.nodes[i];
      }
    }
  }
  r.loops = static_cast<int>(loops.size());
  r.open_walls = static_cast<int>(
      std::count_if(loops.begin(), loops.end(), [](const WallLoop& l) { return !l.closed; }));
  const FrontSplit split = split_front(m, loops, normals);
  r.gap_triangles = split.gap_triangles;

  // Open the room: each front node to depth d_n on its normal.
  std::vector<int> moving, curve;
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t i = 0; i < loops[l].nodes.size(); ++i)
      for (std::size_t j = 0; j < split.front[l][i].size(); ++j) {
        const WallNormal& w = normals[l][i];
        moving.push_back(split.front[l][i][j]);
        curve.push_back(loops[l].curves[i]);
        r.lines.push_back({loops[l].nodes[i], w.directions[j], w.scale, {}});
      }
  const int count = static_cast<int>(r.lines.size());
  // Along the front: a fan's normals run from the incoming edge's side (its
  // last) to the outgoing edge's (its first), which faces the next node's last.
  Room plan{{}, moving, std::vector<int>(count, -1), Eigen::Matrix2Xd(2, count)};
  for (const LayerLine& line : r.lines) plan.wall.push_back(line.wall_node);
  for (std::size_t l = 0, k = 0; l < loops.size(); ++l) {
    const int size = loops[l].size();
    std::vector<int> start(size + 1, static_cast<int>(k));
    for (int i = 0; i < size; ++i)
      start[i + 1] = start[i] + static_cast<int>(split.front[l][i].size());
    for (int i = 0; i < size; ++i) {
      for (int j = start[i] + 1; j < start[i + 1]; ++j) plan.next[j] = j - 1;
      if (i + 1 < size || loops[l].closed) plan.next[start[i]] = start[(i + 1) % size + 1] - 1;
    }
    k = start[size];
  }
  // Thinner stacks where the walls leave too little room (stack_fit.h).
  Eigen::Matrix2Xd direction(2, count);
  std::vector<double> scale(count);
  for (int k = 0; k < count; ++k) {
    direction.col(k) = r.lines[k].direction;
    scale[k] = r.lines[k].scale;
  }
  const StackFit fit =
      fit_stack(m, plan.wall, direction, scale, plan.next, d[n], opt.first, opt.fill, opt.cross);
  if (fit.no_room >= 0) {
    const LayerLine& line = r.lines[fit.no_room];
    const double room = (fit.crossing ? opt.cross : opt.fill) * fit.gap / line.scale;
    const std::string what =
        fit.crossing
            ? "the neighbouring normals cross (a concave wall) " + number_text(fit.gap) + " away"
            : "curve " + std::to_string(fit.curve) + " is " + number_text(fit.gap) + " away";
    throw Error(
        "layers: no layer fits at the wall node " + point_text(m.x.col(line.wall_node)) +
        " on curve " + std::to_string(curve[fit.no_room]) + ": along its normal " + what +
        ", room for a stack " + number_text(room) + " deep (" +
        (fit.crossing ? "cross = " + number_text(opt.cross) : "fill = " + number_text(opt.fill)) +
        "), less than the first layer (" + number_text(opt.first) +
        "); first = " + number_text(round_down(0.5 * room)) + " would fit");
  }
  for (int k = 0; k < count; ++k) r.lines[k].scale *= fit.factor[k];
  for (const ThinnedStretch& t : fit.thinned)
    r.thinned.push_back({m.x.col(r.lines[t.first].wall_node), m.x.col(r.lines[t.last].wall_node),
                         m.x.col(r.lines[t.tightest].wall_node), t.lines, t.factor, t.gap,
                         curve[t.tightest], t.curve, t.crossing});
  for (int k = 0; k < count; ++k)
    plan.target.col(k) =
        m.x.col(r.lines[k].wall_node) + d[n] * r.lines[k].scale * r.lines[k].direction;
  const Eigen::Matrix2Xd& target = plan.target;
  std::vector<bool> fixed(split.mesh.num_nodes());
  for (int i = 0; i < split.mesh.num_nodes(); ++i) fixed[i] = split.mesh.node_class[i].dim < 2;
  std::vector<double> floor = star_quality(m);
  floor.resize(split.mesh.num_nodes(), 1.0);
  const RoomResult room = open_room(split.mesh, moving, target, fixed, opt.room, floor, &plan);
  r.cleared = room.cleared;
  r.push_steps = room.steps;
  r.solves = room.solves;
  r.smoothed = room.smoothed;
  if (!room.complete) {
    const int b = std::max(room.bottleneck, 0);
    throw Error("layers: cannot open a room " + number_text(d[n]) + " thick for " +
                std::to_string(n) + " layers: the elastic push (" + opt.room.formulation +
                ", nu = " + number_text(opt.room.params.poisson) +
                ") keeps every element valid only up to " + number_text(100 * room.reached) +
                " % of it (" + std::to_string(room.steps) + " steps), tightest at the wall node " +
                point_text(m.x.col(r.lines[b].wall_node)) + " on curve " +
                std::to_string(curve[b]) + "; use fewer or thinner layers (n, first, ratio)");
  }

  // Layer nodes between each wall node and its front node.
  Mesh& out = r.mesh;
  out = room.mesh;
  const int base = out.num_nodes();
  out.x.conservativeResize(2, base + count * (n - 1));
  for (int k = 0; k < count; ++k) {
    LayerLine& line = r.lines[k];
    const NodeClass surface = out.node_class[moving[k]];
    line.nodes.push_back(line.wall_node);
    for (int i = 1; i < n; ++i) {
      const int node = base + k * (n - 1) + (i - 1);
      out.x.col(node) = m.x.col(line.wall_node) + d[i] * line.scale * line.direction;
      out.node_class.push_back(surface);
      line.nodes.push_back(node);
    }
    line.nodes.push_back(moving[k]);
  }
  split_end_lines(loops, split.front, r.lines, out);

  // Quads on the wall edges, fans at the sharp nodes.
  Triangles added;
  int first_line = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const int size = static_cast<int>(loops[l].nodes.size());
    std::vector<int> start(size + 1);  // lines of node i: start[i] .. start[i + 1] - 1
    for (int i = 0; i < size; ++i)
      start[i + 1] = start[i] + static_cast<int>(split.front[l][i].size());
    for (int i = 0; i < size; ++i) {
      const int surface = m.tri_entity[loops[l].triangles[i]];
      const LayerLine& a = r.lines[first_line + start[i]];
      const LayerLine& b = r.lines[first_line + start[(i + 1) % size + 1] - 1];
      for (int k = 1; k <= n && i < loops[l].edges(); ++k)
        add_quad(out.x, a.nodes[k - 1], b.nodes[k - 1], b.nodes[k], a.nodes[k], surface, k,
                 opt.quads, added);
      for (int j = start[i]; j + 1 < start[i + 1]; ++j) {
        const LayerLine& p = r.lines[first_line + j];
        const LayerLine& q = r.lines[first_line + j + 1];
        added.add({p.nodes[0], p.nodes[1], q.nodes[1]}, surface, 1);
        for (int k = 2; k <= n; ++k)
          add_quad(out.x, p.nodes[k - 1], p.nodes[k], q.nodes[k], q.nodes[k - 1], surface, k,
                   /*quads=*/false, added);
      }
    }
    first_line += start[size];
  }
  const int t0 = out.num_triangles();
  const int t1 = t0 + static_cast<int>(added.nodes.size());
  out.tri.conservativeResize(3, t1);
  for (int e = t0; e < t1; ++e)
    for (int i = 0; i < 3; ++i) out.tri(i, e) = added.nodes[e - t0][i];
  out.tri_entity.insert(out.tri_entity.end(), added.entity.begin(), added.entity.end());
  r.layer.assign(t0, 0);
  r.layer.insert(r.layer.end(), added.layer.begin(), added.layer.end());
  const int q1 = static_cast<int>(added.quads.size());
  out.quad.resize(4, q1);
  for (int e = 0; e < q1; ++e)
    for (int i = 0; i < 4; ++i) out.quad(i, e) = added.quads[e][i];
  out.quad_entity = added.quad_entity;
  r.layer.insert(r.layer.end(), added.quad_layer.begin(), added.quad_layer.end());

  const std::vector<int> renumber = drop_unused_nodes(out);
  for (LayerLine& line : r.lines) {
    line.wall_node = renumber[line.wall_node];
    for (int& v : line.nodes) v = renumber[v];
  }
  if (r.sharpest_node >= 0) r.sharpest_node = renumber[r.sharpest_node];

  const MeshValidity v = mesh_validity(out);
  if (v.invalid > 0) {
    int e = 0;
    while (v.min_det(e) > 0 && e + 1 < out.num_elements_2d()) ++e;
    const Eigen::Vector2d c = out.corner_centroid(e);
    throw Error("layers: " + std::to_string(v.invalid) + " layer elements would fold, e.g. in " +
                "layer " + std::to_string(r.layer[e]) + " near " + point_text(c) +
                " (neighbouring normals cross within the thickness " + number_text(d[n]) +
                "); use fewer or thinner layers (n, first, ratio)");
  }
  return r;
}

std::vector<int> corner_triangles(const LayerResult& r, int wall_node) {
  std::set<int> nodes;
  for (const LayerLine& line : r.lines)
    if (line.wall_node == wall_node) nodes.insert(line.nodes.begin(), line.nodes.end());
  std::vector<int> tris;
  const int nt = r.mesh.num_triangles();
  for (int e = 0; e < r.mesh.num_elements_2d(); ++e) {
    if (r.layer[e] == 0) continue;
    const auto corners = e < nt ? r.mesh.tri.col(e).head(3) : r.mesh.quad.col(e - nt).head(4);
    for (const int i : corners)
      if (nodes.count(i)) {
        tris.push_back(e);
        break;
      }
  }
  return tris;
}

}  // namespace homesh
