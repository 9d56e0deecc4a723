#include "accuracy_scenes.h"

#include "fractal_dem.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSphereSource.h"
#include "vtkSkySource.h"
#include "vtkStructuredGrid.h"
#include "vtkSunSource.h"
#include "vtkTerrainSource.h"
#include "vtkTessellatedBoxSource.h"
#include "vtkTriangleFilter.h"

#include <cmath>
#include <functional>
#include <stdexcept>

namespace terralux_bench
{
namespace
{
constexpr double degree = 3.14159265358979323846 / 180.0;

// A sun as vtkHierarchicalRadiosity reads it: field data SunDirection and
// SunNormalIrradiance (what vtkSunSource writes), for an exact altitude and azimuth.
vtkSmartPointer<vtkDataObject> sunAt(double altitudeDeg, double compassAzimuthDeg, double normalIrradiance)
{
  auto sun = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkDoubleArray> direction, irradiance;
  direction->SetName("SunDirection");
  const double a = altitudeDeg * degree, z = compassAzimuthDeg * degree;
  direction->InsertNextValue(std::sin(z) * std::cos(a));
  direction->InsertNextValue(std::cos(z) * std::cos(a));
  direction->InsertNextValue(std::sin(a));
  irradiance->SetName("SunNormalIrradiance");
  irradiance->InsertNextValue(normalIrradiance);
  sun->GetFieldData()->AddArray(direction);
  sun->GetFieldData()->AddArray(irradiance);
  return sun;
}

vtkSmartPointer<vtkDataObject> skyMap(int model, int type, double sunZenithDeg, double sunAzimuthDeg, double diffuse)
{
  vtkNew<vtkSkySource> sky;
  sky->UseSunSourceOff();
  sky->SetSkyModel(model);
  sky->SetSkyType(type);
  sky->SetSunZenith(sunZenithDeg);
  sky->SetSunAzimuth(sunAzimuthDeg);
  sky->SetDiffuseHorizontalIrradiance(diffuse);
  sky->Update();
  vtkSmartPointer<vtkDataObject> map;
  map.TakeReference(sky->GetRadianceOutput()->NewInstance());
  map->DeepCopy(sky->GetRadianceOutput());
  return map;
}

// One sun `altitude` deg up toward compass `azimuth` (800 W/m^2) and its CIE clear sky
// (100 W/m^2 diffuse on the horizontal): the scene's lights, and what it records of them.
void sunAndClearSky(
  AccuracyScene& scene, double altitude, double azimuth, double normalIrradiance = 800.0, double diffuse = 100.0)
{
  scene.lights = { sunAt(altitude, azimuth, normalIrradiance),
    skyMap(vtkSkySource::CIE_GENERAL, 12, 90.0 - altitude, azimuth, diffuse) };
  scene.sunAltitude = altitude;
  scene.sunAzimuth = azimuth;
  scene.sunIrradiance = normalIrradiance;
  scene.diffuseHorizontal = diffuse;
}

vtkSmartPointer<vtkDataObject> heightField(int n, double spacing, const std::function<double(int, int)>& height)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, 1);
  image->SetSpacing(spacing, spacing, 1.0);
  image->SetOrigin(-0.5 * spacing * (n - 1), -0.5 * spacing * (n - 1), 0.0);
  vtkNew<vtkFloatArray> heights;
  heights->SetNumberOfTuples(static_cast<vtkIdType>(n) * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      heights->SetValue(i + static_cast<vtkIdType>(j) * n, static_cast<float>(height(i, j)));
  image->GetPointData()->SetScalars(heights);
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetInputData(image);
  terrain->Update();
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->DeepCopy(terrain->GetOutput());
  return grid;
}

vtkSmartPointer<vtkPolyData> box(double x0, double x1, double y0, double y1, double z0, double z1, int level)
{
  vtkNew<vtkTessellatedBoxSource> source;
  source->SetBounds(x0, x1, y0, y1, z0, z1);
  source->SetLevel(level);
  source->QuadsOn();
  source->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->DeepCopy(source->GetOutput());
  return result;
}
} // namespace

std::vector<std::string> accuracySceneNames()
{
  return { "olinda", "fractal", "hills", "crater", "canyon", "box", "house-sky", "house-sun", "olinda-sky", "olinda-black",
    "steep-morning", "steep-noon", "gentle-morning", "snowbowl", "ridges" };
}

namespace
{
// (d) A house and two trees on a small hill (the paper's Figs. 5-8): a terrain grid, a
// box house and trees as closed triangle meshes (trunk box, crown sphere).
// An n x n fractal DEM at 30 m (roughness 0.55) under a sun `altitude` deg up (800
// W/m^2) toward compass `azimuth` and the matching CIE clear sky (100 W/m^2).
void fractalTerrain(AccuracyScene& scene, int n, std::uint32_t seed, double reliefM, double altitude,
  double azimuth, double reflectance)
{
  const std::vector<float> heights = fractalHeights(n, seed, 0.55, reliefM);
  scene.geometry = heightField(n, 30.0, [&](int i, int j) { return heights[static_cast<std::size_t>(j) * n + i]; });
  sunAndClearSky(scene, altitude, azimuth);
  scene.reflectance = reflectance;
  scene.terrain = true;
}

// The centre 129 x 129 posts of a benchmark DEM (make_fractal_dem 1025 posts, seed 1):
// the steep one (3000 m relief: mean slope 15 deg, p95 28 deg; the crop 17 and 30 deg)
// or the gentle one (1500 m), under a sun `altitude` deg up toward compass `azimuth` and
// its CIE clear sky.
void benchmarkCrop(AccuracyScene& scene, double reliefM, double altitude, double azimuth, double reflectance,
  double normalIrradiance = 800.0, double diffuse = 100.0)
{
  constexpr int full = 1025, n = 129, first = (full - n) / 2;
  const std::vector<float> heights = fractalHeights(full, 1, 0.55, reliefM);
  scene.geometry = heightField(
    n, 30.0, [&](int i, int j) { return heights[static_cast<std::size_t>(first + j) * full + first + i]; });
  sunAndClearSky(scene, altitude, azimuth, normalIrradiance, diffuse);
  scene.reflectance = reflectance;
  scene.terrain = true;
}

// A real DEM (a pixel window of it, or all of it when `window` is null) under the sun
// and CIE clear sky (type 12) of `dateTime` at its centre, reflectance 0.2.
void realTerrain(AccuracyScene& scene, const std::string& file, const int* window, const char* dateTime)
{
  vtkNew<vtkTerrainSource> terrain;
  terrain->SetFileName(file.c_str());
  if (window)
    terrain->SetPixelWindow(window[0], window[1], window[2], window[3]);
  vtkNew<vtkSunSource> sun;
  sun->SetInputConnection(terrain->GetOutputPort());
  sun->SetDateTime(dateTime);
  vtkNew<vtkSkySource> sky;
  sky->SetSunConnection(sun->GetOutputPort());
  sky->SetSkyType(12);
  terrain->Update();
  if (terrain->GetOutput()->GetNumberOfPoints() == 0)
    throw std::runtime_error(file + " is missing: run cmake/install-dependencies.sh");
  sun->Update();
  sky->Update();
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->DeepCopy(terrain->GetOutput());
  scene.geometry = grid;
  auto sunData = vtkSmartPointer<vtkPolyData>::New();
  sunData->DeepCopy(sun->GetOutput());
  auto map = vtkSmartPointer<vtkImageData>::New();
  map->DeepCopy(sky->GetRadianceOutput());
  scene.lights = { sunData, map };
  scene.reflectance = 0.2;
  scene.terrain = true;
}

void houseAndTrees(AccuracyScene& scene, bool withSun)
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetNumberOfBlocks(4);
  blocks->SetBlock(0, heightField(41, 2.0, [](int i, int j) {
    const double x = (i - 20) * 2.0, y = (j - 20) * 2.0;
    return 0.02 * x + 0.01 * y - 0.0004 * (x * x + y * y); // a gentle rise, curved
  }));
  blocks->SetBlock(1, box(-5, 5, -4, 4, -1.0, 6.0, 2));
  auto tree = [](double x, double y) {
    vtkNew<vtkSphereSource> crown;
    crown->SetCenter(x, y, 7.0);
    crown->SetRadius(3.0);
    crown->SetThetaResolution(16);
    crown->SetPhiResolution(12);
    crown->Update();
    vtkNew<vtkAppendPolyData> both;
    both->AddInputData(crown->GetOutput());
    both->AddInputData(box(x - 0.3, x + 0.3, y - 0.3, y + 0.3, -1.0, 4.5, 1));
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputConnection(both->GetOutputPort());
    triangles->Update();
    auto result = vtkSmartPointer<vtkPolyData>::New();
    result->DeepCopy(triangles->GetOutput());
    return result;
  };
  blocks->SetBlock(2, tree(12.0, 6.0));
  blocks->SetBlock(3, tree(-11.0, -9.0));
  scene.geometry = blocks;
  scene.lights = { skyMap(vtkSkySource::CIE_GENERAL, 12, 55.0, 160.0, 100.0) };
  if (withSun)
    scene.lights.push_back(sunAt(35.0, 160.0, 800.0));
  scene.reflectance = 0.3;
  scene.description = std::string("house 10 x 8 x 6 m and two trees on an 80 m hill, CIE 12 sky (100 W/m^2)") +
    (withSun ? " and sun 35 deg up (800 W/m^2)" : ", sky only") + ", reflectance 0.3";
}
} // namespace

AccuracyScene makeAccuracyScene(const std::string& name, const std::string& dataDir)
{
  AccuracyScene scene;
  scene.name = name;
  if (name == "olinda")
  {
    // (a) The paper's Fig. 4: Olinda on an August morning, sun and CIE clear sky.
    realTerrain(scene, dataDir + "/olinda_dem_utm25s.tif", nullptr, "2024-08-15T08:30:00-03:00");
    scene.description = "Olinda SRTM DEM 111 x 111, 2024-08-15 08:30 -03:00, ESRA sun + CIE 12 sky, reflectance 0.2";
  }
  else if (name == "ridges")
  {
    // (a') A rough real DEM: the centre 129 x 129 posts of the Jacksboro fault's ridges
    // and valleys (3 arc-seconds, 74 x 93 m; mean slope 16 deg, p95 26 deg) on a
    // December morning, the sun 16 deg up in the south-east (09:00 local solar time).
    const int window[4] = { 137, 107, 129, 129 };
    realTerrain(scene, dataDir + "/jacksboro_fault_dem.tif", window, "2024-12-21T09:35:00-05:00");
    scene.description =
      "Jacksboro fault ridges 129 x 129 (3 arc-seconds), 2024-12-21 09:35 -05:00, ESRA sun + CIE 12 sky, reflectance 0.2";
  }
  else if (name == "house-sky" || name == "house-sun")
  {
    houseAndTrees(scene, name == "house-sun");
  }
  else if (name == "olinda-sky" || name == "olinda-black")
  {
    // Work follows the scene: Olinda with the sun below the horizon (sky alone), or with
    // every reflectance 0 (no interreflection to compute).
    scene = makeAccuracyScene("olinda", dataDir);
    scene.name = name;
    if (name == "olinda-sky")
    {
      scene.lights = { scene.lights[1], sunAt(-5.0, 90.0, 800.0) };
      scene.description = "Olinda, CIE 12 sky, a sun 5 deg below the horizon";
    }
    else
    {
      scene.reflectance = 0.0;
      scene.description = "Olinda as (a), reflectance 0";
    }
  }
  else if (name == "fractal")
  {
    // (b) Steep fractal relief, winter sun 10.7 deg up: long shadows, strong interreflection.
    fractalTerrain(scene, 129, 3, 800.0, 10.7, 160.0, 0.5);
    scene.description = "fractal DEM 129 x 129 at 30 m, 800 m relief, sun 10.7 deg up (800 W/m^2) + CIE 12 sky (100 W/m^2), reflectance 0.5";
  }
  else if (name == "hills")
  {
    // (b') The scale benchmarks' terrain (make_fractal_dem: roughness 0.55, its finest
    // scales as on the 1025^2 DEM), a morning sun 25 deg up: mostly open slopes, where
    // light from surfaces is small and smooth.
    fractalTerrain(scene, 257, 1, 450.0, 25.0, 120.0, 0.2);
    scene.description = "fractal hills 257 x 257 at 30 m, 450 m relief, sun 25 deg up (800 W/m^2) + CIE 12 sky (100 W/m^2), reflectance 0.2";
  }
  else if (name == "steep-morning" || name == "steep-noon")
  {
    // (b'') Steep mountains as real DEMs have them, a winter morning sun 8 deg up in the
    // south-east, or the winter noon sun 22 deg up in the south.
    const bool morning = name == "steep-morning";
    benchmarkCrop(scene, steepReliefM, morning ? 8.0 : 22.0, morning ? 135.0 : 180.0, 0.5);
    scene.description = std::string("steep fractal 129 x 129 at 30 m (crop of the 1025^2 steep DEM), sun ") +
      (morning ? "8 deg up in the SE" : "22 deg up in the S") + " (800 W/m^2) + CIE 12 sky (100 W/m^2), reflectance 0.5";
  }
  else if (name == "gentle-morning")
  {
    // (b''') The gentle benchmark DEM under its benchmarks' winter morning sun, 9 deg up
    // in the SE, with the clear sky's irradiances there (ESRA, Linke 3; vtkSunSource's
    // defaults): the defaults' horizons take 16 azimuths.
    benchmarkCrop(scene, gentleReliefM, 9.0, 135.0, 0.2, 450.0, 44.0);
    scene.description = "gentle fractal 129 x 129 at 30 m (crop of the 1025^2 gentle DEM), sun 9 deg up in the SE "
                        "(450 W/m^2) + CIE 12 sky (44 W/m^2), reflectance 0.2";
  }
  else if (name == "snowbowl")
  {
    // (c') A snowy bowl with small-scale relief on its walls (ridges and gullies of a
    // few tens of metres), reflectance 0.8, a winter morning sun 10 deg up.
    // A paraboloid 1100 m in radius, continued by its tangent cone, and the relief
    // (centred on 0) growing from the floor to the rim.
    const int n = 129;
    constexpr double reliefM = 80.0;
    const std::vector<float> relief = fractalHeights(n, 7, 0.6, reliefM);
    scene.geometry = heightField(n, 15.0, [&](int i, int j) {
      const double x = (i - 64) * 15.0, y = (j - 64) * 15.0, r = std::sqrt(x * x + y * y) / 1100.0;
      const double ridges = relief[static_cast<std::size_t>(j) * n + i] - (200.0 + 0.5 * reliefM); // heights start at 200 m
      return 1000.0 + 400.0 * (r < 1.0 ? r * r : 2.0 * r - 1.0) + std::min(1.0, r) * ridges;
    });
    sunAndClearSky(scene, 10.0, 135.0);
    scene.reflectance = 0.8;
    scene.terrain = true;
    scene.description = "snowy bowl 129 x 129 at 15 m, 400 m deep over its 1100 m radius, 80 m fractal relief on its walls, sun 10 deg up "
                        "in the SE (800 W/m^2) + CIE 12 sky (100 W/m^2), reflectance 0.8";
  }
  else if (name == "crater")
  {
    // (c) A snowy bowl: reflectance 0.8, sun 20 deg up; light bounces across the floor.
    const int n = 65;
    scene.geometry = heightField(n, 30.0, [&](int i, int j) {
      const double x = (i - 32) * 30.0, y = (j - 32) * 30.0, r = std::sqrt(x * x + y * y) / 960.0;
      return 1000.0 + 400.0 * std::min(r * r, 1.0 + 2.0 * (r - 1.0));
    });
    sunAndClearSky(scene, 20.0, 180.0);
    scene.reflectance = 0.8;
    scene.terrain = true;
    scene.description = "bowl crater 65 x 65 at 30 m, 400 m deep, sun 20 deg up (800 W/m^2) + CIE 12 sky (100 W/m^2), reflectance 0.8";
  }
  else if (name == "canyon")
  {
    // (e) An urban canyon: a street between two long blocks, a low sun across it.
    vtkNew<vtkPlaneSource> street;
    // The street runs between the blocks' walls (its edges are their feet), not under them.
    street->SetOrigin(-60, -6, 0);
    street->SetPoint1(60, -6, 0);
    street->SetPoint2(-60, 6, 0);
    street->SetResolution(48, 8);
    street->Update();
    auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    blocks->SetNumberOfBlocks(3);
    blocks->SetBlock(0, street->GetOutput());
    blocks->SetBlock(1, box(-50, 50, -16, -6, 0, 15, 3));
    blocks->SetBlock(2, box(-50, 50, 6, 16, 0, 15, 3));
    scene.geometry = blocks;
    sunAndClearSky(scene, 25.0, 200.0);
    scene.reflectance = 0.3;
    scene.description = "street 12 m wide between 15 m blocks, sun 25 deg up across it (800 W/m^2) + CIE 12 sky, reflectance 0.3";
  }
  else if (name == "box")
  {
    // (f) The closed box of inward faces: radiosity 200 everywhere, exactly.
    vtkNew<vtkTriangleFilter> triangles;
    vtkNew<vtkTessellatedBoxSource> source;
    source->SetLevel(4);
    source->QuadsOn();
    triangles->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkReverseSense> inward;
    inward->SetInputConnection(triangles->GetOutputPort());
    inward->ReverseCellsOn();
    inward->Update();
    auto closed = vtkSmartPointer<vtkPolyData>::New();
    closed->DeepCopy(inward->GetOutput());
    vtkNew<vtkDoubleArray> emission;
    emission->SetName("Emission");
    emission->SetNumberOfTuples(closed->GetNumberOfCells());
    emission->Fill(100.0);
    closed->GetCellData()->AddArray(emission);
    scene.geometry = closed;
    scene.reflectance = 0.5;
    scene.emissionArray = "Emission";
    scene.description = "closed box of inward faces (vtkTessellatedBoxSource level 4), emission 100, reflectance 0.5";
  }
  else
  {
    throw std::runtime_error("unknown scene '" + name + "'");
  }
  return scene;
}
} // namespace terralux_bench
