"""One MPI rank of the MPI benchmark (run by run_mpi_benchmark.sh under mpirun):

  mpirun -np N --bind-to core python3 mpi_benchmark.py DEM instant|day OUTPUT.tif

instant: sun + CIE clear sky + interreflection at every post (vtkHierarchicalRadiosity,
EvaluateAtPoints on, the paper's August morning); day: vtkSolarIrradiation over
2024-06-21 at 30-minute steps. Each rank evaluates its piece; rank 0 writes the GeoTIFF
and prints, per rank, the posts it evaluated, its seconds (pipeline update and write)
and its peak memory. TERRALUX_BENCH_DETAIL_DISTANCE (m) sets the solvers' DetailDistance,
TERRALUX_BENCH_FAR_STRIDE their FarTerrainStride; TERRALUX_BENCH_WINDOW=1 gives them the
source's far terrain at that stride instead (SetFarTerrainConnection): each rank then
reads its piece and a halo of the DEM only.
"""
import os
import resource
import sys
import time

from mpi4py import MPI

import terralux
from terralux.irradiation import start_mpi

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "MPI"))
from mpi_pipeline import instant_solver, series_solver  # noqa: E402

controller = start_mpi()
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
dem, mode, output = sys.argv[1:4]

start = time.perf_counter()
terrain = terralux.vtkTerrainSource()
terrain.SetFileName(dem)
far_stride = int(os.environ.get("TERRALUX_BENCH_FAR_STRIDE", "1"))
window = os.environ.get("TERRALUX_BENCH_WINDOW", "0") == "1"
if window:
    terrain.SetFarTerrainStride(far_stride)
if mode == "instant":
    solver = instant_solver(terrain, "2024-08-15T08:30:00-03:00", far_terrain=window)
else:
    solver = series_solver(terrain, "2024-06-21T00:00:00+00:00", "2024-06-22T00:00:00+00:00", 30.0,
                           far_terrain=window)
solver.SetDetailDistance(float(os.environ.get("TERRALUX_BENCH_DETAIL_DISTANCE", "0")))
solver.SetFarTerrainStride(far_stride)
writer = terralux.vtkTerrainRasterWriter()
writer.SetInputConnection(solver.GetOutputPort(0))
writer.SetFileName(output)
ok = writer.Write()
seconds = time.perf_counter() - start
points = solver.GetOutputDataObject(0).GetNumberOfPoints()
read = solver.GetInputDataObject(0, 0).GetNumberOfPoints()
field = solver.GetOutputDataObject(0).GetFieldData()
phase = {name: field.GetArray(name).GetValue(0) for name in ("SecondsVisibilityBuild", "SecondsRefine", "SecondsHorizons", "SecondsPoints",
                                                          "SecondsLattice", "Steps")
         if field.GetArray(name) is not None}
peak_mib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
rows = MPI.COMM_WORLD.gather((rank, points, read, seconds, peak_mib, phase, ok), root=0)
if rank == 0:
    for r, posts, held, s, mib, phases, written in rows:
        print("  rank %d of %d: %9d posts (%d read), %7.1f s (Embree %.1f, refine %.1f, horizons and skies %.1f, points %.1f"
              " of which lattice %.1f%s), peak %6.0f MiB%s"
              % (r, size, posts, held, s, phases.get("SecondsVisibilityBuild", 0), phases.get("SecondsRefine", 0),
                 phases.get("SecondsHorizons", 0), phases.get("SecondsPoints", 0), phases.get("SecondsLattice", 0),
                 ", %d steps" % phases["Steps"] if "Steps" in phases else "", mib, "" if written else ", WRITE FAILED"))
controller.Finalize(1)
