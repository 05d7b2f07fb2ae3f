#pragma once
// Comparing two certified validities (quality/mesh_validity.h) number by number.
#include <catch2/catch.hpp>

#include "quality/mesh_validity.h"

namespace homesh::test {

/// Every number of a and b equal, to the bit.
inline void require_same_validity(const MeshValidity& a, const MeshValidity& b) {
  REQUIRE(a.ratio.size() == b.ratio.size());
  CHECK((a.ratio.array() == b.ratio.array()).all());
  CHECK((a.min_det.array() == b.min_det.array()).all());
  CHECK(a.converged == b.converged);
  CHECK(a.invalid == b.invalid);
  CHECK(a.unconverged == b.unconverged);
  CHECK(a.worst == b.worst);
  CHECK(a.worst_element == b.worst_element);
  CHECK(a.relative_tolerance == b.relative_tolerance);
  CHECK(a.max_subdivisions == b.max_subdivisions);
}

}  // namespace homesh::test
