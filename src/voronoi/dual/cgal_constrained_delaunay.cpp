#include "voronoi/dual/cgal_constrained_delaunay.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <list>
#include <set>
#include <string>

#include "core/error.h"

namespace homesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;  // nesting level
using Fb = CGAL::Constrained_triangulation_face_base_2<Kernel, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

std::array<int, 2> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

}  // namespace

std::vector<std::array<int, 3>> cgal_constrained_triangles(
    const Eigen::Matrix2Xd& points, const std::vector<std::array<int, 2>>& boundary,
    const std::vector<std::array<int, 2>>& constraints) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> v(points.cols());
  for (Eigen::Index k = 0; k < points.cols(); ++k) {
    v[k] = cdt.insert(Kernel::Point_2(points(0, k), points(1, k)));
    v[k]->info() = static_cast<int>(k);
  }
  if (static_cast<Eigen::Index>(cdt.number_of_vertices()) != points.cols())
    throw Error("constrained Delaunay: coincident points");
  std::set<std::array<int, 2>> walls;
  for (const auto& [a, b] : boundary) {
    cdt.insert_constraint(v[a], v[b]);
    walls.insert(key(a, b));
  }
  for (const auto& [a, b] : constraints) cdt.insert_constraint(v[a], v[b]);
  if (static_cast<Eigen::Index>(cdt.number_of_vertices()) != points.cols())
    throw Error("constrained Delaunay: constraint segments cross");
  for (const auto& [a, b] : boundary)
    if (!cdt.is_edge(v[a], v[b]))
      throw Error("constrained Delaunay: boundary segment " + std::to_string(a) + "-" +
                  std::to_string(b) + " runs through another point");
  // Nesting level: 0 outside, +1 across each boundary segment, by flooding
  // from the unbounded face.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::list<Cdt::Face_handle> queue{cdt.infinite_face()};
  cdt.infinite_face()->info() = 0;
  while (!queue.empty()) {
    const Cdt::Face_handle f = queue.front();
    queue.pop_front();
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle n = f->neighbor(i);
      if (n->info() >= 0) continue;
      const Cdt::Vertex_handle a = f->vertex(Cdt::cw(i)), b = f->vertex(Cdt::ccw(i));
      const bool wall = !cdt.is_infinite(a) && !cdt.is_infinite(b) && f->is_constrained(i) &&
                        walls.count(key(a->info(), b->info()));
      n->info() = f->info() + (wall ? 1 : 0);
      wall ? queue.push_back(n) : queue.push_front(n);
    }
  }
  std::vector<std::array<int, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    std::array<int, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace homesh
