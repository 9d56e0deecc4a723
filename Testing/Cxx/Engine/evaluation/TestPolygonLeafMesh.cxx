// PolygonLeafMesh (polygon_leaf_mesh.h): shared corners become one vertex with the
// area-weighted mean of the leaves around it, and a T-vertex on a coarser leaf's edge
// takes the mean of that edge's ends, so the leaf mesh output has no cracks.
#include "hierarchy/polygon_element.h"
#include "evaluation/polygon_leaf_mesh.h"

#include <gtest/gtest.h>

using namespace terralux;

TEST(PolygonLeafMesh, SharedCornersAverageAndTVerticesInterpolate)
{
  // Two unit squares side by side along x: the left one whole, the right one split
  // into four, whose children put a vertex at (1, 0.5) on the left square's edge.
  ElementStore store;
  store.MinimumArea = 0.01;
  const Vec3 left[4] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  const Vec3 right[4] = { { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 } };
  PolygonElement* a = store.make<PolygonElement>(0, &store, left, 4, uniformSpectrum(0.5), Spectrum{}, 0);
  PolygonElement* b = store.make<PolygonElement>(0, &store, right, 4, uniformSpectrum(0.5), Spectrum{}, 1);
  ASSERT_EQ(b->children().size(), 4u);

  const PolygonLeafMesh mesh({ a, nullptr, b });
  ASSERT_EQ(mesh.leaves().size(), 5u);
  // 4 corners of the left square, 7 more of the right one's children (a 3 x 3 grid).
  EXPECT_EQ(mesh.vertexCount(), 4u + 7u);

  // Values: the left square 10, the right square's children 20 + their index.
  std::vector<double> leafValues;
  for (const PolygonElement* leaf : mesh.leaves())
    leafValues.push_back(leaf == a ? 10.0 : 20.0 + static_cast<double>(leafValues.size() - 1));
  const std::vector<double> vertex = mesh.vertexValues(leafValues, 1);
  auto valueAt = [&](const Vec3& p) {
    for (std::size_t k = 0; k < mesh.vertexCount(); ++k)
      if (mesh.position(k) == p)
        return vertex[k];
    ADD_FAILURE() << "no vertex at " << p.x << ", " << p.y;
    return 0.0;
  };
  // A corner only the left square has.
  EXPECT_DOUBLE_EQ(valueAt(Vec3(0, 0, 0)), 10.0);
  // (1, 0): the left square (area 1) and the right square's child there (area 1/4).
  double child = 0.0;
  for (std::size_t k = 0; k < mesh.leaves().size(); ++k)
    for (int c = 0; c < 4; ++c)
      if (mesh.leaves()[k] != a && mesh.position(mesh.corners(k)[c]) == Vec3(1, 0, 0))
        child = leafValues[k];
  EXPECT_NEAR(valueAt(Vec3(1, 0, 0)), (1.0 * 10.0 + 0.25 * child) / 1.25, 1e-12);
  // The T-vertex (1, 0.5) lies on the left square's edge: the mean of the edge's ends.
  EXPECT_NEAR(valueAt(Vec3(1, 0.5, 0)), 0.5 * (valueAt(Vec3(1, 0, 0)) + valueAt(Vec3(1, 1, 0))), 1e-12);
  // The right square's centre is no T-vertex: the mean of its four children.
  EXPECT_NEAR(valueAt(Vec3(1.5, 0.5, 0)), 20.0 + 1.5, 1e-12);
}
