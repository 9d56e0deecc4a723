"""vtkTerrainSource's far terrain (output 1) and a solver that sees it beyond its
DetailDistance (SetFarTerrainConnection): streamed pieces read only their window of
the DEM and give the one-piece values, on the real Olinda (UTM) and Luxembourg
(geographic, no data) DEMs; and what the far terrain refuses."""
import math
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData

from terralux import (vtkHierarchicalRadiosity, vtkSkySource, vtkSolarIrradiation, vtkSunSource,
                      vtkTerrainSource)
from terralux_testing import LUXEMBOURG, OLINDA, ErrorCatcher

DETAIL = 500.0  # m: a halo of about 28 Olinda posts, 14 of Luxembourg's (its posts ~90 x 60 m)


def points_of(grid):
    nx, ny, _ = grid.GetDimensions()
    return vtk_to_numpy(grid.GetPoints().GetData()).astype(float).reshape(ny, nx, 3)


def field_vector(data, name):
    array = data.GetFieldData().GetArray(name)
    return [array.GetComponent(0, c) for c in range(array.GetNumberOfComponents())] \
        if array.GetNumberOfTuples() == 1 else [array.GetValue(k) for k in range(array.GetNumberOfValues())]


def solver_on(dem, series=False, detail=DETAIL, far=True):
    """A fresh pipeline (nothing kept from another piece's update): the terrain, the
    sun and sky read their georeference on the far terrain, the solver."""
    terrain = vtkTerrainSource()
    terrain.SetFileName(dem)
    terrain.SetFarTerrainStride(4)
    if series:
        solver = vtkSolarIrradiation()
        solver.SetStartTime("2024-08-15T09:00:00-03:00")
        solver.SetEndTime("2024-08-15T11:00:00-03:00")
        solver.SetTimeStep(60.0)
    else:
        sun = vtkSunSource()
        sun.SetInputConnection(terrain.GetOutputPort(1))
        sun.SetDateTime("2024-08-15T08:30:00-03:00")
        sky = vtkSkySource()
        sky.SetSunConnection(sun.GetOutputPort())
        sky.SetLevels(6)
        solver = vtkHierarchicalRadiosity()
        solver.AddLightConnection(sun.GetOutputPort())
        solver.AddLightConnection(sky.GetOutputPort(0))
    solver.SetInputConnection(terrain.GetOutputPort(0))
    if far:
        solver.SetFarTerrainConnection(terrain.GetOutputPort(1))
    solver.SetDetailDistance(detail)
    solver._terrain = terrain  # keep the pipeline alive with the solver
    return solver


class FarTerrainOutput(unittest.TestCase):
    def test_every_fourth_post_in_the_terrains_frame(self):
        for dem in (OLINDA, LUXEMBOURG):
            terrain = vtkTerrainSource()
            terrain.SetFileName(dem)
            terrain.SetFarTerrainStride(4)
            terrain.Update(1)
            # Output 1 alone reads no piece of output 0.
            self.assertEqual(terrain.GetOutput(0).GetNumberOfPoints(), 0)
            far = terrain.GetOutput(1)
            self.assertEqual(field_vector(far, "FarTerrainStride"), [4])
            terrain.Update(0)
            fine = terrain.GetOutput(0)
            nx, ny, _ = fine.GetDimensions()
            self.assertEqual(far.GetDimensions()[:2], ((nx - 1) // 4 + 1, (ny - 1) // 4 + 1))
            self.assertEqual(field_vector(far, "GeoOrigin"), field_vector(fine, "GeoOrigin"))
            # A north-up raster's strided rows start at its north edge: the grid's last row.
            offset = (ny - 1) % 4
            fine_posts, far_posts = points_of(fine)[offset::4, ::4], points_of(far)
            valid = np.isfinite(vtk_to_numpy(far.GetPointData().GetArray("Elevation")))
            valid = valid.reshape(far_posts.shape[:2])
            self.assertGreater(valid.sum(), 100)
            np.testing.assert_allclose(far_posts[valid], fine_posts[valid], atol=1e-3)
            # POST_SPACING: a lower bound within 2 % of the narrowest spacing.
            spacing = terrain.GetOutputInformation(0).Get(vtkTerrainSource.POST_SPACING())
            posts = points_of(fine)
            least = min(np.hypot(*np.diff(posts[..., :2], axis=a).reshape(-1, 2).T).min() for a in (0, 1))
            self.assertLessEqual(spacing, least)
            self.assertGreater(spacing, 0.98 * least)

    def test_a_height_field_has_none(self):
        image = vtkImageData()
        image.SetDimensions(9, 9, 1)
        image.SetSpacing(10.0, 10.0, 1.0)
        heights = vtkFloatArray()
        heights.SetNumberOfTuples(81)
        heights.Fill(5.0)
        image.GetPointData().SetScalars(heights)
        terrain = vtkTerrainSource()
        terrain.SetInputData(image)
        terrain.Update(1)
        terrain.Update(0)
        self.assertEqual(terrain.GetOutput(0).GetNumberOfPoints(), 81)
        self.assertEqual(terrain.GetOutput(1).GetNumberOfPoints(), 0)


class PiecesWithTheFarTerrain(unittest.TestCase):
    def pieces_against_one(self, dem, series, names):
        one = solver_on(dem, series)
        one.UpdatePiece(0, 1, 0)
        whole = one.GetOutput()
        nx = whole.GetDimensions()[0]
        read_whole = one.GetInputDataObject(0, 0).GetNumberOfPoints()
        self.assertEqual(read_whole, whole.GetNumberOfPoints())
        expected = {n: vtk_to_numpy(whole.GetPointData().GetArray(n)).reshape(-1, nx) for n in names}
        for pieces in (2, 3):
            for piece in range(pieces):
                solver = solver_on(dem, series)
                solver.UpdatePiece(piece, pieces, 0)
                out = solver.GetOutput()
                e = out.GetExtent()
                read = solver.GetInputDataObject(0, 0)
                # A window: more than the piece, less than the DEM.
                self.assertGreater(read.GetNumberOfPoints(), out.GetNumberOfPoints())
                self.assertLess(read.GetNumberOfPoints(), read_whole)
                # The piece's georeference is the DEM's own, cut to it.
                self.assertEqual(field_vector(out, "RasterSize"), [e[1] - e[0] + 1, e[3] - e[2] + 1])
                for n in names:
                    got = vtk_to_numpy(out.GetPointData().GetArray(n))
                    want = expected[n][e[2]:e[3] + 1, e[0]:e[1] + 1].ravel()
                    np.testing.assert_array_equal(np.isnan(got), np.isnan(want))
                    finite = np.isfinite(want)
                    scale = np.abs(want[finite]).max()
                    self.assertLessEqual(np.abs(got[finite] - want[finite]).max(), 1e-6 * scale,
                                         "%s, piece %d of %d" % (n, piece, pieces))

    def test_olinda_instant(self):
        self.pieces_against_one(OLINDA, False, ("Irradiance", "SkyIrradiance", "ReflectedIrradiance"))

    def test_luxembourg_instant(self):
        self.pieces_against_one(LUXEMBOURG, False, ("Irradiance", "SkyViewFactor"))

    def test_olinda_series(self):
        self.pieces_against_one(OLINDA, True, ("GlobalIrradiation", "SunshineDuration"))

    def test_the_far_terrain_changes_little_and_something(self):
        near = solver_on(OLINDA, far=False)
        near.Update()
        window = solver_on(OLINDA)
        window.Update()
        a, b = (vtk_to_numpy(s.GetOutput().GetPointData().GetArray("Irradiance")) for s in (near, window))
        change = np.abs(a - b).max() / np.abs(a).max()
        self.assertGreater(change, 0.0)
        self.assertLess(change, 0.02)


class FarTerrainRefused(unittest.TestCase):
    def refused(self, dem, stride, port, message):
        """Olinda's solver given output `port` of another source: an error, no output."""
        solver = solver_on(OLINDA)
        other = vtkTerrainSource()
        other.SetFileName(dem)
        other.SetStride(stride)
        solver.SetFarTerrainConnection(other.GetOutputPort(port))
        errors = ErrorCatcher(solver)
        solver.Update()
        self.assertIn(message, errors.text())
        self.assertEqual(solver.GetOutput().GetNumberOfPoints(), 0)

    def test_another_dems_far_terrain(self):
        self.refused(LUXEMBOURG, 1, 1, "are not every 4th post of the terrain")

    def test_a_grid_that_is_no_far_terrain(self):
        self.refused(OLINDA, 4, 0, "must be vtkTerrainSource's output port 1")

    def test_without_a_detail_distance_it_is_ignored_with_a_warning(self):
        solver = solver_on(OLINDA, detail=0.0)
        warnings = []
        solver.AddObserver("WarningEvent", lambda caller, event: warnings.append(event))
        solver.Update()
        self.assertEqual(len(warnings), 1)
        plain = solver_on(OLINDA, detail=0.0, far=False)
        plain.Update()
        a, b = (vtk_to_numpy(s.GetOutput().GetPointData().GetArray("Irradiance")) for s in (solver, plain))
        np.testing.assert_array_equal(a, b)

    def test_the_inputs_are_left_as_they_were(self):
        solver = solver_on(OLINDA)
        solver.UpdatePiece(1, 3, 0)
        read = solver.GetInputDataObject(0, 0)
        e = read.GetExtent()
        # The window keeps the georeference the source gave it: its own rows.
        self.assertEqual(field_vector(read, "RasterSize"), [e[1] - e[0] + 1, e[3] - e[2] + 1])
        self.assertIsNone(read.GetPointData().GetArray("Irradiance"))


if __name__ == "__main__":
    unittest.main()
