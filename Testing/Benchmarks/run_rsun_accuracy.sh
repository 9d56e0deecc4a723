#!/usr/bin/env bash
# GRASS r.sun's error against the accuracy report's reference (peer benchmark of the
# steep-terrain issue; needs grass-core, not run by ctest): on each terrain scene under
# one sun and its clear sky, r.sun plain and with r.horizon, its inputs matched to the
# scene's (rsun_accuracy.py). Writes OUT_DIR/rsun.jsonl, which the accuracy report
# (accuracy_report.py) plots as points beside TerraLux's knob and lists in its tables;
# then remakes the report from OUT_DIR/report.json.
# Usage: Testing/Benchmarks/run_rsun_accuracy.sh [BUILD_DIR] [OUT_DIR] [SCENES...]
#   OUT_DIR holds the scenes' references (run_accuracy_report.sh; default build/accuracy)
#   TERRALUX_REPORT_DOC  as for run_accuracy_report.sh: also write docs/validation.md
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build_dir="$(cd "${1:-${repo_dir}/build}" && pwd)"
out_dir="${2:-${build_dir}/accuracy}"
shift $(( $# > 2 ? 2 : $# ))
scenes=("$@")
[ "${#scenes[@]}" -gt 0 ] || scenes=(steep-morning steep-noon snowbowl fractal hills crater)
command -v grass >/dev/null || { echo "needs GRASS GIS: apt-get install grass-core" >&2; exit 2; }
cmake --build "${build_dir}" --target accuracy_report >/dev/null
export TERRALUX_DATA_DIR="${repo_dir}/Testing/Data/External"
peers="${out_dir}/rsun.jsonl"
: > "${peers}"
for scene in "${scenes[@]}"; do
  [ -s "${out_dir}/${scene}.reference" ] ||
    { echo "no reference for ${scene} in ${out_dir}: run run_accuracy_report.sh first" >&2; exit 2; }
  echo "== ${scene}"
  /usr/bin/python3 "${repo_dir}/Testing/Benchmarks/rsun_accuracy.py" "${build_dir}" "${out_dir}" "${scene}" \
    | tee -a "${peers}" | cut -c1-160
done
[ -s "${out_dir}/report.json" ] && /usr/bin/python3 "${repo_dir}/Testing/Benchmarks/accuracy_report.py" \
  "${out_dir}/report.json" "${out_dir}" ${TERRALUX_REPORT_DOC:+"${TERRALUX_REPORT_DOC}"}
