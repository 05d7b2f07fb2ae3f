#pragma once
// A 4-ary min-heap of (time, index) pairs, the priority queue of the
// fast-marching engine (voronoi/fast_marching_engine.cpp): half the depth of
// a binary heap, and the four children of a node share a cache line. Ties
// leave in no particular order.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace homesh {

class TimeHeap {
 public:
  using Item = std::pair<double, int>;
  bool empty() const { return items_.empty(); }
  std::size_t size() const { return items_.size(); }
  /// The item of least time; the heap must not be empty.
  const Item& top() const { return items_.front(); }
  void push(const Item& item) {
    std::size_t k = items_.size();
    items_.push_back(item);
    while (k > 0 && item.first < items_[(k - 1) / 4].first) {
      items_[k] = items_[(k - 1) / 4];
      k = (k - 1) / 4;
    }
    items_[k] = item;
  }
  /// Removes the top item; the heap must not be empty.
  void pop() {
    const Item last = items_.back();
    items_.pop_back();
    if (items_.empty()) return;
    std::size_t k = 0;
    for (;;) {
      const std::size_t first = 4 * k + 1;
      if (first >= items_.size()) break;
      std::size_t best = first;
      const std::size_t end = std::min(first + 4, items_.size());
      for (std::size_t c = first + 1; c < end; ++c)
        if (items_[c].first < items_[best].first) best = c;
      if (!(items_[best].first < last.first)) break;
      items_[k] = items_[best];
      k = best;
    }
    items_[k] = last;
  }
  /// Drops every item and gives the memory back.
  void release() { std::vector<Item>().swap(items_); }

 private:
  std::vector<Item> items_;
};

}  // namespace homesh
