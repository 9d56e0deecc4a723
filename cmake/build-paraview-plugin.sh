#!/usr/bin/env bash
# Builds the TerraLux ParaView plugin (ParaView/) into build-paraview/ and, with --test,
# runs its tests. Debian's ParaView 5.11 bundles its own VTK 9.2 and its Python package
# conflicts with python3-vtk9, so ParaView is never installed: its three packages are
# unpacked into a private prefix (build-paraview/prefix), whose pvpython and pvbatch run
# as they are. Only the shared libraries those tools need that are missing here are
# installed, after checking that installing them removes nothing.
#
# Usage: cmake/build-paraview-plugin.sh [--test] [--gui]
#   --test  run the plugin's tests (pvpython, pvbatch) after the build
#   --gui   also install the Qt libraries the ParaView GUI (prefix/usr/bin/paraview) needs
#   TERRALUX_PARAVIEW_BUILD_DIR  plugin build folder (default: <repo>/build-paraview)
#   TERRALUX_BUILD_DIR           the plain-VTK build the tests compare with
#                                (default: <repo>/build)
# Where Debian's archive offers no ParaView 5.11, it says so in one line and exits 0.
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TERRALUX_PARAVIEW_BUILD_DIR:-${repo_dir}/build-paraview}"
vtk_build_dir="${TERRALUX_BUILD_DIR:-${repo_dir}/build}"
prefix="${build_dir}/prefix"
run_tests=0
with_gui=0
for argument in "$@"; do
  case "${argument}" in
    --test) run_tests=1 ;;
    --gui) with_gui=1 ;;
    *) echo "usage: $0 [--test] [--gui]" >&2; exit 2 ;;
  esac
done

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

paraview_version() { apt-cache policy "$1" 2>/dev/null | sed -n 's/^ *Candidate: *//p'; }
version="$(paraview_version paraview-dev)"
if [ -z "${version}" ] || [ "${version}" = "(none)" ]; then
  "${sudo_cmd[@]}" apt-get update -qq >/dev/null 2>&1 || true
  version="$(paraview_version paraview-dev)"
fi
case "${version}" in
  5.11.*) ;;
  *) echo "ParaView plugin: skipped, Debian's archive offers no ParaView 5.11 here (paraview-dev: ${version:-none})"
     exit 0 ;;
esac

# 1. The private prefix: the three packages unpacked, never installed.
stamp="${prefix}/.unpacked-${version}"
if [ ! -f "${stamp}" ]; then
  echo "== ParaView ${version}: unpacking into ${prefix}"
  rm -rf "${prefix}" "${build_dir}/debs"
  mkdir -p "${build_dir}/debs" "${prefix}"
  (cd "${build_dir}/debs" && apt-get download -qq paraview paraview-dev python3-paraview 2>/dev/null)
  for deb in "${build_dir}"/debs/*.deb; do dpkg -x "${deb}" "${prefix}"; done
  rm -rf "${build_dir}/debs"
  touch "${stamp}"
fi

# 2. The libraries pvpython and pvbatch need: paraview's own library dependencies,
# without the Python web stack and (unless --gui) the Qt GUI, which the headless
# tools do not load.
needed=()
deps="$(apt-cache show "paraview=${version}" | sed -n 's/^Depends: //p' | head -n 1)"
IFS=',' read -ra alternatives <<< "${deps}"
for alt in "${alternatives[@]}"; do
  pkg="$(echo "${alt}" | sed 's/|.*//; s/(.*)//; s/ //g')"
  case "${pkg}" in
    libqt5*) [ "${with_gui}" = 1 ] || continue ;;
    python3-autobahn|python3-twisted|python3-six|tclsh) continue ;;
  esac
  if ! dpkg-query -W -f='${Status}' "${pkg}" 2>/dev/null | grep -q "install ok installed"; then
    needed+=("${pkg}")
  fi
done
if [ "${#needed[@]}" -gt 0 ]; then
  if "${sudo_cmd[@]}" apt-get -s install --no-install-recommends "${needed[@]}" | grep -q '^Remv'; then
    echo "ParaView plugin: installing ${needed[*]} would remove packages; install them by hand" >&2
    exit 1
  fi
  echo "== ParaView: installing ${needed[*]}"
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${needed[@]}" >/dev/null
fi
missing="$(ldd "${prefix}/usr/bin/pvpython" "${prefix}/usr/bin/pvbatch" | grep 'not found' | sort -u || true)"
if [ -n "${missing}" ]; then
  echo "ParaView plugin: pvpython or pvbatch miss libraries: ${missing}" >&2
  exit 1
fi

# 3. The plugin: TerraLux's modules built again against ParaView's VTK.
echo "== build (ParaView plugin) in ${build_dir}"
cmake -S "${repo_dir}/ParaView" -B "${build_dir}" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="${prefix}/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11" \
  -DPython3_EXECUTABLE=/usr/bin/python3 \
  -DTERRALUX_VTK_BUILD_DIR="${vtk_build_dir}" >/dev/null
cmake --build "${build_dir}" -j "$(nproc)"

if [ "${run_tests}" = 1 ]; then
  echo "== tests: ParaView plugin (pvpython, pvbatch)"
  # A test that fails is run once more: the X tests depend on an Xvfb starting in time
  # on a loaded machine. A real failure fails twice and is reported.
  ctest --test-dir "${build_dir}" --output-on-failure -j "$(nproc)" --repeat until-pass:2
fi
