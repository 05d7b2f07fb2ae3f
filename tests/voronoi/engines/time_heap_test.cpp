#include "voronoi/engines/time_heap.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <vector>

using namespace homesh;

TEST_CASE("the time heap gives its items back in increasing time, pushes between pops",
          "[voronoi][fmm]") {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> time(0.0, 1.0);
  TimeHeap heap;
  std::vector<double> held;  // the multiset the heap should hold
  double last = -1.0;
  int popped = 0, pushed = 0;
  for (int round = 0; round < 3; ++round) {
    for (int step = 0; step < 5000; ++step) {
      // Pushes above the last time popped (as fast marching does) and pops.
      if (held.empty() || step % 3 != 0) {
        const double t = std::max(last, 0.0) + time(gen);
        heap.push({t, step});
        held.push_back(t);
        ++pushed;
        continue;
      }
      REQUIRE(!heap.empty());
      const double t = heap.top().first;
      heap.pop();
      CHECK(t >= last);
      const auto it = std::min_element(held.begin(), held.end());
      CHECK(t == *it);
      held.erase(it);
      last = t;
      ++popped;
    }
    CHECK(heap.size() == held.size());
    // Drained, released, then used again.
    while (!heap.empty()) {
      CHECK(heap.top().first >= last);
      last = heap.top().first;
      heap.pop();
      ++popped;
    }
    held.clear();
    heap.release();
    CHECK(heap.size() == 0);
  }
  CHECK(popped == pushed);
  CHECK(pushed > 10000);
  // The children of a node share a cache line: the root's four children
  // start on a 64-byte boundary.
  TimeHeap one;
  for (int k = 0; k < 5; ++k) one.push({1.0 * k, k});
  CHECK(reinterpret_cast<std::uintptr_t>(&one.top() + 1) % 64 == 0);
}
