#include "gmsh/boundary_sampling.h"

#include <gmsh.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <set>

#include "core/error.h"

namespace homesh::gmsh_adapter {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

}  // namespace

CadCurve cad_curve(int tag) {
  CadCurve c;
  c.tag = tag;
  std::vector<double> lo, hi;
  gmsh::model::getParametrizationBounds(1, tag, lo, hi);
  c.u0 = lo[0];
  c.u1 = hi[0];
  gmsh::vectorpair ends;
  gmsh::model::getBoundary({{1, tag}}, ends, false, false, false);
  if (ends.empty()) throw Error("curve " + std::to_string(tag) + " has no end points");
  c.start_point = ends.front().second;
  c.end_point = ends.back().second;
  c.closed = c.start_point == c.end_point;
  return c;
}

std::vector<SurfaceBoundary> surface_boundaries() {
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  std::vector<SurfaceBoundary> out;
  for (const auto& [dim, tag] : surfaces) {
    gmsh::vectorpair bnd;
    gmsh::model::getBoundary({{dim, tag}}, bnd, false, true, false);
    std::vector<LoopCurve> open;
    for (const auto& b : bnd) open.push_back({std::abs(b.second), b.second < 0});
    const auto from = [](const LoopCurve& l) {
      const CadCurve c = cad_curve(l.tag);
      return l.reversed ? c.end_point : c.start_point;
    };
    const auto to = [](const LoopCurve& l) {
      const CadCurve c = cad_curve(l.tag);
      return l.reversed ? c.start_point : c.end_point;
    };
    SurfaceBoundary s;
    s.tag = tag;
    while (!open.empty()) {
      std::vector<LoopCurve> loop{open.front()};
      open.erase(open.begin());
      while (to(loop.back()) != from(loop.front())) {
        const auto next = std::find_if(open.begin(), open.end(), [&](const LoopCurve& l) {
          return from(l) == to(loop.back());
        });
        if (next == open.end())
          throw Error("surface " + std::to_string(tag) + ": its boundary curves do not close");
        loop.push_back(*next);
        open.erase(next);
      }
      s.loops.push_back(loop);
    }
    out.push_back(s);
  }
  return out;
}

Eigen::Matrix2Xd curve_points(int tag, const std::vector<double>& u) {
  std::vector<double> xyz;
  gmsh::model::getValue(1, tag, u, xyz);
  Eigen::Matrix2Xd out(2, static_cast<Eigen::Index>(u.size()));
  for (std::size_t k = 0; k < u.size(); ++k) out.col(k) << xyz[3 * k], xyz[3 * k + 1];
  return out;
}

Eigen::Vector2d model_point(int tag) {
  std::vector<double> xyz;
  gmsh::model::getValue(0, tag, {}, xyz);
  return {xyz[0], xyz[1]};
}

std::vector<int> curves_in_group(const std::string& name) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  std::set<int> out;
  for (const auto& [dim, tag] : groups) {
    std::string group;
    gmsh::model::getPhysicalName(dim, tag, group);
    if (lower(group) != lower(name)) continue;
    std::vector<int> curves;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, curves);
    out.insert(curves.begin(), curves.end());
  }
  return {out.begin(), out.end()};
}

std::vector<int> boundary_curves() {
  std::set<int> out;
  for (const SurfaceBoundary& s : surface_boundaries())
    for (const auto& loop : s.loops)
      for (const LoopCurve& c : loop) out.insert(c.tag);
  return {out.begin(), out.end()};
}

SeededBoundary seed_boundary(
    int samples,
    const std::function<std::vector<double>(const Eigen::VectorXd&, const Eigen::Matrix2Xd&, bool)>&
        divide) {
  SeededBoundary out;
  out.surfaces = surface_boundaries();
  std::vector<Eigen::Vector2d> seeds;
  std::map<int, int> point_seed;  // model point -> seed
  const auto point = [&](int tag) {
    const auto it = point_seed.find(tag);
    if (it != point_seed.end()) return it->second;
    seeds.push_back(model_point(tag));
    out.classes.push_back({0, tag, std::numeric_limits<double>::quiet_NaN()});
    return point_seed[tag] = static_cast<int>(seeds.size()) - 1;
  };
  for (const int tag : boundary_curves()) {
    const CadCurve c = cad_curve(tag);
    std::vector<double> u(samples + 1);
    for (int k = 0; k <= samples; ++k) u[k] = c.u0 + (c.u1 - c.u0) * k / samples;
    const Eigen::Matrix2Xd x = curve_points(tag, u);
    out.curve_samples[tag] = x;
    const std::vector<double> at =
        divide(Eigen::Map<const Eigen::VectorXd>(u.data(), samples + 1), x, c.closed);
    std::vector<int>& on = out.curve_seeds[tag];
    on.push_back(point(c.start_point));
    const std::vector<double> inner(at.begin() + 1, at.end() - 1);
    const Eigen::Matrix2Xd p = curve_points(tag, inner);
    for (std::size_t k = 0; k < inner.size(); ++k) {
      seeds.push_back(p.col(k));
      out.classes.push_back({1, tag, inner[k]});
      on.push_back(static_cast<int>(seeds.size()) - 1);
    }
    on.push_back(point(c.end_point));
  }
  out.seeds.resize(2, static_cast<Eigen::Index>(seeds.size()));
  for (std::size_t k = 0; k < seeds.size(); ++k) out.seeds.col(k) = seeds[k];
  return out;
}

}  // namespace homesh::gmsh_adapter
