// Plate with a hole in a C++ Gmsh-API program, curved to order 3 by homesh.
//
//   1. CAD with gmsh::model::occ: the square [-1, 1]^2 minus the disk of
//      radius 0.5, physical curves "hole" and "farfield", surface "plate";
//   2. a linear mesh by Gmsh;
//   3. homesh::api::curve: order 3, boundary nodes on the circle, interior by
//      the elastic analogy, certified valid;
//   4. homesh::api::quality: minJ/maxJ and Q4 views, the certified validity;
//   5. homesh::api::write: the .msh with its views and the .opt sidecar.
//
// Usage: plate_curve [OUTPUT.msh] (default plate_curve.msh). Exit status 0 if
// the mesh was written and every triangle is certified valid.
#include <gmsh.h>
#include <homesh/homesh.h>

#include <cmath>
#include <iostream>
#include <string>
#include <variant>
#include <vector>

namespace {

constexpr double kHalfSide = 1.0, kRadius = 0.5, kSize = 0.1;

void plate_with_hole() {
  namespace occ = gmsh::model::occ;
  const int square = occ::addRectangle(-kHalfSide, -kHalfSide, 0, 2 * kHalfSide, 2 * kHalfSide);
  const int disk = occ::addDisk(0, 0, 0, kRadius, kRadius);
  gmsh::vectorpair plate;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{2, square}}, {{2, disk}}, plate, map);
  occ::synchronize();

  gmsh::vectorpair boundary;
  gmsh::model::getBoundary(plate, boundary, false, false);
  std::vector<int> hole, farfield;
  for (const auto& [dim, tag] : boundary) {
    std::string type;
    gmsh::model::getType(dim, tag, type);
    (type == "Line" ? farfield : hole).push_back(tag);
  }
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, hole), "hole");
  gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, farfield), "farfield");
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {plate[0].second}), "plate");

  gmsh::vectorpair points;
  gmsh::model::getEntities(points, 0);
  for (const auto& point : points) {
    std::vector<double> x;
    gmsh::model::getValue(0, point.second, {}, x);
    const bool on_hole = std::hypot(x[0], x[1]) < kRadius + 1e-9;
    gmsh::model::mesh::setSize({point}, on_hole ? kSize : 2 * kSize);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "plate_curve.msh";
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  homesh::api::set_quiet();  // the stages' own reports; this program prints its own
  int status = 0;
  try {
    gmsh::model::add("plate_curve");
    plate_with_hole();
    gmsh::model::mesh::generate(2);

    const homesh::api::Result curved = homesh::api::curve({{"p", "3"}});
    std::cout << "curved: order " << curved.order << ", " << curved.triangles << " triangles, "
              << curved.nodes << " nodes\n";
    const homesh::api::Result q = homesh::api::quality({{"measures", "Q4"}});
    std::cout << "quality views:";
    for (int tag : q.views) std::cout << " " << tag;
    // Results are std::variant<bool, int, double>: counts int, measurements double.
    std::cout << "; Q4 min " << std::get<double>(q.results.at("Q4_min")) << ", "
              << std::get<int>(q.results.at("invalid")) << " invalid\n"
              << q.validity.line << "\n";
    homesh::api::write(out, "plate_curve (homesh C++ API example)");
    std::cout << "wrote " << out << "\n";
    status = q.validity.invalid == 0 ? 0 : 1;
  } catch (const homesh::Error& e) {
    std::cerr << "plate_curve: " << e.what() << "\n";
    status = 1;
  }
  gmsh::finalize();
  return status;
}
