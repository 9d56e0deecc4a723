"""Scenes the examples light, built in code: the paper's house and trees on a small
terrain (Figs. 5 to 8), and a sun or sky given directly by angles."""
import math

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkTrivialProducer
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource, vtkTessellatedBoxSource

from terralux import vtkSkySource, vtkTerrainSource


def height_field(posts, spacing, height):
    """A terrain grid (vtkTerrainSource over an image of heights) centred on the origin;
    height(x, y) in metres."""
    image = vtkImageData()
    image.SetDimensions(posts, posts, 1)
    image.SetSpacing(spacing, spacing, 1.0)
    half = 0.5 * spacing * (posts - 1)
    image.SetOrigin(-half, -half, 0.0)
    heights = vtkFloatArray()
    heights.SetNumberOfTuples(posts * posts)
    for j in range(posts):
        for i in range(posts):
            heights.SetValue(i + j * posts, height(i * spacing - half, j * spacing - half))
    image.GetPointData().SetScalars(heights)
    terrain = vtkTerrainSource()
    terrain.SetInputData(image)
    terrain.Update()
    grid = terrain.GetOutput().NewInstance()
    grid.DeepCopy(terrain.GetOutput())
    return grid


def box(bounds, level):
    """A closed box of outward quads, each face split level x level."""
    source = vtkTessellatedBoxSource()
    source.SetBounds(*bounds)
    source.SetLevel(level)
    source.QuadsOn()
    source.Update()
    result = vtkPolyData()
    result.DeepCopy(source.GetOutput())
    return result


def tree(x, y, crown_radius=3.0, crown_height=7.0, resolution=16):
    """A tree as closed triangle meshes: a trunk box and a sphere crown."""
    crown = vtkSphereSource()
    crown.SetCenter(x, y, crown_height)
    crown.SetRadius(crown_radius)
    crown.SetThetaResolution(resolution)
    crown.SetPhiResolution(max(6, 3 * resolution // 4))
    both = vtkAppendPolyData()
    both.AddInputConnection(crown.GetOutputPort())
    both.AddInputData(box((x - 0.3, x + 0.3, y - 0.3, y + 0.3, -1.0, crown_height - crown_radius + 0.5), 1))
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(both.GetOutputPort())
    triangles.Update()
    result = vtkPolyData()
    result.DeepCopy(triangles.GetOutput())
    return result


HOUSE = (-5.0, 5.0, -4.0, 4.0, -1.0, 6.0)  # 10 x 8 m, 6 m above the ground at its centre
TREES = ((12.0, 6.0), (-11.0, -9.0))


def house_and_trees(quick=False):
    """The paper's Figs. 5-8 scene: a house and two trees on an 80 m hill, gently rising
    and curved. Blocks: 0 terrain, 1 house, 2 and 3 the trees."""
    posts = 21 if quick else 41
    spacing = 80.0 / (posts - 1)
    blocks = vtkMultiBlockDataSet()
    blocks.SetNumberOfBlocks(2 + len(TREES))
    blocks.SetBlock(0, height_field(posts, spacing, lambda x, y: 0.02 * x + 0.01 * y - 0.0004 * (x * x + y * y)))
    blocks.SetBlock(1, box(HOUSE, 1 if quick else 2))
    for k, (x, y) in enumerate(TREES):
        blocks.SetBlock(2 + k, tree(x, y, resolution=10 if quick else 16))
    for k, name in enumerate(("terrain", "house", "tree 1", "tree 2")):
        blocks.GetMetaData(k).Set(vtkMultiBlockDataSet.NAME(), name)
    return blocks


def sun_at(altitude_deg, compass_azimuth_deg, normal_irradiance):
    """A sun as vtkHierarchicalRadiosity reads it (vtkSunSource's field data), at exact
    angles, for scenes that are not on a real place: a producer to connect with
    AddLightConnection(sun.GetOutputPort())."""
    sun = vtkPolyData()
    a, z = math.radians(altitude_deg), math.radians(compass_azimuth_deg)
    direction = vtkDoubleArray()
    direction.SetName("SunDirection")
    for value in (math.sin(z) * math.cos(a), math.cos(z) * math.cos(a), math.sin(a)):
        direction.InsertNextValue(value)
    irradiance = vtkDoubleArray()
    irradiance.SetName("SunNormalIrradiance")
    irradiance.InsertNextValue(normal_irradiance)
    sun.GetFieldData().AddArray(direction)
    sun.GetFieldData().AddArray(irradiance)
    producer = vtkTrivialProducer()
    producer.SetOutput(sun)
    return producer


def clear_sky(sun_altitude_deg, sun_azimuth_deg, diffuse=100.0, levels=6, dome_radius=60.0):
    """A CIE clear sky (type 12) for a sun at the given angles, scaled to `diffuse` W/m^2
    on a horizontal plane; its dome output (port 1) has the given radius."""
    sky = vtkSkySource()
    sky.UseSunSourceOff()
    sky.SetSkyModelToCIEGeneral()
    sky.SetSkyType(12)
    sky.SetSunZenith(90.0 - sun_altitude_deg)
    sky.SetSunAzimuth(sun_azimuth_deg)
    sky.SetDiffuseHorizontalIrradiance(diffuse)
    sky.SetLevels(levels)
    sky.SetDomeRadius(dome_radius)
    sky.Update()
    return sky
