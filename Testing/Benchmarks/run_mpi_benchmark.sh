#!/usr/bin/env bash
# MPI through VTK's parallel pipeline, measured (not run by ctest): the accurate
# per-post instant and a one-day sum (30-minute steps) on a fractal DEM at 1 and 2 ranks
# of one core each (mpirun --bind-to core: TBB and vtkSMPTools then use one thread),
# whole-run wall time, speed-up, each rank's seconds by phase and peak memory, and the
# GeoTIFFs of 2 ranks compared with 1 rank's.
# Usage: Testing/Benchmarks/run_mpi_benchmark.sh [BUILD_DIR] [SIZE]   (SIZE: 2049)
#   TERRALUX_BENCH_DETAIL_DISTANCE  the solvers' DetailDistance, m (default 0: none)
#   TERRALUX_BENCH_FAR_STRIDE       their FarTerrainStride (default 1: none)
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="$(cd "${1:-${repo_dir}/build}" && pwd)"
size="${2:-2049}"
mkdir -p "${build_dir}/bench"
dem="${build_dir}/bench/fractal_${size}.tif"
[ -s "${dem}" ] || "${build_dir}/bin/make_fractal_dem" "${dem}" "${size}" 1 30 >/dev/null
export PYTHONPATH="${build_dir}/lib/python3.11/dist-packages${PYTHONPATH:+:${PYTHONPATH}}"
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
for mode in instant day; do
  echo "== ${size} x ${size} fractal DEM, ${mode}"
  for ranks in 1 2; do
    start=$(date +%s.%N)
    mpirun --allow-run-as-root --bind-to core --map-by core -np "${ranks}" /usr/bin/python3 \
      "${repo_dir}/Testing/Benchmarks/mpi_benchmark.py" "${dem}" "${mode}" "${work}/${mode}_${ranks}.tif"
    end=$(date +%s.%N)
    wall=$(awk -v a="${start}" -v b="${end}" 'BEGIN { printf "%.1f", b - a }')
    echo "  ${ranks} rank(s): ${wall} s wall"
    eval "wall_${ranks}=${wall}"
  done
  echo "  speed-up at 2 ranks: $(awk -v a="${wall_1}" -v b="${wall_2}" 'BEGIN { printf "%.2f", a / b }')"
  echo "  2 ranks against 1: $(/usr/bin/python3 "${repo_dir}/Testing/MPI/compare_runs.py" --rasters \
    "${work}/${mode}_1.tif" "${work}/${mode}_2.tif" | head -n 1)"
done
