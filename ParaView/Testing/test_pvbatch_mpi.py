"""pvbatch under mpirun (2 ranks): the plugin's pipeline runs on both ranks, each on its
piece of the Olinda DEM, and SaveData writes one GeoTIFF (assembled on rank 0), which
the next test compares with the one plain VTK wrote on one process.

Environment: TERRALUX_PLUGIN, TERRALUX_DEM, TERRALUX_OUTPUT_DIR.
"""
import os
import sys

from paraview import servermanager
from paraview import simple as pv

from pipeline_parameters import paraview_pipeline

pv.LoadPlugin(os.environ["TERRALUX_PLUGIN"], remote=False)
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
path = os.path.join(os.environ["TERRALUX_OUTPUT_DIR"], "radiosity_mpi.tif")
if os.path.exists(path):
    os.remove(path)

terrain, sun, sky, solver = paraview_pipeline(pv, os.environ["TERRALUX_DEM"])
pv.SaveData(path, proxy=solver, ArrayNames=["Irradiance", "SkyViewFactor"])
# Data information sums the ranks' pieces: 111 x 111 posts and the row they share.
points = solver.GetDataInformation().GetNumberOfPoints()
print("pvbatch on %d ranks: %d posts in the pieces, %s written" % (ranks, points, path))
if ranks != 2 or points != 111 * 112 or not os.path.exists(path):
    sys.exit("FAIL")
print("OK")
