#!/usr/bin/env bash
# Ingest benchmark of issue #3: a generated 4097 x 4097 float32 GeoTIFF read by
# vtkTerrainSource; wall time and peak memory from the program and /usr/bin/time -v.
# Usage: Testing/Benchmarks/run_ingest_benchmark.sh [BUILD_DIR]
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
cmake --build "${build_dir}" --target make_fractal_dem benchmark_terrain_ingest >/dev/null
dem="${build_dir}/bench/fractal_4097.tif"
mkdir -p "$(dirname "${dem}")"
[ -s "${dem}" ] || "${build_dir}/bin/make_fractal_dem" "${dem}" 4097 1 30
for args in "1 single" "1 double" "4 single"; do
  /usr/bin/time -v "${build_dir}/bin/benchmark_terrain_ingest" "${dem}" ${args} 2> "${build_dir}/bench/time.txt"
  grep -E "Maximum resident|Elapsed" "${build_dir}/bench/time.txt" | sed 's/^\s*/  time -v: /'
done
