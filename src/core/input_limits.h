#pragma once
// The ranges homesh accepts in its input, checked before any stage runs, so
// that a hostile or corrupt input gets a clear error instead of a hang (Gmsh's
// 1D mesher never ends on coordinates of 1e300) or of an overflow.
// Chosen, not taken from the thesis: a planar model at most 1e12 units from
// the origin, at least 1e-100 across (triangle areas, squares of lengths, stay
// normal doubles) and at least 1e-10 of its distance from the origin across
// (its vertices then differ in at least 6 of a double's 16 digits).

namespace homesh::limits {

constexpr double kMaxCoordinate = 1e12;
constexpr double kMinExtent = 1e-100;
constexpr double kMinRelativeExtent = 1e-10;

}  // namespace homesh::limits
