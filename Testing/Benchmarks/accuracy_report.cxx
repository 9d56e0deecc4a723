// The accuracy report's worker: one scene, against the independent reference.
//   accuracy_report SCENE OUTDIR reference [SAMPLES]   compute OUTDIR/SCENE.reference
//   accuracy_report SCENE OUTDIR solve METHOD TOLERANCE [TARGET_ERROR]  one solve, one JSON line
// METHOD: points (EvaluateAtPoints on), rays (on, with SkyFromHorizons off: the sky's
// hidden part from the gather's rays), averaged (off), triangles (terrain as two
// triangles per cell, at points). The JSON line holds wall time, peak memory, elements,
// links, rays, the floor (one occlusion ray per point toward the sun) and, per component
// (sun, sky, reflected, global), RMS, 95th percentile, maximum and bias of the error over
// the reference's mean, with the reference's own standard error. run_accuracy_report.sh
// sweeps them and Testing/Benchmarks/accuracy_report.py writes the tables and plots.
#include "base/angles.h"
#include "accuracy_scenes.h"
#include "path_tracer.h"
#include "reference_scene.h"
#include "vtkRadiosityScene.h"
#include "vtkDataSetAttributes.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStructuredGrid.h"
#include "vtkUnsignedCharArray.h"
#include "vtkFieldData.h"
#include "vtkIntArray.h"

#include "terrain/terrain_grid.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkHierarchicalRadiosity.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <sys/resource.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

using terralux::Vec3;

namespace
{
struct ReferencePoint
{
  double used = 0, sunFacing = 0, sun = 0, sky = 0, skyError = 0, reflected = 0, reflectedError = 0, global = 0,
         globalError = 0;
};

double seconds(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peakMiB()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// The scene as the engine's description (shared with the reference) and every output
// point with its normal: terrain posts with their area-weighted post normal, polygon
// points with the area-weighted normal of the polygons around them, or on a crease one
// normal per side (polygons within 20 degrees of each other), the point's value being
// the area-weighted mean over its sides (TerraLux's definition of a point's value).
struct ScenePoints
{
  vtkRadiosityScene scene;
  std::vector<Vec3> points, normals;
  std::vector<bool> used;
  /// Extra sides of crease points: (point index, normal, weight); the first side's
  /// normal is in `normals`, its weight in `firstWeight`.
  std::vector<std::pair<std::size_t, std::pair<Vec3, double>>> moreSides;
  std::vector<double> firstWeight;
  std::vector<Vec3> moreSidePoints; ///< where each extra side is evaluated
};

void loadScene(const terralux_bench::AccuracyScene& input, ScenePoints& out)
{
  for (vtkDataSet* data : vtkRadiosityScene::DataSetsOf(input.geometry))
    out.scene.AddDataSet(data, input.reflectance, nullptr, input.emissionArray, true);
  for (const auto& light : input.lights)
    out.scene.AddLight(light);
  // The ray offset both TerraLux and the reference use: 1e-5 of the scene's diagonal.
  const double offset = out.scene.Scene.polygons.empty() ? 0.0 : [&]() {
    Vec3 low(1e300), high(-1e300);
    for (const Vec3& p : out.scene.Scene.points)
    {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
    return 1e-5 * glm::length(high - low);
  }();
  for (std::size_t k = 0; k < out.scene.Inputs.size(); ++k)
  {
    const vtkRadiosityScene::Input& in = out.scene.Inputs[k];
    if (in.terrain >= 0)
    {
      const terralux::TerrainGrid& grid = *out.scene.Terrains[in.terrain];
      for (int j = 0; j < grid.postsY(); ++j)
        for (int i = 0; i < grid.postsX(); ++i)
        {
          out.points.push_back(grid.post(i, j));
          out.normals.push_back(grid.postNormal(i, j));
          out.used.push_back(grid.postUsed(i, j));
        }
      continue;
    }
    const vtkIdType count = in.data->GetNumberOfPoints();
    struct Side
    {
      Vec3 normalSum;
      double area;
      Vec3 centroidSum; // area-weighted centroid of its polygons
    };
    std::vector<std::vector<Side>> sides(count);
    for (const terralux::ScenePolygon& polygon : out.scene.Scene.polygons)
    {
      if (polygon.owner != static_cast<int>(k))
        continue;
      Vec3 area(0.0);
      for (int c = 0; c < polygon.vertexCount; ++c)
        area += glm::cross(out.scene.Scene.points[polygon.vertices[c]],
          out.scene.Scene.points[polygon.vertices[(c + 1) % polygon.vertexCount]]);
      const double a = 0.5 * glm::length(area);
      if (!(a > 0.0))
        continue;
      const Vec3 n = 0.5 * area / a;
      Vec3 centroid(0.0);
      for (int c = 0; c < polygon.vertexCount; ++c)
        centroid += out.scene.Scene.points[polygon.vertices[c]] / static_cast<double>(polygon.vertexCount);
      for (int c = 0; c < polygon.vertexCount; ++c)
      {
        auto& list = sides[polygon.vertices[c] - in.firstPoint];
        auto side = std::find_if(
          list.begin(), list.end(), [&](const Side& s) { return glm::dot(glm::normalize(s.normalSum), n) > 0.94; });
        if (side == list.end())
          list.push_back({ a * n, a, a * centroid });
        else
        {
          side->normalSum += a * n;
          side->area += a;
          side->centroidSum += a * centroid;
        }
      }
    }
    for (vtkIdType p = 0; p < count; ++p)
    {
      const std::size_t index = out.points.size();
      const Vec3 point = out.scene.Scene.points[in.firstPoint + p];
      // Each side is evaluated two ray offsets into its polygons, as TerraLux does: the
      // limit of the value from inside the face (a junction point lies on the other face).
      auto into = [&](const Side& side) {
        const Vec3 toward = side.centroidSum / side.area - point;
        const double distance = glm::length(toward);
        return distance > 0.0 ? point + std::min(0.5, 2.0 * offset / distance) * toward : point;
      };
      out.points.push_back(sides[p].empty() ? point : into(sides[p][0]));
      out.used.push_back(!sides[p].empty());
      out.normals.push_back(sides[p].empty() ? Vec3(0, 0, 1) : glm::normalize(sides[p][0].normalSum));
      out.firstWeight.resize(out.points.size(), 1.0);
      if (!sides[p].empty())
        out.firstWeight[index] = sides[p][0].area;
      for (std::size_t s = 1; s < sides[p].size(); ++s)
        out.moreSides.push_back({ index, { glm::normalize(sides[p][s].normalSum), sides[p][s].area } });
      for (std::size_t s = 1; s < sides[p].size(); ++s)
        out.moreSidePoints.push_back(into(sides[p][s]));
    }
  }
  out.firstWeight.resize(out.points.size(), 1.0);
}

// The slopes of a scene's points (their normals' angles from the zenith, degrees):
// mean and 95th percentile, as a DEM's users state how steep it is.
int describe(const terralux_bench::AccuracyScene& input)
{
  ScenePoints s;
  loadScene(input, s);
  std::vector<double> slopes;
  for (std::size_t k = 0; k < s.points.size(); ++k)
    if (s.used[k])
      slopes.push_back(std::acos(std::clamp(s.normals[k].z, -1.0, 1.0)) / terralux::degree);
  double mean = 0.0;
  for (double slope : slopes)
    mean += slope / std::max<std::size_t>(1, slopes.size());
  std::sort(slopes.begin(), slopes.end());
  const double p95 = slopes.empty() ? 0.0 : slopes[static_cast<std::size_t>(0.95 * (slopes.size() - 1))];
  std::printf("{\"scene\": \"%s\", \"points\": %zu, \"mean_slope_deg\": %.2f, \"p95_slope_deg\": %.2f, "
              "\"terrain\": %s, \"reflectance\": %g, \"sun_altitude_deg\": %g, \"sun_azimuth_deg\": %g, "
              "\"sun_normal_irradiance\": %g, \"diffuse_horizontal\": %g}\n",
    input.name.c_str(), slopes.size(), mean, p95, input.terrain ? "true" : "false", input.reflectance,
    input.sunAltitude, input.sunAzimuth, input.sunIrradiance, input.diffuseHorizontal);
  return 0;
}

int computeReference(const terralux_bench::AccuracyScene& input, const std::string& path, int samples)
{
  ScenePoints s;
  loadScene(input, s);
  const auto start = std::chrono::steady_clock::now();
  const terralux_reference::ReferenceScene reference(s.scene.Scene);
  const terralux_reference::PathTracer tracer(reference, s.scene.Sky.get(), terralux_reference::referenceSuns(s.scene.Suns));
  auto estimates = tracer.irradianceAt(s.points, s.normals, samples);
  if (!s.moreSides.empty())
  {
    // Crease points: the area-weighted mean over their sides.
    std::vector<Vec3> points, normals;
    for (std::size_t m = 0; m < s.moreSides.size(); ++m)
    {
      points.push_back(s.moreSidePoints[m]);
      normals.push_back(s.moreSides[m].second.first);
    }
    const auto extra = tracer.irradianceAt(points, normals, samples);
    std::vector<double> weight(s.points.size());
    for (std::size_t k = 0; k < s.points.size(); ++k)
      weight[k] = s.firstWeight[k];
    auto scale = [](terralux_reference::ReferenceIrradiance& e, double w) {
      for (auto* c : { &e.sun, &e.sky, &e.reflected, &e.global })
      {
        c->mean *= w;
        c->standardError *= w; // added as variances below
        c->standardError *= c->standardError;
      }
    };
    for (std::size_t k = 0; k < s.points.size(); ++k)
      scale(estimates[k], weight[k]);
    for (std::size_t m = 0; m < extra.size(); ++m)
    {
      auto e = extra[m];
      const std::size_t k = s.moreSides[m].first;
      scale(e, s.moreSides[m].second.second);
      weight[k] += s.moreSides[m].second.second;
      auto* to = &estimates[k];
      const terralux_reference::Estimate* from[4] = { &e.sun, &e.sky, &e.reflected, &e.global };
      terralux_reference::Estimate* into[4] = { &to->sun, &to->sky, &to->reflected, &to->global };
      for (int c = 0; c < 4; ++c)
      {
        into[c]->mean += from[c]->mean;
        into[c]->standardError += from[c]->standardError;
      }
    }
    for (std::size_t k = 0; k < s.points.size(); ++k)
      for (auto* c : { &estimates[k].sun, &estimates[k].sky, &estimates[k].reflected, &estimates[k].global })
      {
        c->mean /= weight[k];
        c->standardError = std::sqrt(c->standardError) / weight[k];
      }
  }
  // Which band of reflected light a point falls in, from an estimate of its own (an
  // eighth of the directions, seeds 2^40 draws away, its first side alone): chosen by
  // the reference itself, a band would hold the points its noise pushed in, and read
  // every solve low against it at the band's lower edge (docs/benchmarks.md).
  constexpr std::uint64_t bandSeeds = std::uint64_t(1) << 40;
  const auto forBands = tracer.irradianceAt(s.points, s.normals, std::max(64, samples / 8), bandSeeds);
  std::vector<ReferencePoint> values(s.points.size());
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    const auto& e = estimates[k];
    bool facing = false;
    for (const auto& sun : terralux_reference::referenceSuns(s.scene.Suns))
      facing = facing || glm::dot(s.normals[k], sun.direction) > 0.0;
    values[k] = { s.used[k] ? 1.0 : 0.0, facing ? 1.0 : 0.0, e.sun.mean, e.sky.mean, e.sky.standardError,
      e.reflected.mean, e.reflected.standardError, e.global.mean, e.global.standardError };
  }
  std::ofstream file(path, std::ios::binary);
  const std::uint64_t n = values.size();
  file.write(reinterpret_cast<const char*>(&n), sizeof n);
  file.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(n * sizeof(ReferencePoint)));
  // Beside it, so that earlier releases' solves still read the reference.
  std::vector<double> bands(n);
  for (std::size_t k = 0; k < n; ++k)
    bands[k] = forBands[k].reflected.mean;
  std::ofstream bandFile(path + ".bands", std::ios::binary);
  bandFile.write(reinterpret_cast<const char*>(bands.data()), static_cast<std::streamsize>(n * sizeof(double)));
  std::printf("{\"scene\": \"%s\", \"reference_seconds\": %.3f, \"points\": %zu, \"samples\": %d}\n",
    input.name.c_str(), seconds(start), values.size(), samples);
  return 0;
}

// How well the filter's IrradianceError estimates the error of the global irradiance
// over the points where `include` holds: the share of points whose difference from the
// reference lies within the estimate (widened, in quadrature, by twice the reference's
// own standard error), and the estimate's median over the mean global. null without it.
std::string estimateJson(const std::vector<double>& estimate, const std::vector<double>& value,
  const std::vector<double>& reference, const std::vector<double>& referenceError, const std::vector<bool>& include)
{
  std::vector<double> estimates;
  double sumRef = 0.0;
  std::size_t covered = 0;
  for (std::size_t k = 0; k < value.size(); ++k)
  {
    if (!include[k] || !std::isfinite(estimate[k]))
      continue;
    estimates.push_back(estimate[k]);
    sumRef += reference[k];
    covered += std::abs(value[k] - reference[k]) <= std::hypot(estimate[k], 2.0 * referenceError[k]);
  }
  if (estimates.empty())
    return "null";
  const double meanGlobal = sumRef / estimates.size();
  std::nth_element(estimates.begin(), estimates.begin() + estimates.size() / 2, estimates.end());
  char text[200];
  std::snprintf(text, sizeof text, "{\"coverage\": %.4f, \"median\": %.6g}",
    static_cast<double>(covered) / estimates.size(), meanGlobal > 0.0 ? estimates[estimates.size() / 2] / meanGlobal : 0.0);
  return text;
}

// Error figures of one component over the points where `include` holds.
std::string errorJson(const std::vector<double>& value, const std::vector<double>& reference,
  const std::vector<double>& referenceError, const std::vector<bool>& include)
{
  double sumRef = 0.0, sumDiff = 0.0, sumSq = 0.0, sumSe = 0.0, worst = 0.0;
  std::vector<double> absolute;
  for (std::size_t k = 0; k < value.size(); ++k)
  {
    if (!include[k])
      continue;
    const double d = value[k] - reference[k];
    sumRef += reference[k];
    sumDiff += d;
    sumSq += d * d;
    sumSe += referenceError[k];
    worst = std::max(worst, std::abs(d));
    absolute.push_back(std::abs(d));
  }
  const double n = std::max<std::size_t>(1, absolute.size());
  const double mean = sumRef / n;
  std::sort(absolute.begin(), absolute.end());
  const double p95 = absolute.empty() ? 0.0 : absolute[static_cast<std::size_t>(0.95 * (absolute.size() - 1))];
  auto relative = [mean](double x) { return mean > 0.0 ? x / mean : 0.0; };
  char text[400];
  std::snprintf(text, sizeof text,
    "{\"mean\": %.6g, \"rms\": %.6g, \"p95\": %.6g, \"max\": %.6g, \"bias\": %.6g, \"reference_error\": %.6g}", mean,
    relative(std::sqrt(sumSq / n)), relative(p95), relative(worst), relative(sumDiff / n), relative(sumSe / n));
  return text;
}

// Reflected light by band of what the points receive of it (W/m^2, as the reference's
// own estimate for bands tells, `referencePath`.bands): the bright posts of a snowy bowl
// judged on their own, not drowned in the scene's mean. null without that estimate (an
// older reference).
std::string reflectedBandsJson(const std::string& referencePath, const std::vector<double>& value,
  const std::vector<double>& reference, const std::vector<double>& referenceError, const std::vector<bool>& include)
{
  const std::size_t n = value.size();
  std::vector<double> forBands(n);
  std::ifstream bandFile(referencePath + ".bands", std::ios::binary);
  if (!bandFile.read(reinterpret_cast<char*>(forBands.data()), static_cast<std::streamsize>(n * sizeof(double))))
    return "null";
  const double bandEdges[] = { 0.0, 1.0, 10.0, 50.0, std::numeric_limits<double>::infinity() };
  std::string text = "[";
  for (int band = 0; band + 1 < static_cast<int>(std::size(bandEdges)); ++band)
  {
    std::vector<bool> inBand(n);
    std::size_t posts = 0;
    for (std::size_t k = 0; k < n; ++k)
      posts += inBand[k] = include[k] && forBands[k] >= bandEdges[band] && forBands[k] < bandEdges[band + 1];
    text += (band ? ", " : "") + std::string("{\"from\": ") + std::to_string(bandEdges[band]) +
      ", \"posts\": " + std::to_string(posts) + ", \"error\": " + errorJson(value, reference, referenceError, inBand) +
      "}";
  }
  return text + "]";
}

int solve(const terralux_bench::AccuracyScene& input, const std::string& referencePath, const std::string& method,
  double tolerance, double targetError)
{
  std::ifstream file(referencePath, std::ios::binary);
  std::uint64_t n = 0;
  file.read(reinterpret_cast<char*>(&n), sizeof n);
  std::vector<ReferencePoint> reference(n);
  file.read(reinterpret_cast<char*>(reference.data()), static_cast<std::streamsize>(n * sizeof(ReferencePoint)));
  if (!file)
  {
    std::cerr << "no reference at " << referencePath << ": run the reference step first\n";
    return 1;
  }

  vtkNew<vtkHierarchicalRadiosity> radiosity;
  radiosity->SetInputData(input.geometry);
  for (const auto& light : input.lights)
    radiosity->AddInputDataObject(1, light);
  radiosity->SetDefaultReflectance(input.reflectance);
  if (input.emissionArray)
    radiosity->SetEmissionArrayName(input.emissionArray);
  radiosity->SetErrorTolerance(tolerance);
  if (targetError > 0.0)
    radiosity->SetTargetError(targetError);
  radiosity->SetEvaluateAtPoints(method != "averaged");
  radiosity->SetSkyFromHorizons(method != "rays");
  // TERRALUX_REPORT_TARGET_FLOOR, _GATHER_RAYS: TargetErrorFloor and MaximumGatherRays
  // other than the defaults.
  if (const char* value = std::getenv("TERRALUX_REPORT_TARGET_FLOOR"))
    radiosity->SetTargetErrorFloor(std::atof(value));
  if (const char* value = std::getenv("TERRALUX_REPORT_GATHER_RAYS"))
    radiosity->SetMaximumGatherRays(std::atoi(value));
  // TERRALUX_REPORT_SEED: another draw of the gather rays (RandomSeed).
  if (const char* value = std::getenv("TERRALUX_REPORT_SEED"))
    radiosity->SetRandomSeed(std::atoi(value));
  // TERRALUX_REPORT_DETAIL_DISTANCE: far gather hits take their leaves' light (m).
  if (const char* value = std::getenv("TERRALUX_REPORT_DETAIL_DISTANCE"))
    radiosity->SetDetailDistance(std::atof(value));
  // TERRALUX_REPORT_FAR_STRIDE: beyond the DetailDistance rays see every Nth post.
  if (const char* value = std::getenv("TERRALUX_REPORT_FAR_STRIDE"))
    radiosity->SetFarTerrainStride(std::atoi(value));
  // TERRALUX_REPORT_WINDOW=1: the far terrain given as an input (every Nth post of the
  // grid, as vtkTerrainSource's output 1 gives it), the way an MPI rank's window sees
  // it: no horizon map, no lattice.
  vtkNew<vtkStructuredGrid> farTerrain;
  auto* fine = vtkStructuredGrid::SafeDownCast(input.geometry);
  if (const char* value = std::getenv("TERRALUX_REPORT_WINDOW"); value && std::string(value) == "1" && fine)
  {
    const int stride = std::max(2, radiosity->GetFarTerrainStride());
    int dims[3];
    fine->GetDimensions(dims);
    const int nx = (dims[0] - 1) / stride + 1, ny = (dims[1] - 1) / stride + 1;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkDataArray* fineGhosts = fine->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName());
    vtkNew<vtkUnsignedCharArray> ghosts;
    ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
    for (int l = 0; l < ny; ++l)
      for (int k = 0; k < nx; ++k)
      {
        const vtkIdType id = k * stride + static_cast<vtkIdType>(l) * stride * dims[0];
        points->InsertNextPoint(fine->GetPoint(id));
        ghosts->InsertNextValue(fineGhosts ? static_cast<unsigned char>(fineGhosts->GetComponent(id, 0)) : 0);
      }
    farTerrain->SetDimensions(nx, ny, 1);
    farTerrain->SetPoints(points);
    if (fineGhosts)
      farTerrain->GetPointData()->AddArray(ghosts);
    vtkNew<vtkIntArray> strideArray;
    strideArray->SetName("FarTerrainStride");
    strideArray->InsertNextValue(stride);
    farTerrain->GetFieldData()->AddArray(strideArray);
    radiosity->SetFarTerrainData(farTerrain);
  }
  radiosity->SetUseTerrainHierarchy(method != "triangles");
  const auto start = std::chrono::steady_clock::now();
  radiosity->Update();
  const double wall = seconds(start);

  std::vector<double> value[4], ref[4], refError[4], estimate, skyView;
  for (vtkDataSet* data : vtkRadiosityScene::DataSetsOf(radiosity->GetOutput()))
  {
    vtkDataArray* error = data->GetPointData()->GetArray("IrradianceError");
    vtkDataArray* view = data->GetPointData()->GetArray("SkyViewFactor");
    for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
    {
      estimate.push_back(error ? error->GetComponent(p, 0) : std::nan(""));
      skyView.push_back(view ? view->GetComponent(p, 0) : std::nan(""));
    }
    const char* names[4] = { "SunIrradiance", "SkyIrradiance", "ReflectedIrradiance", "Irradiance" };
    for (int c = 0; c < 4; ++c)
    {
      vtkDataArray* array = data->GetPointData()->GetArray(names[c]);
      for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
        value[c].push_back(array ? array->GetComponent(p, 0) : 0.0);
    }
  }
  if (value[0].size() != n)
  {
    std::cerr << "the output has " << value[0].size() << " points, the reference " << n << "\n";
    return 1;
  }
  std::vector<bool> used(n), agree(n);
  std::size_t facing = 0, disagree = 0;
  for (std::size_t k = 0; k < n; ++k)
  {
    const ReferencePoint& r = reference[k];
    used[k] = r.used != 0.0 && std::isfinite(value[3][k]);
    const bool shadowAgrees = (value[0][k] > 0.0) == (r.sun > 0.0);
    agree[k] = used[k] && shadowAgrees;
    if (used[k] && r.sunFacing != 0.0)
    {
      ++facing;
      disagree += !shadowAgrees;
    }
    const double refs[4] = { r.sun, r.sky, r.reflected, r.global };
    const double errors[4] = { 0.0, r.skyError, r.reflectedError, r.globalError };
    for (int c = 0; c < 4; ++c)
    {
      ref[c].push_back(refs[c]);
      refError[c].push_back(errors[c]);
    }
  }

  const std::string reflectedBands = reflectedBandsJson(referencePath, value[2], ref[2], refError[2], used);

  // TERRALUX_REPORT_POINTS=FILE: every point's values beside the reference's, as CSV.
  if (const char* pointsFile = std::getenv("TERRALUX_REPORT_POINTS"))
  {
    ScenePoints where;
    loadScene(input, where);
    std::ofstream csv(pointsFile);
    csv << "x,y,z,nx,ny,nz,sun,sky,reflected,global,ref_sun,ref_sky,ref_reflected,ref_global,estimate,ref_error,"
           "used,sun_facing,sky_view\n";
    for (std::size_t k = 0; k < n; ++k)
      csv << where.points[k].x << "," << where.points[k].y << "," << where.points[k].z << "," << where.normals[k].x
          << "," << where.normals[k].y << "," << where.normals[k].z << "," << value[0][k] << "," << value[1][k] << ","
          << value[2][k] << "," << value[3][k] << "," << ref[0][k] << "," << ref[1][k] << "," << ref[2][k] << ","
          << ref[3][k] << "," << estimate[k] << "," << refError[3][k] << "," << (reference[k].used != 0.0) << ","
          << (reference[k].sunFacing != 0.0) << "," << skyView[k] << "\n";
  }
  // The floor: one Embree occlusion ray per point toward the sun.
  ScenePoints s;
  loadScene(input, s);
  double floorSeconds = 0.0;
  if (!terralux_reference::referenceSuns(s.scene.Suns).empty())
  {
    const terralux_reference::ReferenceScene rays(s.scene.Scene);
    const Vec3 toward = terralux_reference::referenceSuns(s.scene.Suns).front().direction;
    std::atomic<int> lit{ 0 };
    const auto floorStart = std::chrono::steady_clock::now();
    tbb::parallel_for(std::size_t(0), s.points.size(), [&](std::size_t k) {
      lit += !rays.occluded(s.points[k] + rays.offsetAt(s.points[k]) * s.normals[k], toward, 0.0, 1e30);
    });
    floorSeconds = seconds(floorStart);
  }
  vtkFieldData* fieldData = radiosity->GetOutput()->GetFieldData();
  auto field = [&](const char* name) {
    vtkDataArray* array = fieldData->GetArray(name);
    return array ? array->GetComponent(0, 0) : 0.0;
  };
  std::printf("{\"scene\": \"%s\", \"method\": \"%s\", \"tolerance\": %g, \"target_error\": %g, \"random_seed\": %d, \"seconds\": %.4f, \"peak_mib\": %.1f, "
              "\"elements\": %.0f, \"links\": %.0f, \"rays\": %.0f, \"iterations\": %.0f, \"horizon_azimuths\": %.0f, \"floor_seconds\": %.5f, "
              "\"phase_seconds\": {\"visibility\": %.4f, \"horizons\": %.4f, \"refine\": %.4f, \"gather\": %.4f, "
              "\"push_pull\": %.4f, \"points\": %.4f}, \"phase_rays\": {\"refine\": %.0f, \"gather_push_pull\": %.0f, \"points\": %.0f}, "
              "\"shadow_disagreement\": %.6f, \"sun\": %s, \"sky\": %s, \"reflected\": %s, \"global\": %s, "
              "\"estimate\": %s, \"reflected_bands\": %s}\n",
    input.name.c_str(), method.c_str(), tolerance, radiosity->GetTargetError(), radiosity->GetRandomSeed(), wall, peakMiB(), field("Elements"), field("Links"), field("Rays"),
    field("Iterations"), field("HorizonAzimuths"), floorSeconds, field("SecondsVisibilityBuild"), field("SecondsHorizons"), field("SecondsRefine"),
    field("SecondsGather"), field("SecondsPushPull"), field("SecondsPoints"), field("RaysRefine"),
    field("RaysPushPull"), field("RaysPoints"), facing ? static_cast<double>(disagree) / facing : 0.0,
    errorJson(value[0], ref[0], refError[0], used).c_str(), errorJson(value[1], ref[1], refError[1], used).c_str(),
    errorJson(value[2], ref[2], refError[2], used).c_str(), errorJson(value[3], ref[3], refError[3], agree).c_str(),
    estimateJson(estimate, value[3], ref[3], refError[3], used).c_str(), reflectedBands.c_str());
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::cerr << "usage: accuracy_report SCENE OUTDIR reference [SAMPLES]\n"
                 "       accuracy_report SCENE OUTDIR describe\n"
                 "       accuracy_report SCENE OUTDIR solve points|rays|averaged|triangles TOLERANCE [TARGET_ERROR]\n";
    return 2;
  }
  try
  {
    const char* dataDir = std::getenv("TERRALUX_DATA_DIR");
    const auto scene = terralux_bench::makeAccuracyScene(argv[1], dataDir ? dataDir : "Testing/Data/External");
    const std::string referencePath = std::string(argv[2]) + "/" + argv[1] + ".reference";
    if (std::string(argv[3]) == "describe")
      return describe(scene);
    if (std::string(argv[3]) == "reference")
      return computeReference(scene, referencePath, argc > 4 ? std::atoi(argv[4]) : 1024);
    if (std::string(argv[3]) == "solve" && argc > 5)
      return solve(scene, referencePath, argv[4], std::atof(argv[5]), argc > 6 ? std::atof(argv[6]) : 0.0);
  }
  catch (const std::exception& error)
  {
    std::cerr << "accuracy_report: " << error.what() << "\n";
    return 1;
  }
  std::cerr << "accuracy_report: unknown command\n";
  return 2;
}
