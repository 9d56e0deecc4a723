#!/usr/bin/env bash
# Command (2) of the README: install what is needed, build, and run every test:
# C++ (GoogleTest), Python and install tests; the ParaView plugin built against
# Debian's ParaView 5.11 and its pvpython, pvbatch and GUI tests; then the C++ tests
# again built with clang, AddressSanitizer and UndefinedBehaviorSanitizer, and the
# libFuzzer targets for TERRALUX_FUZZ_SECONDS each (default 60) under the same sanitizers.
#   TERRALUX_BUILD_DIR   build folder (default: <repo>/build); the plugin build goes
#                        to <that>-paraview, the sanitizer build to <that>-asan
set -euo pipefail
repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${TERRALUX_BUILD_DIR:-${repo_dir}/build}"
jobs="$(nproc)"

bash "${repo_dir}/cmake/install-dependencies.sh"

echo "== build (Release) in ${build_dir}"
cmake -S "${repo_dir}" -B "${build_dir}" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "${build_dir}" -j "${jobs}"
echo "== tests: C++, Python, install"
ctest --test-dir "${build_dir}" --output-on-failure -j "${jobs}"

TERRALUX_BUILD_DIR="${build_dir}" TERRALUX_PARAVIEW_BUILD_DIR="${build_dir}-paraview" \
  bash "${repo_dir}/cmake/build-paraview-plugin.sh" --test --gui

echo "== build (clang, AddressSanitizer + UndefinedBehaviorSanitizer, libFuzzer) in ${build_dir}-asan"
CC=clang CXX=clang++ cmake -S "${repo_dir}" -B "${build_dir}-asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DTERRALUX_SANITIZE=ON -DTERRALUX_FUZZ=ON -DTERRALUX_WRAP_PYTHON=OFF \
  -DTERRALUX_FUZZ_SECONDS="${TERRALUX_FUZZ_SECONDS:-60}" >/dev/null
cmake --build "${build_dir}-asan" -j "${jobs}"
echo "== tests: C++ and fuzz targets under sanitizers"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1" \
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  ctest --test-dir "${build_dir}-asan" -L "cxx|fuzz" --output-on-failure -j "${jobs}"
