#pragma once
// Test fixture: a Gmsh session for one test case, quiet, finalized at the end.
#include <gmsh.h>

#include <cmath>

namespace homesh::test {

struct GmshSession {
  GmshSession() {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
  }
  ~GmshSession() { gmsh::finalize(); }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

/// A unit square with a circular hole, physical groups "plate" and "hole",
/// meshed by Gmsh at order p (curved on the CAD for p > 1).
inline void make_plate_with_hole(int p, double size = 0.25) {
  gmsh::model::add("plate");
  gmsh::model::occ::addRectangle(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::addDisk(0.5, 0.5, 0, 0.2, 0.2, 2);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({{2, 1}}, {{2, 2}}, out, map);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves;
  gmsh::model::getBoundary(out, curves, false, false, false);
  const int plate = gmsh::model::addPhysicalGroup(2, {out[0].second});
  gmsh::model::setPhysicalName(2, plate, "plate");
  std::vector<int> hole;
  for (const auto& c : curves) {
    double xmin, ymin, zmin, xmax, ymax, zmax;
    gmsh::model::getBoundingBox(1, std::abs(c.second), xmin, ymin, zmin, xmax, ymax, zmax);
    if (xmin > 0.1 && xmax < 0.9) hole.push_back(std::abs(c.second));
  }
  const int h = gmsh::model::addPhysicalGroup(1, hole);
  gmsh::model::setPhysicalName(1, h, "hole");
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::model::mesh::generate(2);
  if (p > 1) gmsh::model::mesh::setOrder(p);
}

/// The plate of make_plate_with_hole with a boundary layer of quadrilaterals
/// round the hole (Gmsh's BoundaryLayer field, Quads = 1: the mixed meshes of
/// 2D CFD), triangles elsewhere; all quadrilaterals if `recombine_all`.
/// Meshed at order p (curved on the CAD for p > 1).
inline void make_plate_with_quad_layer(int p, double size = 0.15, bool recombine_all = false) {
  gmsh::model::add("plate");
  gmsh::model::occ::addRectangle(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::addDisk(0.5, 0.5, 0, 0.2, 0.2, 2);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({{2, 1}}, {{2, 2}}, out, map);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves;
  gmsh::model::getBoundary(out, curves, false, false, false);
  std::vector<double> hole;
  for (const auto& c : curves) {
    double xmin, ymin, zmin, xmax, ymax, zmax;
    gmsh::model::getBoundingBox(1, std::abs(c.second), xmin, ymin, zmin, xmax, ymax, zmax);
    if (xmin > 0.1 && xmax < 0.9) hole.push_back(std::abs(c.second));
  }
  const int f = gmsh::model::mesh::field::add("BoundaryLayer");
  gmsh::model::mesh::field::setNumbers(f, "CurvesList", hole);
  gmsh::model::mesh::field::setNumber(f, "Size", 0.01);
  gmsh::model::mesh::field::setNumber(f, "Ratio", 1.3);
  gmsh::model::mesh::field::setNumber(f, "Thickness", 0.05);
  gmsh::model::mesh::field::setNumber(f, "Quads", 1);
  gmsh::model::mesh::field::setAsBoundaryLayer(f);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  gmsh::option::setNumber("Mesh.RecombineAll", recombine_all ? 1 : 0);
  gmsh::model::mesh::generate(2);
  if (p > 1) gmsh::model::mesh::setOrder(p);
}

}  // namespace homesh::test
