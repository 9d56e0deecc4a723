#!/usr/bin/env bash
# Radiosity benchmark of issues #5 and #6: the Olinda DEM (111 x 111 posts), sun + CIE
# clear sky, reflectance 0.2, at several tolerances, through terrain patches and
# through the plain-triangle path (24,200 triangles), against a converged run of the
# plain path (tolerance 1e-5, 16 samples): an independent discretisation of the same
# surface.
# Usage: Testing/Benchmarks/run_radiosity_benchmark.sh [BUILD_DIR]
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
cmake --build "${build_dir}" --target benchmark_radiosity >/dev/null
dem="${repo_dir}/Testing/Data/External/olinda_dem_utm25s.tif"
reference="${build_dir}/bench/olinda_reference.bin"
mkdir -p "$(dirname "${reference}")"
TERRALUX_BENCH_TRIANGLES=1 /usr/bin/time -f "  reference: %e s, peak %M kB" \
  "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-5 16 --write "${reference}"
for path in patches triangles; do
  echo "== ${path}"
  for tolerance in 1e-2 1e-3 1e-4; do
    if [ "${path}" = triangles ]; then
      TERRALUX_BENCH_TRIANGLES=1 "${build_dir}/bin/benchmark_radiosity" "${dem}" "${tolerance}" 4 --compare "${reference}"
    else
      "${build_dir}/bin/benchmark_radiosity" "${dem}" "${tolerance}" 4 --compare "${reference}"
    fi
  done
done
