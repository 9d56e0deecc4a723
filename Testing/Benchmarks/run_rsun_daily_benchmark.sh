#!/usr/bin/env bash
# Daily irradiation against GRASS r.sun's daily mode, in one run on the same DEMs (peer
# benchmark; needs grass-core, not run by ctest): whole-process time and peak memory of
# r.sun (day=173, step=0.5 h, Linke 3.0, albedo 0.2, shadows, slope and aspect from
# r.slope.aspect, 2 threads) and of `python3 -m terralux.irradiation` for the same day at
# 30-minute steps (Horn normals as r.slope.aspect; at the defaults and with --fast, the
# knob's coarse end), and how their
# beam and global sums compare post by post (scripts: compare_rasters.py). With
# TERRALUX_BENCH_YEAR=1, also a year of hourly steps at every post (2024), against the
# same run's r.sun day (the time-integration issue's figure: at most 10 x) and against
# r.sun's year as a GIS user gets it, a daily run per day at 1-hour steps: twelve days
# (the 21st of each month) timed in one GRASS session, their mean times 365.
# Usage: Testing/Benchmarks/run_rsun_daily_benchmark.sh [BUILD_DIR] [DEM ...]
#   default DEMs: Olinda and the 1025^2 fractal (made by make_fractal_dem).
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="$(cd "${1:-${repo_dir}/build}" && pwd)"
shift || true
source "${repo_dir}/Testing/Benchmarks/rsun_common.sh"
cmake --build "${build_dir}" --target make_fractal_dem TerraLux::Python >/dev/null 2>&1 || cmake --build "${build_dir}" >/dev/null
fractal="$(default_fractal "${build_dir}")"
dems=("$@")
[ "${#dems[@]}" -gt 0 ] || dems=("${repo_dir}/Testing/Data/External/olinda_dem_utm25s.tif" "${fractal}")
export PYTHONPATH="${build_dir}/lib/python3.11/dist-packages${PYTHONPATH:+:${PYTHONPATH}}"
for dem in "${dems[@]}"; do
  name="$(basename "${dem}" .tif)"
  echo "== ${name}"
  rsun_script "${dem}" "${work}" "${name}"
  cat >> "${work}/${name}.sh" <<GRASS
/usr/bin/time -f "elapsed %e peak %M" -o "${work}/${name}.rsun.time" r.sun elevation=dem slope=slope aspect=aspect \
  day=173 step=0.5 linke_value=3.0 albedo_value=0.2 beam_rad=beam diff_rad=diff refl_rad=refl glob_rad=glob \
  nprocs=2 --overwrite --quiet
for map in beam glob; do r.out.gdal -c input=\${map} output="${work}/${name}.rsun.\${map}.tif" --overwrite --quiet 2>/dev/null; done
GRASS
  grass "${work}/${name}/PERMANENT" --exec bash "${work}/${name}.sh" >/dev/null 2>&1
  for mode in defaults fast; do
    flags=()
    [ "${mode}" = fast ] && flags=(--fast)
    /usr/bin/time -f "elapsed %e peak %M" -o "${work}/${name}.${mode}.time" /usr/bin/python3 -m terralux.irradiation \
      "${dem}" -o "${work}/${name}.${mode}.tif" --day-of-year 173 --year 2024 --step 30 --linke 3.0 \
      --reflectance 0.2 "${flags[@]}" --quiet >/dev/null
  done
  rsun="$(seconds "${work}/${name}.rsun.time")"
  echo "  r.sun daily:              $(printf '%6.1f' "${rsun}") s, $(peak_mib "${work}/${name}.rsun.time") MiB"
  for mode in defaults fast; do
    t="$(seconds "${work}/${name}.${mode}.time")"
    echo "  terralux.irradiation (${mode}): $(printf '%6.1f' "${t}") s, $(peak_mib "${work}/${name}.${mode}.time") MiB," \
      "$(awk -v a="${t}" -v b="${rsun}" 'BEGIN { printf "%.2f", a / b }') x r.sun"
    echo "    beam:   $(/usr/bin/python3 "${repo_dir}/Testing/Benchmarks/compare_rasters.py" "${work}/${name}.${mode}.tif" BeamIrradiation "${work}/${name}.rsun.beam.tif")"
    echo "    global: $(/usr/bin/python3 "${repo_dir}/Testing/Benchmarks/compare_rasters.py" "${work}/${name}.${mode}.tif" GlobalIrradiation "${work}/${name}.rsun.glob.tif")"
  done
  if [ "${TERRALUX_BENCH_YEAR:-0}" = 1 ]; then
    /usr/bin/time -f "elapsed %e peak %M" -o "${work}/${name}.year.time" /usr/bin/python3 -m terralux.irradiation \
      "${dem}" -o "${work}/${name}.year.tif" --start 2024-01-01 --end 2025-01-01 --step 60 --linke 3.0 \
      --reflectance 0.2 --quiet >/dev/null
    t="$(seconds "${work}/${name}.year.time")"
    echo "  terralux.irradiation, a year hourly: $(printf '%6.1f' "${t}") s, $(peak_mib "${work}/${name}.year.time") MiB," \
      "$(awk -v a="${t}" -v b="${rsun}" 'BEGIN { printf "%.2f", a / b }') x r.sun's day"
    cat > "${work}/${name}.days.sh" <<GRASS
set -e
for day in 21 52 81 112 142 173 203 234 265 295 326 356; do
  r.sun elevation=dem slope=slope aspect=aspect day=\${day} step=1.0 linke_value=3.0 albedo_value=0.2 \
    glob_rad=glob nprocs=2 --overwrite --quiet
done
GRASS
    /usr/bin/time -f "elapsed %e peak %M" -o "${work}/${name}.days.time" \
      grass "${work}/${name}/PERMANENT" --exec bash "${work}/${name}.days.sh" >/dev/null 2>&1
    days="$(seconds "${work}/${name}.days.time")"
    year="$(awk -v d="${days}" 'BEGIN { printf "%.0f", d / 12 * 365 }')"
    echo "  r.sun's year, a run per day at 1-hour steps: about ${year} s (12 days in ${days} s, x 365 / 12);" \
      "TerraLux's year $(awk -v a="${t}" -v b="${year}" 'BEGIN { printf "%.3f", a / b }') x that"
  fi
done
