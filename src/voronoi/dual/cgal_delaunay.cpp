#include "voronoi/dual/cgal_delaunay.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <utility>

namespace homesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vertex = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vertex>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

}  // namespace

std::vector<std::array<int, 3>> cgal_delaunay_triangles(const Eigen::Matrix2Xd& points) {
  std::vector<std::pair<Kernel::Point_2, int>> input;
  input.reserve(points.cols());
  for (int k = 0; k < points.cols(); ++k)
    input.emplace_back(Kernel::Point_2(points(0, k), points(1, k)), k);
  const Delaunay dt(input.begin(), input.end());
  std::vector<std::array<int, 3>> out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    std::array<int, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

VoronoiCells cgal_voronoi_cells(const Eigen::Matrix2Xd& points) {
  std::vector<std::pair<Kernel::Point_2, int>> input;
  input.reserve(points.cols());
  for (int k = 0; k < points.cols(); ++k)
    input.emplace_back(Kernel::Point_2(points(0, k), points(1, k)), k);
  const Delaunay dt(input.begin(), input.end());
  VoronoiCells out;
  out.vertices.resize(points.cols());
  out.neighbours.resize(points.cols());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const int k = v->info();
    auto f = dt.incident_faces(v), end = f;
    bool bounded = true;
    std::vector<Eigen::Vector2d> cell;
    do {
      if (dt.is_infinite(f)) {
        bounded = false;
      } else {
        const Kernel::Point_2 c = dt.circumcenter(f);
        cell.emplace_back(c.x(), c.y());
      }
    } while (++f != end);
    if (bounded) out.vertices[k] = std::move(cell);
    auto n = dt.incident_vertices(v), stop = n;
    do
      if (!dt.is_infinite(n)) out.neighbours[k].push_back(n->info());
    while (++n != stop);
  }
  return out;
}

int cgal_orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return static_cast<int>(CGAL::orientation(
      Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y()), Kernel::Point_2(c.x(), c.y())));
}

}  // namespace homesh
