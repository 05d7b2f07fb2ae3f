#pragma once
// Insertion of boundary layers into an existing triangle mesh (thesis
// Section 4.3): the walls' front is detached (front_split.h) and pushed into the
// domain by the elastic analogy (open_room.h) by the total thickness, the free
// nodes in its way removed (clear_room.h), then the room between wall and front
// is filled layer by layer from the wall outward, along single or multiple
// normals (wall_normals.h).
//
// Layer depths grow geometrically: layer k (k = 1 at the wall) is
// first * ratio^(k-1) thick, so the interfaces lie at depths
// d_k = first (ratio^k - 1) / (ratio - 1) (first * k if ratio = 1) and the total
// thickness is d_n. On a normal line of direction n and scale s the layer nodes
// sit at x_wall + d_k s n.
//
// Elements: each wall edge gets n quads between the normal lines of its ends
// (the outgoing-side normal of its first node, the incoming-side normal of its
// second), kept as quadrilaterals with LayerOptions::quads (not in fans), else two triangles each,
// the diagonal chosen for the better worst radius ratio (Eq 4.17) among valid choices (the swap of
// Fig 4.5c). Between consecutive normals of a fan: a triangle at the wall node, then n - 1 quads.
// Triangle count: T - 2 c + 2 n E + 2 n (m - 1) per fan of m normals (the m - 1 gap triangles of
// the split included), E the number of wall edges, c the free nodes removed from the room
// (clear_room.h); node count: V - c + n L, L the number of normal lines.
//
// Where a normal meets another boundary closer than d_n / fill, or its
// neighbours' normals cross (a concave wall) closer than that, the layers of
// that line are thinned to fit (stack_fit.h) and the result lists where.
//
// Open walls (wall_loops.h) end on a non-wall boundary: their end normals run
// along it (wall_normals.h), the end front nodes slide along it while the room
// opens, and its boundary line at each end is split at the end's n nodes
// (lines: + n per end), which are classified on its curve.
//
// The walls keep their nodes (and their indices), classification (curve and parameter), lines,
// points and physical groups; other new nodes lie on the surface of the wall's
// triangles, whose tag the layer triangles take. Meshes of order p > 1 are
// reduced to their corners first (the result is linear; curve it afterwards).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/mesh.h"
#include "layers/open_room.h"
#include "layers/wall_normals.h"

namespace homesh {

struct LayerOptions {
  std::vector<std::string> walls;  ///< curve physical group names or curve tags
  int layers = 3;                  ///< n >= 1
  double first = 1e-3;             ///< thickness of the layer at the wall, > 0
  double ratio = 1.2;              ///< growth of thickness from layer to layer, > 0
  /// Largest fraction of the distance along a normal to the nearest other
  /// boundary the stack may take; thinner layers there (stack_fit.h). In (0, 1].
  double fill = 0.4;
  /// Largest fraction of the depth at which neighbouring normals cross (concave
  /// walls and corners) the stack may take; thinner layers there (stack_fit.h).
  /// In (0, 1).
  double cross = 0.6;
  /// The layer cells of the wall edges as quadrilaterals, not split into two triangles
  /// each. A fan stays triangles: its cells between diverging normals are trapezia of
  /// minJ/maxJ d_(k-1) / d_k (1 / (1 + ratio) in layer 2: 0.45 at ratio 1.2, what Gmsh's
  /// quad fans give), where its triangles are the linear map's own (1).
  bool quads = false;
  NormalOptions normals;
  RoomOptions room;
};

/// One normal line of nodes from a wall node into the domain.
struct LayerLine {
  int wall_node = -1;
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  ///< unit
  double scale = 1;                                     ///< node k at depth d_k * scale
  std::vector<int> nodes;  ///< n + 1 nodes: the wall node, the layer nodes, the front node
};

/// Wall nodes where the stack was thinned to fit (stack_fit.h).
struct ThinnedLayers {
  Eigen::Vector2d from, to;  ///< the first and last wall node of the stretch
  Eigen::Vector2d tightest;  ///< the wall node thinned most
  int lines = 0;             ///< normal lines thinned
  double factor = 1;         ///< thickness there over the full stack's, in (0, 1)
  double gap = 0;            ///< distance along the normal there to the nearest boundary
  int curve = -1;            ///< the wall's curve there
  int facing = -1;           ///< the curve met along the normal (-1 if crossing)
  /// The limit is where neighbouring normals cross (a concave wall, stack_fit.h),
  /// gap the distance to it along the normal.
  bool crossing = false;
};

struct LayerResult {
  Mesh mesh;
  /// #2D elements (triangles, then quadrilaterals: core/mesh.h): 0 for the existing
  /// mesh (the input's T - 2 c triangles first, with their surfaces, re-joined by the
  /// push's edge flips; the fans' gap triangles next), k = 1..n for layer k from the wall.
  std::vector<int> layer;
  std::vector<LayerLine> lines;
  int loops = 0;       ///< walls: closed loops and open chains
  int open_walls = 0;  ///< of them open chains (wall_loops.h)
  int wall_edges = 0;
  int fan_nodes = 0;
  int gap_triangles = 0;
  double thickness = 0;  ///< d_n
  int push_steps = 0;    ///< accepted elastic steps opening the room
  int solves = 0;        ///< elasticity solves
  int cleared = 0;       ///< free nodes removed from the room before it opened (clear_room.h)
  int smoothed = 0;      ///< node moves repairing triangles the push squeezed (open_room.h)
  std::vector<ThinnedLayers> thinned;  ///< where the stack was thinned
  bool from_corners = false;           ///< the input was of order > 1
  int sharpest_node = -1;              ///< wall node with the largest domain angle
  double sharpest_angle = 0;           ///< its domain angle, radians
};

/// d_0 = 0, d_1, ..., d_n as above. Throws homesh::Error unless n >= 1,
/// first > 0 and ratio > 0.
std::vector<double> layer_depths(double first, double ratio, int n);

/// m with boundary layers on the walls of opt; every triangle certified valid.
/// Throws homesh::Error with a message naming the cause and the place if the
/// input is not valid, the walls are unusable (wall_loops.h), the room cannot
/// be opened with every element valid, the layers themselves would fold, or
/// not even the first layer fits somewhere (stack_fit.h: checked before the room opens).
LayerResult insert_layers(const Mesh& m, const LayerOptions& opt);

/// The layer elements (layer > 0; 2D element indices) having a node on a normal
/// line of `wall_node`: the elements of that corner, where single and multiple
/// normals differ.
std::vector<int> corner_triangles(const LayerResult& r, int wall_node);

}  // namespace homesh
