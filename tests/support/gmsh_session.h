#pragma once
// Test fixture: a Gmsh session for one test case, quiet, finalized at the end.
#include <gmsh.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

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

/// A unit square with a circular hole of radius 0.2 (OpenCASCADE), synchronized:
/// returns the plate's surface tag and fills `hole` with the hole's curve tags.
inline int make_plate_cad(std::vector<int>& hole) {
  gmsh::model::add("plate");
  gmsh::model::occ::addRectangle(0, 0, 0, 1, 1, 1);
  gmsh::model::occ::addDisk(0.5, 0.5, 0, 0.2, 0.2, 2);
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> map;
  gmsh::model::occ::cut({{2, 1}}, {{2, 2}}, out, map);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves;
  gmsh::model::getBoundary(out, curves, false, false, false);
  hole.clear();
  for (const auto& c : curves) {
    double xmin, ymin, zmin, xmax, ymax, zmax;
    gmsh::model::getBoundingBox(1, std::abs(c.second), xmin, ymin, zmin, xmax, ymax, zmax);
    if (xmin > 0.1 && xmax < 0.9) hole.push_back(std::abs(c.second));
  }
  return out[0].second;
}

/// A unit square with a circular hole, physical groups "plate" and "hole",
/// meshed by Gmsh at order p (curved on the CAD for p > 1).
inline void make_plate_with_hole(int p, double size = 0.25) {
  std::vector<int> hole;
  const int surface = make_plate_cad(hole);
  const int plate = gmsh::model::addPhysicalGroup(2, {surface});
  gmsh::model::setPhysicalName(2, plate, "plate");
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
  std::vector<int> hole;
  make_plate_cad(hole);
  const int f = gmsh::model::mesh::field::add("BoundaryLayer");
  gmsh::model::mesh::field::setNumbers(f, "CurvesList",
                                       std::vector<double>(hole.begin(), hole.end()));
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

/// Gmsh's AnalyseMeshQuality plugin's minJ/maxJ of every 2D element of the current
/// model: its view's element tags and one value per element (data[k][0]); the view
/// is the only one. Returns false if the plugin made no single view.
inline bool analyse_mesh_quality(std::vector<std::size_t>& tags,
                                 std::vector<std::vector<double>>& data) {
  gmsh::plugin::setNumber("AnalyseMeshQuality", "JacobianDeterminant", 1);
  gmsh::plugin::setNumber("AnalyseMeshQuality", "CreateView", 1);
  gmsh::plugin::run("AnalyseMeshQuality");
  std::vector<int> views;
  gmsh::view::getTags(views);
  if (views.size() != 1) return false;
  std::string type;
  double time;
  int components;
  gmsh::view::getModelData(views[0], 0, type, tags, data, time, components);
  return true;
}

}  // namespace homesh::test
