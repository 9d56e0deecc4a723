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
