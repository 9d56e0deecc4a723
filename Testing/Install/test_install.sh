#!/usr/bin/env bash
# Installs the build tree into a scratch prefix, builds a consumer project against
# it with find_package(TerraLux), runs it, and imports `terralux` from the prefix.
# Usage: test_install.sh BUILD_DIR SCRATCH_DIR PYTHON DEM PYTHON_DESTINATION
set -euo pipefail
build_dir="$1" scratch="$2" python="$3" dem="$4" python_destination="$5"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$scratch"
mkdir -p "$scratch"
cmake --install "$build_dir" --prefix "$scratch/prefix" >/dev/null
# Every installed header compiles on its own: the engine's with the compiler's own paths
# (GLM, Embree, TBB are Debian's), the VTK modules' with VTK's too.
include="$scratch/prefix/include"
compile_alone() { # header below $include, extra flags...
  local header="$1"; shift
  echo "#include <${header}>" | c++ -std=c++17 -fsyntax-only -I"$include" -I"$include/terralux/engine" "$@" -x c++ - \
    || { echo "installed header ${header} does not compile on its own" >&2; return 1; }
}
export -f compile_alone; export include
engine_headers="$(cd "$include" && find terralux/engine -name '*.h' | sort)"
test -n "$engine_headers"
echo "$engine_headers" | xargs -P 2 -I{} bash -c 'compile_alone {}'
vtk_include="$(find /usr/include -maxdepth 1 -name 'vtk-9*' | head -n 1)"
(cd "$include" && find terralux -maxdepth 1 -name 'vtk*.h' | sort) |
  xargs -P 2 -I{} bash -c "compile_alone {} -I$vtk_include -I$include/terralux"
echo "installed headers: $(echo "$engine_headers" | wc -l) engine headers and the VTK modules' compile alone"
cmake -S "$here" -B "$scratch/consumer" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/consumer" >/dev/null
"$scratch/consumer/terralux_consumer" "$dem"
# The C++ example of Examples/cxx, built the way its CMakeLists.txt says.
cmake -S "$here/../../Examples/cxx" -B "$scratch/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$scratch/prefix" >/dev/null
cmake --build "$scratch/example" >/dev/null
"$scratch/example/lit_dem" "$dem" "$scratch/example/lit.tif" | tee "$scratch/example/lit.log"
grep -q "global irradiance" "$scratch/example/lit.log"
test -s "$scratch/example/lit.tif"
cd /
PYTHONPATH="$scratch/prefix/$python_destination" "$python" -c "
import terralux, os
from terralux import vtkTerrainSource
assert terralux.__file__.startswith('$scratch/prefix'), terralux.__file__
t = vtkTerrainSource(); t.SetFileName('$dem'); t.Update()
print('python from install:', t.GetOutput().GetDimensions())
assert t.GetOutput().GetDimensions() == (111, 111, 1)
"
echo "install test passed"
