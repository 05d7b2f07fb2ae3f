#pragma once
// A 4-ary min-heap of (time, index) pairs, the priority queue of the
// fast-marching engine (voronoi/engines/fast_marching_engine.cpp): half the depth of
// a binary heap, and the four children of a node share a cache line. Ties
// leave in no particular order.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/huge_page_allocator.h"

namespace homesh {

class TimeHeap {
 public:
  using Item = std::pair<double, int>;
  bool empty() const { return items_.size() <= kPad; }
  std::size_t size() const { return empty() ? 0 : items_.size() - kPad; }
  /// The item of least time; the heap must not be empty.
  const Item& top() const { return items_[kPad]; }
  void push(const Item& item) {
    if (items_.empty()) items_.resize(kPad);
    std::size_t k = items_.size();
    items_.push_back(item);
    while (k > kPad && item.first < items_[parent(k)].first) {
      items_[k] = items_[parent(k)];
      k = parent(k);
    }
    items_[k] = item;
  }
  /// Removes the top item; the heap must not be empty.
  void pop() {
    const Item last = items_.back();
    items_.pop_back();
    if (empty()) return;
    std::size_t k = kPad;
    for (;;) {
      const std::size_t first = first_child(k);
      if (first >= items_.size()) break;
      // The least child, by selects rather than branches (which child is
      // least is a coin toss the branch predictor loses).
      std::size_t best = first;
      double least = items_[first].first;
      const std::size_t end = std::min(first + 4, items_.size());
      for (std::size_t c = first + 1; c < end; ++c) {
        const double t = items_[c].first;
        const bool less = t < least;
        best = less ? c : best;
        least = less ? t : least;
      }
      if (!(least < last.first)) break;
      items_[k] = items_[best];
      k = best;
    }
    items_[k] = last;
  }
  /// Drops every item and gives the memory back.
  void release() { HugeVector<Item>().swap(items_); }

 private:
  // Heap position p (root 0, children 4p + 1 .. 4p + 4) is stored at
  // items_[p + kPad]: the children of a node then sit at 4(p + 1) ..
  // 4(p + 1) + 3, one 64-byte cache line of the line-aligned array.
  static constexpr std::size_t kPad = 3;
  static std::size_t parent(std::size_t k) { return (k - kPad - 1) / 4 + kPad; }
  static std::size_t first_child(std::size_t k) { return 4 * (k - kPad) + 1 + kPad; }

  HugeVector<Item> items_;
};

}  // namespace homesh
