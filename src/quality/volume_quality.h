#pragma once
// The thesis' measures over every tetrahedron of a volume mesh (issue 24), as
// quality/mesh_quality.h does over planar meshes: each measure sampled at the
// points of a reference lattice and at the element's nodes, through W =
// J inv(J_ri) to the regular tetrahedron (quality/volume_measures.h).
#include <vector>

#include "core/volume_mesh.h"
#include "quality/element_quality.h"
#include "quality/measure_registry.h"
#include "quality/mesh_quality.h"

namespace homesh {

/// Each measure of `qs` over every tetrahedron of m, sampled at the nodes of
/// the order-`lattice` reference lattice (a multiple of m's order holds the
/// element's nodes) and at the element's nodes, normalised as `ref` says (the
/// thesis' Q / Qmax over the element's samples for Q2, Q3, Q4, Q5 and Q17 with
/// Reference::element_max). Q1 is min det J / max det J over the samples, 0 if
/// min det J <= 0, at every node. element_min is per tetrahedron, node_values
/// (p+1)(p+2)(p+3)/6 by #tetrahedra. Throws homesh::Error if lattice < 1.
std::vector<MeshMeasure> volume_quality(const VolumeMesh& m, const std::vector<const Measure*>& qs,
                                        int lattice, Reference ref, int threads = 0);

}  // namespace homesh
