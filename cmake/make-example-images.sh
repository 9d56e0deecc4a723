#!/usr/bin/env bash
# Runs every example of Examples/ at full settings into <build>/examples and copies the
# pictures the README shows into Examples/images/ (run after cmake/run-demo.sh or any
# build; about a minute on 2 cores).
#   TERRALUX_BUILD_DIR   build folder (default: <repo>/build)
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TERRALUX_BUILD_DIR:-${repo_dir}/build}"
python_path="$(cmake -LA -N "${build_dir}" 2>/dev/null | sed -n 's/^TERRALUX_PYTHON_DESTINATION:STRING=//p')"
export PYTHONPATH="${build_dir}/${python_path:-lib/python3.11/dist-packages}${PYTHONPATH:+:${PYTHONPATH}}"
out="${build_dir}/examples"
mkdir -p "${out}" "${repo_dir}/Examples/images"
for example in terrain_analyst olinda_morning house_and_trees tolerance_comparison sky_links building_on_dem; do
  echo "== ${example}"
  xvfb-run -a /usr/bin/python3 "${repo_dir}/Examples/${example}.py" --output-dir "${out}/${example}"
done
cp "${out}"/*/*.png "${repo_dir}/Examples/images/"
echo "pictures in ${repo_dir}/Examples/images"
