#!/usr/bin/env bash
# Radiosity benchmark of issue #5: Olinda DEM (24k triangles), sun + CIE clear sky,
# reflectance 0.2, at several tolerances and visibility samples against a converged
# run (tolerance 1e-5, 16 samples).
# Usage: Testing/Benchmarks/run_radiosity_benchmark.sh [BUILD_DIR]
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
cmake --build "${build_dir}" --target benchmark_radiosity >/dev/null
dem="${repo_dir}/Testing/Data/External/olinda_dem_utm25s.tif"
reference="${build_dir}/bench/olinda_reference.bin"
mkdir -p "$(dirname "${reference}")"
# Reference: fine tolerance and 16 visibility samples per link.
/usr/bin/time -f "  reference: %e s, peak %M kB" \
  "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-5 16 --write "${reference}"
for samples in 4 16; do
  for tolerance in 1e-2 1e-3 1e-4; do
    "${build_dir}/bin/benchmark_radiosity" "${dem}" "${tolerance}" "${samples}" --compare "${reference}"
  done
done
