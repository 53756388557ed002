// Kernel unit tests: Doo-Sabin weights, the dual split's counts and orientation, and on a
// regular grid the refined net is the knot-inserted net of the biquadratic B-spline.
#include "SubDBSplineNets.h"
#include "SubDDooSabinRules.h"
#include "SubDDualSplit.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <array>

using subd::Index;

TEST(DooSabinRules, PublishedWeights)
{
  // Quads: 9/16 own corner, 3/16 neighbours, 1/16 opposite.
  EXPECT_DOUBLE_EQ(subd::DooSabinWeight(4, 0), 9.0 / 16.0);
  EXPECT_NEAR(subd::DooSabinWeight(4, 1), 3.0 / 16.0, 1e-16);
  EXPECT_NEAR(subd::DooSabinWeight(4, 2), 1.0 / 16.0, 1e-16);
  EXPECT_NEAR(subd::DooSabinWeight(4, 3), 3.0 / 16.0, 1e-16);
  for (Index n = 3; n <= 64; ++n)
  {
    double sum = 0;
    for (Index d = 0; d < n; ++d)
    {
      sum += subd::DooSabinWeight(n, d);
      EXPECT_NEAR(subd::DooSabinWeight(n, d), subd::DooSabinWeight(n, n - d), 1e-15) << "symmetric";
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << "n = " << n;
  }
}

TEST(DualSplit, CountsOrientationAndEulerOnClosedMeshes)
{
  subd::DooSabinScheme scheme;
  for (const subdtest::TestMesh& mesh : { subdtest::Cube(), subdtest::Grid(6, 5, true, true),
         subdtest::House(false), subdtest::Star(3), subdtest::Star(7) })
  {
    subd::Level level = subd::MakeBaseLevel(
      subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices), {},
      subd::BoundaryRule::EdgeOnly);
    for (int l = 1; l <= 3; ++l)
    {
      const subd::MeshTopology& p = level.Topology;
      const Index V = p.GetNumVertices(), E = p.GetNumEdges(), F = p.GetNumFaces();
      const Index H = p.GetNumFaceCorners();
      subd::Level child = scheme.Split(level, subd::ChildTopology::Full);
      const subd::MeshTopology& c = child.Topology;
      EXPECT_EQ(c.GetNumVertices(), H) << mesh.Name;
      EXPECT_EQ(c.GetNumFaces(), F + E + V) << mesh.Name;
      EXPECT_EQ(c.GetNumVertices() - c.GetNumEdges() + c.GetNumFaces(), V - E + F) << mesh.Name;
      // Closed and consistently oriented: every edge has two faces running opposite ways.
      EXPECT_EQ(c.GetNumBoundaryEdges(), 0) << mesh.Name;
      EXPECT_EQ(c.GetNumNonManifoldEdges(), 0) << mesh.Name;
      EXPECT_EQ(c.GetNumNonManifoldVertices(), 0) << mesh.Name;
      const subd::MeshCounts predicted =
        scheme.PredictChildCounts({ double(F), double(E), double(V), double(H) });
      EXPECT_EQ(predicted.Vertices, c.GetNumVertices());
      EXPECT_EQ(predicted.Faces, c.GetNumFaces());
      EXPECT_EQ(predicted.Edges, c.GetNumEdges());
      EXPECT_EQ(predicted.Corners, c.GetNumFaceCorners());
      level = std::move(child);
    }
  }
}

TEST(DualSplit, OpenMeshesShrinkFromTheBoundary)
{
  // A 3x3 grid: 9 F-faces, E-faces only for the 12 interior edges, V-faces for the 4
  // interior vertices.
  const subdtest::TestMesh grid = subdtest::Grid(3, 3, false, false);
  const subd::Level base = subd::MakeBaseLevel(
    subd::MeshTopology::Build(grid.NumVertices(), grid.Offsets, grid.Vertices), {}, subd::BoundaryRule::EdgeOnly);
  const subd::Level child = subd::DooSabinScheme().Split(base, subd::ChildTopology::Full);
  EXPECT_EQ(child.Topology.GetNumFaces(), 9 + 12 + 4);
  EXPECT_EQ(child.Topology.GetNumNonManifoldEdges(), 0);
}

TEST(DooSabinProperties, RegularGridReproducesBiquadraticBSpline)
{
  const int n = 10;
  subdtest::TestMesh mesh = subdtest::Grid(n, n, false, false);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.Points[3 * (j * (n + 1) + i) + 2] = std::sin(0.6 * i) * std::cos(0.5 * j) + 0.02 * i * j;
  std::vector<double> param = subdtest::GridParameters(n);
  const std::vector<double> level0Param = param;

  subd::DooSabinScheme scheme;
  subd::Level level = subd::MakeBaseLevel(
    subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices), {}, subd::BoundaryRule::EdgeOnly);
  std::vector<double> points = mesh.Points;
  for (int l = 1; l <= 3; ++l)
  {
    const subd::StencilTable table = scheme.BuildStencils(level);
    std::vector<double> child(static_cast<size_t>(table.GetNumRows()) * 3);
    table.Apply(points.data(), child.data(), 3);
    // The point of a corner sits halfway between its vertex and the face centre (in the
    // parameter domain of a regular grid).
    const subd::MeshTopology& t = level.Topology;
    std::vector<double> childParam(static_cast<size_t>(t.GetNumFaceCorners()) * 2);
    for (Index f = 0; f < t.GetNumFaces(); ++f)
    {
      double centre[2] = { 0, 0 };
      for (Index v : t.GetFaceVertices(f))
        for (int k = 0; k < 2; ++k)
          centre[k] += param[2 * v + k] / t.GetFaceSize(f);
      for (Index j = 0; j < t.GetFaceSize(f); ++j)
        for (int k = 0; k < 2; ++k)
          childParam[2 * (t.GetFaceOffset(f) + j) + k] = 0.5 * (param[2 * t.GetFaceVertices(f)[j] + k] + centre[k]);
    }
    level = scheme.Split(level, subd::ChildTopology::Full);
    points.swap(child);
    param.swap(childParam);
    const double worst = subdtest::MaxSurfaceDifference(
      subdtest::QuadraticBSpline, mesh.Points, level0Param, points, param, l, 3.0, n - 3.0);
    EXPECT_LT(worst, 1e-12) << "level " << l;
  }
}
