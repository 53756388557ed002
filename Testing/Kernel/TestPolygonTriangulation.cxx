// Ear-clipping triangulation: concave polygons give triangles of the polygon's orientation
// whose areas add up to the polygon's.
#include "SubDPolygonTriangulation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
// Signed area in the xy plane of triangle (a, b, c) of the corner list.
double SignedArea(const std::vector<double>& xyz, subd::Index a, subd::Index b, subd::Index c)
{
  return 0.5 * ((xyz[3 * b] - xyz[3 * a]) * (xyz[3 * c + 1] - xyz[3 * a + 1]) -
           (xyz[3 * b + 1] - xyz[3 * a + 1]) * (xyz[3 * c] - xyz[3 * a]));
}

double PolygonArea(const std::vector<double>& xyz)
{
  const size_t n = xyz.size() / 3;
  double area = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const size_t j = (i + 1) % n;
    area += xyz[3 * i] * xyz[3 * j + 1] - xyz[3 * j] * xyz[3 * i + 1];
  }
  return 0.5 * area;
}

void ExpectValidTriangulation(const std::vector<double>& xyz, bool flip)
{
  const subd::Index n = static_cast<subd::Index>(xyz.size() / 3);
  std::vector<subd::Index> triangles;
  EXPECT_TRUE(subd::TriangulatePolygon(xyz.data(), n, triangles));
  ASSERT_EQ(triangles.size(), 3u * (n - 2));
  double sum = 0;
  for (size_t t = 0; t < triangles.size(); t += 3)
  {
    const double a = SignedArea(xyz, triangles[t], triangles[t + 1], triangles[t + 2]);
    EXPECT_GT(flip ? -a : a, 0.0) << "triangle " << t / 3 << " is flipped or flat";
    sum += a;
  }
  EXPECT_NEAR(sum, PolygonArea(xyz), 1e-12);
}
}

TEST(PolygonTriangulation, ConcaveLShape)
{
  // Counter-clockwise L: a fan from corner 0 would produce a flipped triangle.
  const std::vector<double> l{ 0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0 };
  ExpectValidTriangulation(l, false);
  // Start the list at the reflex corner, and also the clockwise (downward-facing) version.
  const std::vector<double> rotated{ 1, 1, 0, 1, 2, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 2, 1, 0 };
  ExpectValidTriangulation(rotated, false);
  std::vector<double> clockwise;
  for (int i = 5; i >= 0; --i)
    clockwise.insert(clockwise.end(), { l[3 * i], l[3 * i + 1], l[3 * i + 2] });
  ExpectValidTriangulation(clockwise, true);
}

TEST(PolygonTriangulation, CombShapedPolygon)
{
  // A comb with 5 teeth: many reflex corners.
  std::vector<double> comb{ 0, 0, 0, 10, 0, 0 };
  for (int t = 4; t >= 0; --t)
  {
    const double x = 2.0 * t;
    comb.insert(comb.end(), { x + 2, 3, 0, x + 1.5, 3, 0, x + 1.5, 1, 0, x + 0.5, 1, 0, x + 0.5, 3, 0 });
  }
  comb.insert(comb.end(), { 0, 3, 0 });
  ExpectValidTriangulation(comb, false);
}

TEST(PolygonTriangulation, TiltedPlaneAndHugePolygonFallsBackToFan)
{
  // A concave pentagon in a tilted plane (projection must pick the right axes).
  std::vector<double> tilted;
  const double flat[5][2] = { { 0, 0 }, { 4, 0 }, { 4, 4 }, { 2, 1 }, { 0, 4 } };
  for (auto& p : flat)
    tilted.insert(tilted.end(), { p[0], 0.3 * p[0] + p[1], 0.8 * p[1] });
  std::vector<subd::Index> triangles;
  EXPECT_TRUE(subd::TriangulatePolygon(tilted.data(), 5, triangles));
  EXPECT_EQ(triangles.size(), 9u);

  const subd::Index n = subd::EarClippingLimit + 1;
  std::vector<double> circle;
  for (subd::Index i = 0; i < n; ++i)
    circle.insert(circle.end(), { std::cos(6.283185307179586 * i / n), std::sin(6.283185307179586 * i / n), 0.0 });
  triangles.clear();
  EXPECT_FALSE(subd::TriangulatePolygon(circle.data(), n, triangles));
  EXPECT_EQ(triangles.size(), 3u * (n - 2));
}
