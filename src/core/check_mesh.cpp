#include "core/check_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"

namespace homesh {
namespace {

std::string where(const Mesh& m, int e) {
  const Eigen::Vector2d c = m.corner_centroid(e);
  std::ostringstream s;
  s << "triangle " << e + 1 << " at (" << c.x() << ", " << c.y() << ")";
  return s.str();
}

}  // namespace

void check_mesh(const Mesh& m, const std::string& source) {
  for (int i = 0; i < m.num_nodes(); ++i)
    if (!m.x.col(i).allFinite())
      throw Error(source + ": node " + std::to_string(i + 1) + " has a non-finite coordinate");
  std::set<std::array<int, 3>> seen;
  for (int e = 0; e < m.num_triangles(); ++e) {
    std::array<int, 3> c = {m.tri(0, e), m.tri(1, e), m.tri(2, e)};
    const Eigen::Vector2d a = m.x.col(c[0]), b = m.x.col(c[1]), d = m.x.col(c[2]);
    const double area2 = (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
    const double scale = std::max({(b - a).squaredNorm(), (d - a).squaredNorm(),
                                   (d - b).squaredNorm()});
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2])
      throw Error(source + ": " + where(m, e) + " repeats a corner node");
    if (std::abs(area2) <= 1e-12 * scale)
      throw Error(source + ": " + where(m, e) + " has zero area");
    if (area2 < 0)
      throw Error(source + ": " + where(m, e) + " is inverted (its corners run clockwise)");
    std::sort(c.begin(), c.end());
    if (!seen.insert(c).second)
      throw Error(source + ": " + where(m, e) + " duplicates another triangle");
  }
}

}  // namespace homesh
