# Shared by the r.sun peer benchmarks (sourced, not run): GRASS's presence, a location
# per DEM with the DEM ingested and its slopes, and the figures /usr/bin/time wrote.
command -v grass >/dev/null || { echo "needs GRASS GIS: apt-get install grass-core" >&2; exit 2; }

# seconds FILE, peak_mib FILE: from /usr/bin/time -f "elapsed %e peak %M" -o FILE.
seconds() { sed -n 's/^elapsed \([0-9.]*\) peak \([0-9]*\)$/\1/p' "$1"; }
peak_mib() { sed -n 's/^elapsed \([0-9.]*\) peak \([0-9]*\)$/\2/p' "$1" | awk '{printf "%.0f", $1 / 1024}'; }

# rsun_script DEM WORK NAME: makes the location WORK/NAME on the DEM and starts the
# script WORK/NAME.sh with the DEM's ingest (raster dem) and its slopes (slope, aspect);
# the caller appends its r.sun call and runs it with
#   grass WORK/NAME/PERMANENT --exec bash WORK/NAME.sh
rsun_script() {
  local dem="$1" work="$2" name="$3"
  grass -c "${dem}" "${work}/${name}" -e >/dev/null 2>&1
  cat > "${work}/${name}.sh" <<GRASS
set -e
r.in.gdal -o input="${dem}" output=dem --overwrite --quiet
g.region raster=dem
r.slope.aspect elevation=dem slope=slope aspect=aspect --overwrite --quiet
GRASS
}

# bench_fractal BUILD_DIR NAME [RELIEF_M]: BUILD_DIR/bench/NAME.tif, a 1025^2 fractal DEM
# (30 m, seed 1; make_fractal_dem's relief unless given), made once; prints its path.
bench_fractal() {
  local dem="$1/bench/$2.tif"
  mkdir -p "$1/bench"
  [ -s "${dem}" ] || "$1/bin/make_fractal_dem" "${dem}" 1025 1 30 ${3:+"$3"} >/dev/null
  echo "${dem}"
}

# default_fractal BUILD_DIR: the gentle 1025^2 fractal.
default_fractal() { bench_fractal "$1" fractal_1025; }

# steep_fractal BUILD_DIR: the steep one, 3000 m of relief (mean slope 15 deg, p95 28
# deg, as real mountain DEMs).
steep_fractal() { bench_fractal "$1" steep_1025 3000; }

# A scratch folder for the run, removed at exit.
work="$(mktemp -d)"
trap 'rm -rf "${work}"' EXIT
