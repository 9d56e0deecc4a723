"""One MPI rank of the parallel pipeline (run under mpirun, any number of ranks):

  mpirun -np N /usr/bin/python3 mpi_pipeline.py DEM OUTPUT_DIR

vtkTerrainSource -> vtkSunSource -> vtkSkySource -> vtkHierarchicalRadiosity and
vtkTerrainSource -> vtkSolarIrradiation (three morning hours), each rank computing
its piece (the pipeline's UPDATE_PIECE_NUMBER), written as pieces of a .pvts
(vtkXMLPStructuredGridWriter) and as one GeoTIFF assembled on rank 0
(vtkTerrainRasterWriter). Rank 0 prints each rank's posts and seconds.
"""
import os
import sys
import time

from mpi4py import MPI  # noqa: F401 (starts MPI before VTK's controller)
from vtkmodules.vtkIOParallelXML import vtkXMLPStructuredGridWriter
from vtkmodules.vtkParallelCore import vtkMultiProcessController
from vtkmodules.vtkParallelMPI import vtkMPIController

import terralux

controller = vtkMPIController()
controller.Initialize()
vtkMultiProcessController.SetGlobalController(controller)
rank, size = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()

dem, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)

terrain = terralux.vtkTerrainSource()
terrain.SetFileName(dem)
sun = terralux.vtkSunSource()
sun.SetInputConnection(terrain.GetOutputPort())
sun.SetDateTime("2024-08-15T08:30:00-03:00")
sky = terralux.vtkSkySource()
sky.SetSunConnection(sun.GetOutputPort())
instant = terralux.vtkHierarchicalRadiosity()
instant.SetInputConnection(terrain.GetOutputPort())
instant.AddLightConnection(sun.GetOutputPort())
instant.AddLightConnection(sky.GetOutputPort(0))
series = terralux.vtkSolarIrradiation()
series.SetInputConnection(terrain.GetOutputPort())
series.SetStartTime("2024-08-15T06:00:00-03:00")
series.SetEndTime("2024-08-15T09:00:00-03:00")
series.SetTimeStep(60.0)

report = []
for name, solver in (("instant", instant), ("series", series)):
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
        sys.exit("rank %d: could not write %s.pvts" % (rank, name))
    raster = terralux.vtkTerrainRasterWriter()
    raster.SetInputConnection(solver.GetOutputPort(0))
    raster.SetFileName(os.path.join(out, name + ".tif"))
    if not raster.Write():
        sys.exit("rank %d: could not write %s.tif" % (rank, name))
    posts = solver.GetOutputDataObject(0).GetNumberOfPoints()
    report.append("%s: %d posts in %.2f s" % (name, posts, time.perf_counter() - start))

lines = controller.GetCommunicator() and None
gathered = MPI.COMM_WORLD.gather("rank %d of %d: %s" % (rank, size, "; ".join(report)), root=0)
if rank == 0:
    print("\n".join(gathered))
controller.Finalize(1)
