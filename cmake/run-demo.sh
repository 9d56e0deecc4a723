#!/usr/bin/env bash
# Command (1) of the README: install what is needed, build, and run the demo, the
# terrain analyst's workflow (Examples/terrain_analyst.py) on the real Olinda DEM:
# irradiance GeoTIFF, map and plots in <build>/demo.
#   TERRALUX_BUILD_DIR   build folder (default: <repo>/build)
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TERRALUX_BUILD_DIR:-${repo_dir}/build}"

bash "${repo_dir}/cmake/install-dependencies.sh"
cmake -S "${repo_dir}" -B "${build_dir}" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "${build_dir}" -j "$(nproc)"

python_path="$(cmake -LA -N "${build_dir}" 2>/dev/null | sed -n 's/^TERRALUX_PYTHON_DESTINATION:STRING=//p')"
export PYTHONPATH="${build_dir}/${python_path:-lib/python3.11/dist-packages}${PYTHONPATH:+:${PYTHONPATH}}"
xvfb-run -a /usr/bin/python3 "${repo_dir}/Examples/terrain_analyst.py" --output-dir "${build_dir}/demo" "$@"
