#!/usr/bin/env bash
# The speed-against-error report: every scene of accuracy_scenes.cxx against the
# independent reference (Testing/Reference): at points (terrain patches; on terrains
# also the sky by rays and the triangle path) the knob, TargetError, swept over eight
# values at the default ErrorTolerance; averaged, ErrorTolerance swept over six; each
# solve in its own process so its peak memory is its own.
# Writes OUT_DIR/report.json, report.md and the plots (accuracy_report.py).
# Usage: Testing/Benchmarks/run_accuracy_report.sh [BUILD_DIR] [OUT_DIR] [SCENES...]
#   TERRALUX_REFERENCE_SAMPLES  directions per point for the reference (default 32768); a
#                               scene of fewer points than the largest (129^2) takes more,
#                               up to 8 times, so that its reference's noise stays below
#                               what it judges (the canyon's was 0.31 % a point)
#   TERRALUX_REPORT_DETAIL_DISTANCE  DetailDistance (m) of every solve (default 0)
#   TERRALUX_REPORT_FAR_STRIDE  FarTerrainStride of every solve (default 1)
#   TERRALUX_REPORT_DOC         also write the tables and plots as this page (the project's
#                               docs/validation.md, with OUT_DIR docs/validation)
#   TERRALUX_REPORT_REUSE_REFERENCES=1  keep a scene's reference already in OUT_DIR (made at
#                               the same number of directions) instead of computing it again
#   TERRALUX_REPORT_PREVIOUS    the build folder of a previous release: its solves at
#                               points join the report as "previous release", the
#                               new curve beside the old
#   TERRALUX_REPORT_SEEDS       the defaults' solve drawn again with RandomSeed 1..N-1
#                               (default 5 seeds in all): each band's bias over the seeds,
#                               its mean and spread, tells a solve's sampling noise from
#                               its bias
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="${1:-${repo_dir}/build}"
out_dir="${2:-${build_dir}/accuracy}"
shift $(( $# > 2 ? 2 : $# ))
scenes=("$@")
[ "${#scenes[@]}" -gt 0 ] || scenes=(olinda fractal hills crater canyon box house-sky house-sun olinda-sky olinda-black
  steep-morning steep-noon gentle-morning snowbowl ridges)
samples="${TERRALUX_REFERENCE_SAMPLES:-32768}"
cmake --build "${build_dir}" --target accuracy_report >/dev/null
export TERRALUX_DATA_DIR="${repo_dir}/Testing/Data/External"
mkdir -p "${out_dir}"
runs="${out_dir}/runs.jsonl"
: > "${runs}"
for scene in "${scenes[@]}"; do
  if [ "${TERRALUX_REPORT_REUSE_REFERENCES:-0}" = 1 ] && [ -s "${out_dir}/${scene}.reference" ] &&
    [ -s "${out_dir}/${scene}.reference.json" ] && [ -s "${out_dir}/${scene}.reference.bands" ]; then
    echo "== ${scene}: reference kept"
    tee -a "${runs}" < "${out_dir}/${scene}.reference.json"
  else
    points="$("${build_dir}/bin/accuracy_report" "${scene}" "${out_dir}" describe | sed -n 's/.*"points": \([0-9]*\).*/\1/p')"
    scene_samples="${samples}"
    for factor in 2 4 8; do
      [ "$(( points * factor ))" -le 16641 ] && scene_samples="$(( samples * factor ))"
    done
    echo "== ${scene}: reference (${scene_samples} directions per point)"
    "${build_dir}/bin/accuracy_report" "${scene}" "${out_dir}" reference "${scene_samples}" | tee "${out_dir}/${scene}.reference.json" | tee -a "${runs}"
  fi
  methods=(points averaged)
  case "${scene}" in olinda|fractal|crater) methods+=(rays triangles) ;; esac
  case "${scene}" in olinda-sky|olinda-black) methods+=(rays) ;; esac
  previous="${TERRALUX_REPORT_PREVIOUS:-}"
  if [ -n "${previous}" ]; then
    for tolerance in 3e-2 1e-2 3e-3 1e-3 3e-4 1e-4; do
      # A scene the previous release does not have gives no line.
      { "${previous}/bin/accuracy_report" "${scene}" "${out_dir}" solve points "${tolerance}" 2>/dev/null || true; } \
        | sed 's/"method": "points"/"method": "points-previous"/' | tee -a "${runs}" | cut -c1-160
    done
  fi
  for method in "${methods[@]}"; do
    if [ "${method}" = averaged ]; then
      for tolerance in 3e-2 1e-2 3e-3 1e-3 3e-4 1e-4; do
        "${build_dir}/bin/accuracy_report" "${scene}" "${out_dir}" solve averaged "${tolerance}" 2>/dev/null \
          | tee -a "${runs}" | cut -c1-160
      done
      continue
    fi
    for target in 0.256 0.128 0.064 0.04 0.016 0.008 0.004 0.002; do
      "${build_dir}/bin/accuracy_report" "${scene}" "${out_dir}" solve "${method}" 1e-2 "${target}" 2>/dev/null \
        | tee -a "${runs}" | cut -c1-160
    done
  done
  for (( seed = 1; seed < ${TERRALUX_REPORT_SEEDS:-5}; ++seed )); do
    TERRALUX_REPORT_SEED="${seed}" "${build_dir}/bin/accuracy_report" "${scene}" "${out_dir}" solve points 1e-2 0.008 \
      2>/dev/null | tee -a "${runs}" | cut -c1-160
  done
done
/usr/bin/python3 "${repo_dir}/Testing/Benchmarks/accuracy_report.py" "${runs}" "${out_dir}" ${TERRALUX_REPORT_DOC:+"${TERRALUX_REPORT_DOC}"}
