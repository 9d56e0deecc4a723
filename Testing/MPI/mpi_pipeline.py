"""One MPI rank of the parallel pipeline (run under mpirun, any number of ranks):

  mpirun -np N /usr/bin/python3 mpi_pipeline.py DEM OUTPUT_DIR

vtkTerrainSource -> vtkSunSource -> vtkSkySource -> vtkHierarchicalRadiosity (also
with a DetailDistance of 1.5 km, "near": each rank then holds the posts' skies within
it of its piece only) and vtkTerrainSource -> vtkSolarIrradiation (three morning
hours), each rank computing
its piece (the pipeline's UPDATE_PIECE_NUMBER), written as pieces of a .pvts
(vtkXMLPStructuredGridWriter), as one GeoTIFF assembled on rank 0
(vtkTerrainRasterWriter) and as a GeoTIFF per rank with a VRT over them (WritePieces). Rank 0 prints each rank's posts and seconds.
"""
import os
import sys
import time

import terralux
from terralux.irradiation import start_mpi


DETAIL_DISTANCE = 1500.0  # m: 17 posts of the 90 m Olinda DEM, less than a piece


def instant_solver(terrain, when):
    """Sun, the CIE clear sky it lights and interreflection on the terrain at `when`."""
    sun = terralux.vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort())
    sun.SetDateTime(when)
    sky = terralux.vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    solver = terralux.vtkHierarchicalRadiosity()
    solver.SetInputConnection(terrain.GetOutputPort())
    solver.AddLightConnection(sun.GetOutputPort())
    solver.AddLightConnection(sky.GetOutputPort(0))
    return solver


def series_solver(terrain, start, end, minutes):
    """Irradiation sums on the terrain from `start` to `end` at steps of `minutes`."""
    solver = terralux.vtkSolarIrradiation()
    solver.SetInputConnection(terrain.GetOutputPort())
    solver.SetStartTime(start)
    solver.SetEndTime(end)
    solver.SetTimeStep(minutes)
    return solver


def main(dem, out):
    from mpi4py import MPI
    from vtkmodules.vtkIOParallelXML import vtkXMLPStructuredGridWriter

    controller = start_mpi()
    rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    os.makedirs(out, exist_ok=True)
    terrain = terralux.vtkTerrainSource()
    terrain.SetFileName(dem)
    instant = instant_solver(terrain, "2024-08-15T08:30:00-03:00")
    near = instant_solver(terrain, "2024-08-15T08:30:00-03:00")
    near.SetDetailDistance(DETAIL_DISTANCE)
    series = series_solver(terrain, "2024-08-15T06:00:00-03:00", "2024-08-15T09:00:00-03:00", 60.0)

    def fail(message):  # one rank's failure ends every rank (no rank left in a collective)
        sys.stderr.write("rank %d: %s\n" % (rank, message))
        MPI.COMM_WORLD.Abort(1)

    report = []
    for name, solver in (("instant", instant), ("near", near), ("series", series)):
        start = time.perf_counter()
        pieces = vtkXMLPStructuredGridWriter()
        pieces.SetInputConnection(solver.GetOutputPort(0))
        pieces.SetFileName(os.path.join(out, name + ".pvts"))
        pieces.SetNumberOfPieces(size)
        pieces.SetStartPiece(rank)
        pieces.SetEndPiece(rank)
        pieces.SetController(controller)
        pieces.SetDataModeToBinary()
        if not pieces.Write():
            fail("could not write %s.pvts" % name)
        raster = terralux.vtkTerrainRasterWriter()
        raster.SetInputConnection(solver.GetOutputPort(0))
        raster.SetFileName(os.path.join(out, name + ".tif"))
        if not raster.Write():
            fail("could not write %s.tif" % name)
        tiles = terralux.vtkTerrainRasterWriter()  # a GeoTIFF per rank and a VRT over them
        tiles.SetInputConnection(solver.GetOutputPort(0))
        tiles.SetFileName(os.path.join(out, name + "_pieces.vrt"))
        tiles.WritePiecesOn()
        if not tiles.Write():
            fail("could not write %s_pieces.vrt" % name)
        posts = solver.GetOutputDataObject(0).GetNumberOfPoints()
        report.append("%s: %d posts in %.2f s" % (name, posts, time.perf_counter() - start))

    gathered = MPI.COMM_WORLD.gather("rank %d of %d: %s" % (rank, size, "; ".join(report)), root=0)
    if rank == 0:
        print("\n".join(gathered))
    controller.Finalize(1)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
