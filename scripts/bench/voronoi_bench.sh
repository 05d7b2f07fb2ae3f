#!/bin/sh
# Scaling of the crystal-growth engines (thesis Fig 2.9, Section 2.8) against
# CGAL's Delaunay triangulation of the same seeds, in one run: CSV and PNG.
#
# usage: scripts/bench/voronoi_bench.sh BUILD_DIR [OUT_DIR]
#
# Seeds uniform in the unit square on one grid (default 2000 x 2000 nodes);
# then fast marching on the general path (the thesis' aerofoil with its
# domain, isotropic and anisotropic; 1000 seeds in the square under a turning
# metric field, and round a hole), best of three, in voronoi_bench_general.csv.
# Environment (passed on to the hidden test cases "[.voronoi_bench]" and
# "[.voronoi_bench_general]" of tests/voronoi/voronoi_dump_test.cpp):
#   HOMESH_VORONOI_BENCH_GRID           grid nodes per side (2000)
#   HOMESH_VORONOI_BENCH_SEEDS          seed counts (10,100,1000,10000,100000)
#   HOMESH_VORONOI_BENCH_LEVEL_SET_MAX  largest count for level_set (10000)
#   HOMESH_VORONOI_BENCH_CASE           one general-path case alone
set -eu
if [ $# -lt 1 ]; then
  sed -n '2,20p' "$0"
  exit 2
fi
build=$1
out=${2:-$build/voronoi_bench}
mkdir -p "$out"
HOMESH_VORONOI_OUT="$out" "$build/tests/test_numeric" "[.voronoi_bench]"
# Fast marching's full update (a domain, a metric field): voronoi_bench_general.csv.
HOMESH_VORONOI_OUT="$out" "$build/tests/test_numeric" "[.voronoi_bench_general]"
cat "$out/voronoi_bench_general.csv"
/usr/bin/python3 "$(dirname "$0")/voronoi_bench.py" "$out/voronoi_bench.csv" \
  "$out/voronoi_bench.png"
