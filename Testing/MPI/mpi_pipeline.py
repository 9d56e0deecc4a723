"""One MPI rank of the parallel pipeline (run under mpirun, any number of ranks):

  mpirun -np N /usr/bin/python3 mpi_pipeline.py DEM OUTPUT_DIR

vtkTerrainSource -> vtkSunSource -> vtkSkySource -> vtkHierarchicalRadiosity (also
with a DetailDistance of 1.5 km, "near": each rank then holds the posts' skies within
it of its piece only) and vtkTerrainSource -> vtkSolarIrradiation (three morning
hours); and both again with the source's far terrain (output 1) and a DetailDistance
of 500 m, "window" and "window_series": each rank then reads only its piece and a halo
of the DEM (checked here: less than the whole with more than one rank); each rank computing
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
# With the far terrain a piece reads three of them around it, and the lattice's posts:
# 28 posts here, so that 2 and 3 ranks read less than the DEM's 111 x 111.
WINDOW_DETAIL_DISTANCE = 500.0


def instant_solver(terrain, when, far_terrain=False):
    """Sun, the CIE clear sky it lights and interreflection on the terrain at `when`;
    with `far_terrain`, the source's output 1 as the far terrain (the sun reads its
    georeference there, so that output 0 is asked for the solver's piece alone)."""
    sun = terralux.vtkSunSource()
    sun.SetInputConnection(terrain.GetOutputPort(1 if far_terrain else 0))
    sun.SetDateTime(when)
    sky = terralux.vtkSkySource()
    sky.SetSunConnection(sun.GetOutputPort())
    solver = terralux.vtkHierarchicalRadiosity()
    solver.SetInputConnection(terrain.GetOutputPort())
    solver.AddLightConnection(sun.GetOutputPort())
    solver.AddLightConnection(sky.GetOutputPort(0))
    if far_terrain:
        solver.SetFarTerrainConnection(terrain.GetOutputPort(1))
    return solver


def series_solver(terrain, start, end, minutes, far_terrain=False):
    """Irradiation sums on the terrain from `start` to `end` at steps of `minutes`."""
    solver = terralux.vtkSolarIrradiation()
    solver.SetInputConnection(terrain.GetOutputPort())
    solver.SetStartTime(start)
    solver.SetEndTime(end)
    solver.SetTimeStep(minutes)
    if far_terrain:
        solver.SetFarTerrainConnection(terrain.GetOutputPort(1))
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
    # Their own source: a source another solver asked for the whole DEM holds it, and a
    # window within serves from it (correct, but not what this test measures).
    window_terrain = terralux.vtkTerrainSource()
    window_terrain.SetFileName(dem)
    window = instant_solver(window_terrain, "2024-08-15T08:30:00-03:00", far_terrain=True)
    window_series = series_solver(window_terrain, "2024-08-15T06:00:00-03:00", "2024-08-15T09:00:00-03:00", 60.0,
                                  far_terrain=True)
    for solver in (window, window_series):
        solver.SetDetailDistance(WINDOW_DETAIL_DISTANCE)

    def fail(message):  # one rank's failure ends every rank (no rank left in a collective)
        sys.stderr.write("rank %d: %s\n" % (rank, message))
        MPI.COMM_WORLD.Abort(1)

    report = []
    for name, solver in (("instant", instant), ("near", near), ("series", series), ("window", window),
                         ("window_series", window_series)):
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
        read = solver.GetInputDataObject(0, 0).GetNumberOfPoints()
        if name.startswith("window") and size > 1 and not posts < read < 111 * 111:
            fail("%s: the solver read %d posts of the DEM for a piece of %d (a window holds more than the "
                 "piece and less than the DEM's 12321)" % (name, read, posts))
        report.append("%s: %d posts (read %d) in %.2f s" % (name, posts, read, time.perf_counter() - start))

    gathered = MPI.COMM_WORLD.gather("rank %d of %d: %s" % (rank, size, "; ".join(report)), root=0)
    if rank == 0:
        print("\n".join(gathered))
    controller.Finalize(1)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
