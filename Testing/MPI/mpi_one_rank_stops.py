"""One rank stops, the others must not wait for it (run under mpirun, 2 or more ranks):

  mpirun -np N /usr/bin/python3 mpi_one_rank_stops.py DEM

Each rank updates its piece of vtkTerrainSource -> vtkHierarchicalRadiosity (sun and
CIE clear sky). In the first update the last rank aborts its solve (a progress
observer sets AbortExecute, as a GUI's cancel button would), so it never reaches the
broadcasts of the horizons the ranks share: every rank must come back with an empty
output (the others with an error naming the stopped rank), not hang. A second update,
with no abort, must then give every rank its piece: no collective was left unmatched.
Then the one GeoTIFF rank 0 writes of the pieces: asked for an array the pieces lack,
rank 0 fails with an error once every rank has sent its piece (none waits), and the
next write succeeds.
"""
import os
import sys
import tempfile

import terralux
from mpi_pipeline import instant_solver
from terralux.irradiation import start_mpi


def main(dem):
    from mpi4py import MPI
    from vtkmodules.vtkCommonCore import vtkCommand

    controller = start_mpi()
    rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    terrain = terralux.vtkTerrainSource()
    terrain.SetFileName(dem)
    solver = instant_solver(terrain, "2024-08-15T08:30:00-03:00")

    errors = []
    solver.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    solver.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda caller, event: errors.append(event))
    stopping = {"on": rank == size - 1}

    def cancel(caller, event):
        if stopping["on"] and caller.GetProgress() >= 0.1:
            caller.SetAbortExecute(1)

    solver.AddObserver(vtkCommand.ProgressEvent, cancel)
    problems = []

    solver.UpdatePiece(rank, size, 0)
    first = solver.GetOutputDataObject(0)
    if first.GetNumberOfPoints() != 0 or first.GetPointData().GetNumberOfArrays() != 0:
        problems.append("the aborted update left %d posts" % first.GetNumberOfPoints())
    if rank != size - 1 and not errors:
        problems.append("no error reported while the last rank stopped")

    stopping["on"] = False
    solver.SetAbortExecute(0)
    solver.Modified()
    solver.UpdatePiece(rank, size, 0)
    second = solver.GetOutputDataObject(0)
    if second.GetNumberOfPoints() == 0 or not second.GetPointData().GetArray("Irradiance"):
        problems.append("the next update gave no piece (%d posts)" % second.GetNumberOfPoints())

    folder = MPI.COMM_WORLD.bcast(tempfile.mkdtemp() if rank == 0 else None, root=0)
    tif = os.path.join(folder, "pieces.tif")
    writer = terralux.vtkTerrainRasterWriter()
    writer.SetInputConnection(solver.GetOutputPort(0))
    writer.SetFileName(tif)
    writer.AddArrayName("NoSuchArray")
    writer_errors = []
    writer.AddObserver(vtkCommand.ErrorEvent, lambda caller, event: writer_errors.append(event))
    writer.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda caller, event: writer_errors.append(event))
    if writer.Write() != (0 if rank == 0 else 1) or (rank == 0 and not writer_errors):
        problems.append("a write of a missing array did not fail on rank 0 alone")
    writer.RemoveAllArrayNames()
    writer.AddArrayName("Irradiance")
    writer.Modified()
    if writer.Write() != 1:
        problems.append("the next write failed")
    if rank == 0:
        written, dem_posts = terralux.vtkTerrainSource(), terralux.vtkTerrainSource()
        written.SetFileName(tif)
        dem_posts.SetFileName(dem)
        written.Update()
        dem_posts.Update()
        if written.GetOutput().GetNumberOfPoints() != dem_posts.GetOutput().GetNumberOfPoints():
            problems.append("the GeoTIFF written after the failed one is not the whole DEM's")
        os.remove(tif)
        os.rmdir(folder)

    results = MPI.COMM_WORLD.gather((rank, problems), root=0)
    if rank == 0:
        failed = [(r, p) for r, p in results if p]
        for r, p in failed:
            print("rank %d: %s" % (r, "; ".join(p)))
        print("%d ranks: the stopped rank's update ended on every rank, the next one solved" % size)
        controller.Finalize(1)
        sys.exit(1 if failed else 0)
    controller.Finalize(1)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
