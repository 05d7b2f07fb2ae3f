#include "pipeline/quality_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace homesh {

namespace {

// "triangle" or "quadrilateral": the kind of 2D element e (core/mesh.h numbering).
const char* kind(const Mesh& m, int e) {
  return e < m.num_triangles() ? "triangle" : "quadrilateral";
}

// The indices of the `count` smallest values, smallest first.
std::vector<int> smallest(const Eigen::VectorXd& values, int count) {
  std::vector<int> order(static_cast<std::size_t>(values.size()));
  std::iota(order.begin(), order.end(), 0);
  const int n = std::min<int>(count, static_cast<int>(order.size()));
  std::partial_sort(order.begin(), order.begin() + n, order.end(),
                    [&](int a, int b) { return values(a) < values(b); });
  order.resize(static_cast<std::size_t>(n));
  return order;
}

std::string certified_by(const MeshValidity& v, const std::string& elements) {
  return fmt::format(
      "validity: {} invalid of {} (certified by Bezier bounds of det J, relative tolerance {:g})",
      v.invalid, elements, v.relative_tolerance);
}

}  // namespace

std::string validity_line(const Mesh& m, const MeshValidity& v, std::size_t worst_tag) {
  const std::string elements =
      m.num_quads() == 0
          ? fmt::format("{} triangles", m.num_triangles())
          : fmt::format("{} triangles and {} quadrilaterals", m.num_triangles(), m.num_quads());
  std::string line = certified_by(v, elements);
  if (v.worst_element >= 0) {
    const Eigen::Vector2d c = m.corner_centroid(v.worst_element);
    line += fmt::format("; worst minJ/maxJ {:.4f} at {} {} ({:.4g}, {:.4g})", v.worst,
                        kind(m, v.worst_element),
                        worst_tag ? worst_tag : m.triangle_tag(v.worst_element), c.x(), c.y());
  }
  if (v.unconverged > 0) line += fmt::format("; {} not refined to tolerance", v.unconverged);
  return line;
}

std::string validity_line(const VolumeMesh& m, const MeshValidity& v, std::size_t worst_tag) {
  std::string line = certified_by(v, fmt::format("{} tetrahedra", m.num_tetrahedra()));
  if (v.worst_element >= 0) {
    const Eigen::Vector3d c = m.corner_centroid(v.worst_element);
    line += fmt::format("; worst minJ/maxJ {:.4f} at tetrahedron {} ({:.4g}, {:.4g}, {:.4g})",
                        v.worst, worst_tag ? worst_tag : m.tetrahedron_tag(v.worst_element), c.x(),
                        c.y(), c.z());
  }
  if (v.unconverged > 0) line += fmt::format("; {} not refined to tolerance", v.unconverged);
  return line;
}

std::string histogram_line(const std::string& name, const Eigen::VectorXd& values) {
  int bins[10] = {};
  for (double q : values) ++bins[std::clamp(static_cast<int>(q * 10), 0, 9)];
  std::string line =
      fmt::format("  {:<10} min {:.4f}  mean {:.4f}  |", name,
                  values.size() ? values.minCoeff() : 0.0, values.size() ? values.mean() : 0.0);
  for (int b : bins) line += fmt::format(" {}", b);
  return line + " |";
}

std::string worst_elements(const Mesh& m, const Eigen::VectorXd& values, int count) {
  std::string out;
  for (const int e : smallest(values, count)) {
    const Eigen::Vector2d c = m.corner_centroid(e);
    out += fmt::format("    {} {:<8} at ({:.4g}, {:.4g})  {:.4f}\n", kind(m, e), m.triangle_tag(e),
                       c.x(), c.y(), values(e));
  }
  return out;
}

std::string worst_elements(const VolumeMesh& m, const Eigen::VectorXd& values, int count) {
  std::string out;
  for (const int e : smallest(values, count)) {
    const Eigen::Vector3d c = m.corner_centroid(e);
    out += fmt::format("    tetrahedron {:<8} at ({:.4g}, {:.4g}, {:.4g})  {:.4f}\n",
                       m.tetrahedron_tag(e), c.x(), c.y(), c.z(), values(e));
  }
  return out;
}

}  // namespace homesh
