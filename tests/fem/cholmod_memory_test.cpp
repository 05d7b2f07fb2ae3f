// CHOLMOD's allocation functions (fem/cholmod_memory.h): small blocks are malloc's,
// large ones mapped 2 MiB aligned, kept once freed (at most kKeptBytes) and reused;
// realloc and calloc semantics hold across the two; routed, CHOLMOD factorises and
// solves in them.
#include "fem/cholmod_memory.h"

#include <Eigen/SparseCore>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "fem/cholmod_solver.h"

using namespace homesh;
namespace cm = homesh::cholmod_memory;

namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

bool aligned(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % cm::kHugePage == 0; }

// The 5-point Laplacian of an n by n grid plus the identity (lower triangle).
Eigen::SparseMatrix<double> grid_laplacian(int n) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [n](int i, int j) { return i * n + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      t.emplace_back(id(i, j), id(i, j), 5.0);
      if (i + 1 < n) t.emplace_back(id(i + 1, j), id(i, j), -1.0);
      if (j + 1 < n) t.emplace_back(id(i, j + 1), id(i, j), -1.0);
    }
  Eigen::SparseMatrix<double> K(n * n, n * n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

}  // namespace

#if defined(__linux__)
TEST_CASE("cholmod memory: large blocks mapped aligned, kept and reused; small ones malloc",
          "[fem]") {
  const cm::Stats before = cm::stats();
  void* small = cm::allocate(1000);
  REQUIRE(small != nullptr);
  CHECK(cm::stats().mapped_blocks == before.mapped_blocks);
  cm::release(small);

  const std::size_t bytes = 3 * kMiB + 5;
  auto* big = static_cast<unsigned char*>(cm::allocate(bytes));
  REQUIRE(big != nullptr);
  CHECK(aligned(big));
  CHECK(cm::stats().mapped_blocks == before.mapped_blocks + 1);
  std::memset(big, 7, bytes);
  cm::release(big);
  CHECK(cm::stats().mapped_blocks == before.mapped_blocks);
  CHECK(cm::stats().kept_bytes >= before.kept_bytes + 4 * kMiB);  // rounded to 2 MiB pages

  // The same size again: the kept block, handed out zeroed by calloc.
  auto* again = static_cast<unsigned char*>(cm::allocate_zeroed(bytes, 1));
  CHECK(again == big);
  bool zero = true;
  for (std::size_t i = 0; i < bytes; ++i) zero = zero && again[i] == 0;
  CHECK(zero);
  cm::release(again);

  // Freed blocks past kKeptBytes go back: the kept bytes never exceed it.
  std::vector<void*> blocks;
  for (std::size_t total = 0; total <= cm::kKeptBytes + 64 * kMiB; total += 32 * kMiB)
    blocks.push_back(cm::allocate(32 * kMiB));
  for (void* p : blocks) cm::release(p);
  CHECK(cm::stats().kept_bytes <= cm::kKeptBytes);
  CHECK(cm::stats().kept_bytes >= cm::kKeptBytes - 32 * kMiB);
  CHECK(cm::allocate_zeroed(std::size_t{1} << 62, 8) == nullptr);  // count * size overflows
}

TEST_CASE("cholmod memory: reallocate keeps the contents between malloc and mapped blocks",
          "[fem]") {
  // malloc's block grown past 2 MiB: mapped, its bytes copied.
  auto* p = static_cast<unsigned char*>(cm::reallocate(nullptr, 100));
  for (int i = 0; i < 100; ++i) p[i] = static_cast<unsigned char>(i);
  p = static_cast<unsigned char*>(cm::reallocate(p, 5 * kMiB));
  REQUIRE(p != nullptr);
  CHECK(aligned(p));
  bool same = true;
  for (int i = 0; i < 100; ++i) same = same && p[i] == i;
  CHECK(same);
  // A mapped block shrinks in place and grows by a copy.
  p[5 * kMiB - 1] = 42;
  CHECK(cm::reallocate(p, 4 * kMiB) == p);
  p = static_cast<unsigned char*>(cm::reallocate(p, 9 * kMiB));
  REQUIRE(p != nullptr);
  same = true;
  for (int i = 0; i < 100; ++i) same = same && p[i] == i;
  CHECK(same);
  CHECK(p[5 * kMiB - 1] == 42);
  cm::release(p);
  // Small stays malloc's (realloc in place or moved, contents kept).
  auto* q = static_cast<char*>(cm::reallocate(nullptr, 16));
  std::strcpy(q, "homesh");
  q = static_cast<char*>(cm::reallocate(q, 4096));
  CHECK(std::strcmp(q, "homesh") == 0);
  cm::release(q);
  cm::release(nullptr);  // as free(nullptr)
}
#endif

TEST_CASE("cholmod memory: routed unless HOMESH_MALLOC=default; CHOLMOD solves in it", "[fem]") {
  const char* env = std::getenv("HOMESH_MALLOC");
  const bool declined = env && std::strcmp(env, "default") == 0;
#if defined(__linux__)
  const bool expected = cholmod_available() && !declined;
#else
  const bool expected = false;
  (void)declined;
#endif
  CHECK(route_cholmod_memory() == expected);
  CHECK(route_cholmod_memory() == expected);  // once: the same answer
  if (!cholmod_available()) return;
  // 160 x 160 unknowns: CHOLMOD's factor and copies are several MiB.
  const Eigen::SparseMatrix<double> K = grid_laplacian(160);
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
  const Eigen::VectorXd b = K.selfadjointView<Eigen::Lower>() * x_exact;
  const cm::Stats before = cm::stats();
  Eigen::VectorXd x;
  {
    CholmodFactor f;
    f.analyze(K);
    f.factorize(K);
    x = f.solve(b);
    if (expected) CHECK(cm::stats().mapped_blocks > before.mapped_blocks);
  }
  CHECK((x - x_exact).norm() <= 1e-10 * x_exact.norm());
  CHECK(cm::stats().mapped_blocks == before.mapped_blocks);  // every block given back
}
