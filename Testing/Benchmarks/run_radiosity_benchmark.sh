#!/usr/bin/env bash
# Radiosity benchmark of issue #5: Olinda DEM (24k triangles), sun + CIE clear sky,
# reflectance 0.2, at several tolerances against a converged run (tolerance 1e-5).
# Usage: Testing/Benchmarks/run_radiosity_benchmark.sh [BUILD_DIR]
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
cmake --build "${build_dir}" --target benchmark_radiosity >/dev/null
dem="${repo_dir}/Testing/Data/External/olinda_dem_utm25s.tif"
reference="${build_dir}/bench/olinda_reference.bin"
mkdir -p "$(dirname "${reference}")"
"${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-5 --write "${reference}"
for tolerance in 1e-2 3e-3 1e-3 3e-4 1e-4; do
  "${build_dir}/bin/benchmark_radiosity" "${dem}" "${tolerance}" --compare "${reference}"
done
