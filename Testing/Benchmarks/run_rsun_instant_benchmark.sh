#!/usr/bin/env bash
# One instant against GRASS r.sun's instant mode, in one run on the same DEMs (peer
# benchmark of the fast-per-post issue; needs grass-core, not run by ctest). Whole
# processes: r.sun with its DEM ingest (r.in.gdal) and slopes (r.slope.aspect), sun and
# diffuse at 09:00 local solar time of 21 December, Linke 3.0, albedo 0.2, shadows, 2
# threads; TerraLux's benchmark_radiosity (sun and CIE clear sky at the same instant at
# the DEM's centre, reflectance 0.2, interreflection) at every post at the defaults
# (ErrorTolerance 1e-2, TargetError 0.008) and at the knob's coarse end (TargetError
# 0.04, the command's --fast). Prints the times, peak memory, rays per post and ratios.
# Then the same physics in GRASS: r.sun takes no terrain off the diffuse sky unless
# given horizons, so r.horizon finds them first at TerraLux's 32 azimuths (every 11.25
# deg; one thread, it has no nprocs) and r.sun reads them (horizon_basename); skipped
# with RSUN_HORIZONS=0 (r.horizon takes about 80 s at 1025^2).
# RSUN_SOLAR_TIME: another local solar time (hours) for both, 9.0 unless set.
# Usage: Testing/Benchmarks/run_rsun_instant_benchmark.sh [BUILD_DIR] [DEM ...]
#   default DEMs: the gentle and the steep 1025^2 fractals (made by make_fractal_dem), the
#   Jacksboro fault's ridges (a rough real DEM) and Olinda.
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="$(cd "${1:-${repo_dir}/build}" && pwd)"
shift || true
export TERRALUX_BENCH_SOLAR_TIME="${RSUN_SOLAR_TIME:-9.0}"
source "${repo_dir}/Testing/Benchmarks/rsun_common.sh"
cmake --build "${build_dir}" --target make_fractal_dem benchmark_radiosity >/dev/null
fractal="$(default_fractal "${build_dir}")"
dems=("$@")
[ "${#dems[@]}" -gt 0 ] ||
  dems=("${fractal}" "$(steep_fractal "${build_dir}")" "${repo_dir}/Testing/Data/External/jacksboro_fault_dem.tif"
    "${repo_dir}/Testing/Data/External/olinda_dem_utm25s.tif")
for dem in "${dems[@]}"; do
  name="$(basename "${dem}" .tif)"
  echo "== ${name}"
  # The instant both GRASS sessions compute, with and without horizons.
  rsun_call="r.sun elevation=dem slope=slope aspect=aspect day=356 time=${RSUN_SOLAR_TIME:-9.0} linke_value=3.0 albedo_value=0.2
    beam_rad=beam diff_rad=diff refl_rad=refl glob_rad=glob nprocs=2 --overwrite --quiet"
  rsun_script "${dem}" "${work}" "${name}"
  echo ${rsun_call} >> "${work}/${name}.sh"
  # The whole GRASS session: ingest, slopes and r.sun, as a user runs them.
  /usr/bin/time -f "elapsed %e peak %M" -o "${work}/rsun.time" \
    grass "${work}/${name}/PERMANENT" --exec bash "${work}/${name}.sh" >/dev/null 2>&1
  /usr/bin/time -f "elapsed %e peak %M" -o "${work}/points.time" \
    "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-2 4 > "${work}/points.out"
  TERRALUX_BENCH_TARGET_ERROR=0.04 /usr/bin/time -f "elapsed %e peak %M" -o "${work}/fast.time" \
    "${build_dir}/bin/benchmark_radiosity" "${dem}" 1e-2 4 > "${work}/fast.out"
  rsun="$(seconds "${work}/rsun.time")"
  echo "  r.sun instant (with r.in.gdal, r.slope.aspect): $(printf '%6.1f' "${rsun}") s, $(peak_mib "${work}/rsun.time") MiB"
  for mode in points fast; do
    t="$(seconds "${work}/${mode}.time")"
    echo "  TerraLux ${mode}: $(printf '%6.1f' "${t}") s, $(peak_mib "${work}/${mode}.time") MiB," \
      "$(awk -v a="${t}" -v b="${rsun}" 'BEGIN { printf "%.2f", a / b }') x r.sun"
    sed 's/^/    /' "${work}/${mode}.out" | tail -n 1
  done
  [ "${RSUN_HORIZONS:-1}" = 0 ] && continue
  rsun_script "${dem}" "${work}" "${name}_horizons"
  cat >> "${work}/${name}_horizons.sh" <<GRASS
/usr/bin/time -f "elapsed %e peak %M" -o "${work}/horizon.time" \
  r.horizon elevation=dem step=11.25 output=horizon --overwrite --quiet
$(echo ${rsun_call}) horizon_basename=horizon horizon_step=11.25
GRASS
  /usr/bin/time -f "elapsed %e peak %M" -o "${work}/rsun_horizons.time" \
    grass "${work}/${name}_horizons/PERMANENT" --exec bash "${work}/${name}_horizons.sh" >/dev/null 2>&1
  both="$(seconds "${work}/rsun_horizons.time")"
  echo "  r.horizon (32 azimuths) then r.sun with them, the same session: $(printf '%6.1f' "${both}") s" \
    "(r.horizon $(seconds "${work}/horizon.time") s), $(peak_mib "${work}/rsun_horizons.time") MiB;" \
    "TerraLux points $(awk -v a="$(seconds "${work}/points.time")" -v b="${both}" 'BEGIN { printf "%.3f", a / b }') x"
done
