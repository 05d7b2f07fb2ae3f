#pragma once
// Tables of an element kernel that depend only on the order p (Bezier conversions,
// product terms), built once per order on first use, thread-safe, kept for the
// process: order_tables<T>(p) is T(p), built the first time any thread asks for it.
#include <array>
#include <memory>
#include <mutex>

#include "quality/bezier_jacobian.h"

namespace homesh {

/// T's tables for order 1 <= p <= kMaxBezierJacobianOrder (the caller checks p).
template <class T>
const T& order_tables(int p) {
  static std::array<std::once_flag, kMaxBezierJacobianOrder + 1> once;
  static std::array<std::unique_ptr<const T>, kMaxBezierJacobianOrder + 1> tables;
  std::call_once(once[p], [p] { tables[p] = std::make_unique<const T>(p); });
  return *tables[p];
}

}  // namespace homesh
