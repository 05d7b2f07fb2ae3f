#!/bin/sh
# The installed library as a user meets it: `cmake --install` into a fresh
# prefix, scripts/examples/cpp configured and built against it with
# find_package(homesh), run; the mesh it writes is certified valid by the
# example itself and, read back, by the installed CLI. With the Python module
# built, PYTHON imports the installed one from PYTHON_DIR under the prefix (the
# interpreter's site directory there: on its path when the prefix is /usr or
# /usr/local, given by PYTHONPATH here) and curves a mesh with it.
# Usage: install_example_test.sh CMAKE GENERATOR CXX CXXFLAGS LDFLAGS BUILD_DIR SOURCE_DIR
#                                [PYTHON PYTHON_DIR]
# (the compiler and flags of the build, so a sanitizer build links its example).
set -eu
cmake=$1 generator=$2 cxx=$3 cxxflags=$4 ldflags=$5 build=$6 source=$7
python=${8:-} python_dir=${9:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; for f in "$tmp"/*.log; do echo "--- $f"; cat "$f"; done; exit 1; }

"$cmake" --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log" || fail "install"
for f in bin/homesh include/homesh/homesh.h include/homesh/core/error.h \
         lib/cmake/homesh/homeshConfig.cmake lib/cmake/homesh/FindGmsh.cmake; do
  [ -e "$tmp/prefix/$f" ] || fail "install lacks $f"
done
"$cmake" -S "$source/scripts/examples/cpp" -B "$tmp/example" -G "$generator" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_CXX_FLAGS="$cxxflags" -DCMAKE_EXE_LINKER_FLAGS="$ldflags" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" \
  > "$tmp/configure.log" 2>&1 || fail "configure the example"
"$cmake" --build "$tmp/example" > "$tmp/build.log" 2>&1 || fail "build the example"
"$tmp/example/plate_curve" "$tmp/plate.msh" > "$tmp/run.log" 2>&1 || fail "run the example"
grep -Eq '^curved: order 3, [0-9]+ triangles' "$tmp/run.log" || fail "no order-3 mesh"
triangles=$(sed -n 's/^validity: 0 invalid of \([0-9]*\) triangles.*/\1/p' "$tmp/run.log")
[ -n "$triangles" ] && [ "$triangles" -gt 100 ] || fail "example's mesh not certified valid"
[ -s "$tmp/plate.msh" ] && [ -s "$tmp/plate.msh.opt" ] || fail "no .msh or .opt written"
"$tmp/prefix/bin/homesh" "$tmp/plate.msh" -m info -m quality:measures=Q4 > "$tmp/cli.log" 2>&1 \
  || fail "installed CLI on the example's mesh"
grep -q "order 3: " "$tmp/cli.log" || fail "CLI does not read order 3"
grep -q "validity: 0 invalid of $triangles triangles" "$tmp/cli.log" || fail "CLI validity"
echo "install example: $triangles triangles of order 3, certified valid"

[ -n "$python" ] || exit 0
site="$tmp/prefix/$python_dir"
ls "$site"/homesh*.so > /dev/null 2>&1 || fail "install lacks the Python module in $python_dir"
(cd "$tmp" && PYTHONPATH="$site" "$python" -c '
import os, sys
import gmsh, homesh
assert os.path.dirname(os.path.realpath(homesh.__file__)) == os.path.realpath(sys.argv[1]), homesh.__file__
gmsh.initialize()
gmsh.option.setNumber("General.Terminal", 0)
homesh.set_quiet(True)
gmsh.open(sys.argv[2])
gmsh.model.mesh.generate(2)
homesh.curve(p=2)
print(int(homesh.quality(measures="Q4")["results"]["invalid"]), homesh.__file__)
gmsh.finalize()
' "$site" "$source/geo/plate_hole.geo") > "$tmp/python.log" 2>&1 || fail "import the installed module"
grep -q "^0 $site/homesh" "$tmp/python.log" || fail "installed module's curved mesh not valid"
echo "install example: the installed Python module curves a valid mesh"
