#pragma once
// The gallery of high-order test elements T1-T12 of thesis Fig 3.12 (Section
// 3.7.2), read from its data file (geo/gallery_t1_t12.csv, whose comments say
// how each element was built from the thesis's description).
//
// File format: CSV with the header "element,order,node,x,y" and one row per
// node, nodes of an element in Gmsh order on consecutive rows (node = 0, 1,
// ...). Lines starting with '#' are comments; the comment block just above an
// element's first row is its description.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace homesh {

struct GalleryElement {
  std::string name;         ///< "T1" .. "T12"
  int order = 0;            ///< p
  Eigen::Matrix2Xd nodes;   ///< 2 by (p+1)(p+2)/2, Gmsh order
  std::string description;  ///< the comment block above it, '#' stripped
};

/// The elements of the gallery file at `path`, in file order. Throws
/// homesh::Error naming the file and line on a malformed file (bad header or
/// number, nodes out of order, wrong node count for the order).
std::vector<GalleryElement> read_gallery(const std::string& path);

/// The element called `name` in `gallery`; throws homesh::Error if none.
const GalleryElement& gallery_element(const std::vector<GalleryElement>& gallery,
                                      const std::string& name);

}  // namespace homesh
