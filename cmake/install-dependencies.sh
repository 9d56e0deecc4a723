#!/usr/bin/env bash
# Installs the Debian packages TerraLux needs and extracts the real test DEMs.
# Idempotent: when everything is present it only checks and returns quickly.
#
# Usage: cmake/install-dependencies.sh [DATA_DIR]
#   DATA_DIR (default: <repo>/Testing/Data/External) receives olinda_dem_utm25s.tif
#   (r-cran-stars) and elev.tif (r-cran-terra), extracted with dpkg -x, R is not installed;
#   and jacksboro_fault_dem.tif, a rough real DEM (3 arc-seconds, ridge and valley in
#   Tennessee) that matplotlib ships as a NumPy archive, written as a GeoTIFF.
set -euo pipefail

repo_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
data_dir="${1:-${repo_dir}/Testing/Data/External}"

packages=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev python3-vtk9          # VTK 9.1 and its Python wrapping (never python3-paraview)
  libglm-dev                        # vector maths in the engine
  libembree-dev                     # ray casting (visibility)
  libgeographiclib-dev              # geodetic <-> ECEF <-> ENU
  libgdal-dev gdal-bin              # rasters, CRS (PROJ); gdalinfo for checks
  libtbb-dev                        # vtkSMPTools backend
  googletest libgtest-dev           # C++ unit tests
  xvfb xauth                        # off-screen X for rendering
  time                              # /usr/bin/time -v for the benchmarks
  clang libclang-rt-14-dev          # the sanitizer build and its libFuzzer targets
  python3-matplotlib                # plots: the examples and the accuracy report
  python3-tqdm                      # the irradiation command's progress bar
  openmpi-bin python3-mpi4py        # MPI runs through VTK's parallel pipeline (mpirun)
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -gt 0 ]; then
  echo "install-dependencies: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Real DEMs shipped inside R packages; unpack the .deb without installing R.
extract_from_deb() { # package, path inside the package (below site-library), target file
  local pkg="$1" inner="$2" target="$3"
  [ -s "$target" ] && return 0
  local tmp
  tmp="$(mktemp -d)"
  (cd "$tmp" && apt-get download -qq "$pkg" >/dev/null 2>&1) || {
    "${sudo_cmd[@]}" apt-get update -qq
    (cd "$tmp" && apt-get download -qq "$pkg" >/dev/null)
  }
  dpkg -x "$tmp"/"$pkg"_*.deb "$tmp/root"
  local found
  found="$(find "$tmp/root" -path "*/${inner}" | head -n 1)"
  if [ -z "$found" ]; then
    echo "install-dependencies: ${inner} not found in ${pkg}" >&2
    rm -rf "$tmp"
    return 1
  fi
  mkdir -p "$(dirname "$target")"
  cp "$found" "$target"
  rm -rf "$tmp"
  echo "install-dependencies: extracted ${target}"
}

extract_from_deb r-cran-stars stars/tif/olinda_dem_utm25s.tif "${data_dir}/olinda_dem_utm25s.tif"
extract_from_deb r-cran-terra terra/ex/elev.tif "${data_dir}/elev.tif"

# Matplotlib's sample of the Jacksboro fault (344 x 403 posts, 3 arc-seconds, WGS84,
# north row first): numpy writes it as an Esri ASCII grid, gdal_translate as a GeoTIFF.
matplotlib_dem_to_geotiff() { # .npz archive, target file
  local npz="$1" target="$2"
  [ -s "$target" ] && return 0
  local tmp
  tmp="$(mktemp -d)"
  /usr/bin/python3 - "$npz" "$tmp/dem.asc" <<'PY'
import sys
import numpy as np
d = np.load(sys.argv[1])
z = d["elevation"]
# The archive names its north edge ymin (36.73) and its south edge ymax (36.45).
south, north = sorted((float(d["ymin"]), float(d["ymax"])))
assert abs((north - south) - z.shape[0] * float(d["dy"])) < 1e-9
with open(sys.argv[2], "w") as f:
    f.write(f"ncols {z.shape[1]}\nnrows {z.shape[0]}\n")
    f.write(f"xllcorner {float(d['xmin']):.12f}\nyllcorner {south:.12f}\n")
    f.write(f"cellsize {float(d['dx']):.15f}\n")
    np.savetxt(f, z, fmt="%d")
PY
  mkdir -p "$(dirname "$target")"
  gdal_translate -q -a_srs EPSG:4326 -ot Int16 -of GTiff "$tmp/dem.asc" "$target"
  rm -rf "$tmp"
  echo "install-dependencies: wrote ${target}"
}

matplotlib_dem_to_geotiff /usr/share/matplotlib/mpl-data/sample_data/jacksboro_fault_dem.npz \
  "${data_dir}/jacksboro_fault_dem.tif"
