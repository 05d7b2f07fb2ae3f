#pragma once
// The arrival times of the crystals at the grid nodes, for the fast-marching
// engine (voronoi/engines/fast_marching_engine.cpp): any number of crystals per node,
// most nodes holding one or two. Entry x, for x below the node count N, is
// node x's first slot, in grid order, so that the entries of neighbouring
// nodes share cache lines; a node's further entries are overflow entries
// N, N + 1, ..., linked from its slot through `next`. 32 bytes an entry.
#include <cstdint>
#include <limits>
#include <vector>

#include "core/huge_page_allocator.h"

namespace homesh {

/// The arrival time of one crystal at one node and the source it is measured
/// from; in a node's slot also the node's winner (the engine's, kept here to
/// share the slot's cache line). The crystal, the hop count and the accepted
/// flag share one word: up to kMaxCrystals crystals.
struct CrystalEntry {
  static constexpr int kMaxCrystals = (1 << 24) - 2;
  double time = std::numeric_limits<double>::infinity();
  double source_time = 0.0;
  int source = -1;  ///< a node, or -1 - c for the seed of crystal c
  int next = -1;    ///< the node's next entry, or -1
  /// In a node's slot: the crystal of least accepted time at the node so far
  /// (-1: none).
  int winner = -1;

  /// The crystal; -1: a free slot.
  int label() const { return static_cast<int>(bits_ & kLabel) - 1; }
  void set_label(int c) { bits_ = (bits_ & ~kLabel) | static_cast<std::uint32_t>(c + 1); }
  /// Stencil steps from the crystal's own region (0 inside it): the smallest
  /// over the accepted entries that updated this one, plus 1 (at most 127).
  int hop() const { return static_cast<int>((bits_ >> 24) & 0x7f); }
  void set_hop(int h) {
    bits_ = (bits_ & ~(0x7fu << 24)) | static_cast<std::uint32_t>(h < 127 ? h : 127) << 24;
  }
  /// Time final.
  bool accepted() const { return (bits_ >> 31) != 0; }
  void accept() { bits_ |= 1u << 31; }

 private:
  static constexpr std::uint32_t kLabel = (1u << 24) - 1;
  std::uint32_t bits_ = 0x7fu << 24;  ///< label + 1 (24 bits), hop (7), accepted (1)
};
static_assert(sizeof(CrystalEntry) == 32, "two entries to a cache line");

class CrystalEntries {
 public:
  explicit CrystalEntries(int nodes) : slot_(nodes) {}

  CrystalEntry& operator[](int e) { return e < size() ? slot_[e] : extra_[e - size()]; }
  const CrystalEntry& operator[](int e) const { return e < size() ? slot_[e] : extra_[e - size()]; }
  /// The node of entry e.
  int node(int e) const { return e < size() ? e : extra_node_[e - size()]; }
  /// Node x's winner (CrystalEntry::winner).
  int& winner(int x) { return slot_[x].winner; }
  int winner(int x) const { return slot_[x].winner; }
  /// The first entry at node x, or -1; the others follow through `next`.
  int head(int x) const { return slot_[x].label() < 0 ? -1 : x; }
  /// The entry of crystal c at node x, or -1.
  int find(int x, int c) const {
    const CrystalEntry& first = slot_[x];
    if (first.label() == c) return x;
    if (first.label() < 0) return -1;
    for (int e = first.next; e >= 0; e = extra_[e - size()].next)
      if (extra_[e - size()].label() == c) return e;
    return -1;
  }
  /// Whether node x holds an entry of time below t.
  bool any_below(int x, double t) const {
    for (int e = head(x); e >= 0; e = (*this)[e].next)
      if ((*this)[e].time < t) return true;
    return false;
  }
  /// A new entry of crystal c at node x (which must hold none); entries
  /// added later may move the earlier overflow entries: hold indices, not
  /// references, across calls.
  int add(int x, int c) {
    if (slot_[x].label() < 0) {
      slot_[x].set_label(c);
      return x;
    }
    CrystalEntry en;
    en.set_label(c);
    en.next = slot_[x].next;
    extra_.push_back(en);
    extra_node_.push_back(x);
    slot_[x].next = size() + static_cast<int>(extra_.size()) - 1;
    return slot_[x].next;
  }

 private:
  int size() const { return static_cast<int>(slot_.size()); }

  HugeVector<CrystalEntry> slot_, extra_;
  HugeVector<int> extra_node_;
};

}  // namespace homesh
