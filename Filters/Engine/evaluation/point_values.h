#pragma once
// The values users read at the points of the input geometry (the per-point outputs):
// irradiance by light category, radiosity, sky view factor and hours of sun, taken at
// each terrain post or polygon vertex from the solved hierarchy. The VTK adapter only
// copies them into arrays.

#include "hierarchy/radiosity_types.h"

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace terralux
{
class PointEvaluator;
class PolygonElement;
struct PointIrradiance;
class TerrainPatch;

struct PointValues
{
  std::array<Spectrum, lightCategories> irradiance{};
  Spectrum radiosity{};
  double skyViewFactor = 0.0;
  double sunlitHours = 0.0;
  /// Estimated error of the global irradiance (largest band, W/m^2), at points only.
  double irradianceError = 0.0;

  /// A leaf's own values (uniform over it, as the hierarchy holds them).
  static PointValues ofLeaf(const PolygonElement& leaf);
  /// What a point of `leaf` receives (PointEvaluator::irradianceAt), with the
  /// radiosity the leaf's material makes of it.
  static PointValues atPoint(const PointIrradiance& received, const PolygonElement& leaf);
  /// sun + sky + reflected
  Spectrum globalIrradiance() const;
  void accumulate(const PointValues& v, double weight);

  /// Laid out flat, for meshes that interpolate values between vertices: irradiance by
  /// category, then radiosity (maxBands each), then the sky view factor.
  static constexpr int flatComponents = (lightCategories + 1) * maxBands + 1;
  void flatten(double* out) const;
  static PointValues unflatten(const double* flat);
};

/// Leaf values flattened one leaf after another (the leaf meshes' vertexValues input).
template <typename Leaf>
std::vector<double> flatLeafValues(const std::vector<const Leaf*>& leaves)
{
  std::vector<double> flat(leaves.size() * PointValues::flatComponents);
  for (std::size_t k = 0; k < leaves.size(); ++k)
    PointValues::ofLeaf(*leaves[k]).flatten(flat.data() + k * PointValues::flatComponents);
  return flat;
}

/// How the points are evaluated.
struct PointEvaluation
{
  /// On: every point evaluated at itself (exact form factors and visibility from the
  /// point). Off: sky and reflected light interpolated from the leaves around it (fast,
  /// smeared over elements; direct sun still one ray from the point).
  bool atPoints = true;
  bool hornNormals = false; ///< terrain posts take Horn's 3 x 3 normal, else the area-weighted one
};

/// The posts [i0, i1] x [j0, j1] of a terrain (clipped to its grid): `sink(i + j nx,
/// values)` for every used post a leaf covers, called in parallel (distinct posts).
void terrainPostValues(const PointEvaluator& evaluator, const TerrainPatch& root, const int posts[4],
  const PointEvaluation& how, const std::function<void(std::size_t, const PointValues&)>& sink);

/// The vertices [firstPoint, firstPoint + count) of the scene's polygons from input
/// `owner`. A vertex takes one value per orientation of the polygons around it (a
/// crease, a box's edge, has two sides, each evaluated on its own side), averaged by
/// area; `oneNormal` (a terrain grid given as polygons) gives every vertex one side.
/// `reached[k]` is false for a vertex no polygon has (its values are zeros).
std::vector<PointValues> polygonPointValues(const PointEvaluator& evaluator, const RadiosityScene& scene,
  int owner, std::size_t firstPoint, std::size_t count, bool oneNormal, const PointEvaluation& how,
  std::vector<bool>& reached);
} // namespace terralux
