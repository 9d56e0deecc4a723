#!/usr/bin/env bash
# Scale benchmark of issue #6: generated fractal DEMs of 1025^2, 2049^2 and 4097^2 posts
# (30 m, seed 1) under the sun and a CIE clear sky, reflectance 0.2, tolerance 1e-3,
# 4 visibility samples, terrain patches (UseTerrainHierarchy on). Post values are
# interpolated from the leaf mesh with direct sun at each post (EvaluateAtPoints off);
# with --points also evaluated at every post (slow for the largest DEM).
# Usage: Testing/Benchmarks/run_terrain_scale_benchmark.sh [BUILD_DIR] [--points]
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
cmake --build "${build_dir}" --target make_fractal_dem benchmark_radiosity >/dev/null
mkdir -p "${build_dir}/bench"
for n in 1025 2049 4097; do
  dem="${build_dir}/bench/fractal_${n}.tif"
  [ -s "${dem}" ] || "${build_dir}/bin/make_fractal_dem" "${dem}" "${n}" 1 30
  echo "== ${n} x ${n} posts"
  TERRALUX_BENCH_AVERAGED=1 /usr/bin/time -f "  whole process: %e s, peak %M kB" \
    "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-3 4
  if [ "${2:-}" = "--points" ]; then
    /usr/bin/time -f "  whole process (points): %e s, peak %M kB" \
      "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-3 4
  fi
done
