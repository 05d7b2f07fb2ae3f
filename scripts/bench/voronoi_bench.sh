#!/bin/sh
# Scaling of the crystal-growth engines (thesis Fig 2.9, Section 2.8) against
# CGAL's Delaunay triangulation of the same seeds, in one run: CSV and PNG.
#
# usage: scripts/bench/voronoi_bench.sh BUILD_DIR [OUT_DIR]
#
# Seeds uniform in the unit square on one grid (default 2000 x 2000 nodes).
# Environment (passed on to the hidden test case "[.voronoi_bench]" of
# tests/voronoi/voronoi_dump_test.cpp):
#   HOMESH_VORONOI_BENCH_GRID           grid nodes per side (2000)
#   HOMESH_VORONOI_BENCH_SEEDS          seed counts (10,100,1000,10000,100000)
#   HOMESH_VORONOI_BENCH_LEVEL_SET_MAX  largest count for level_set (10000)
set -eu
if [ $# -lt 1 ]; then
  sed -n '2,13p' "$0"
  exit 2
fi
build=$1
out=${2:-$build/voronoi_bench}
mkdir -p "$out"
HOMESH_VORONOI_OUT="$out" "$build/tests/test_numeric" "[.voronoi_bench]"
/usr/bin/python3 "$(dirname "$0")/voronoi_bench.py" "$out/voronoi_bench.csv" \
  "$out/voronoi_bench.png"
