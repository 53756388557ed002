// Kernel unit tests: Doo-Sabin weights, the dual split's counts and orientation, and on a
// regular grid the refined net is the knot-inserted net of the biquadratic B-spline.
#include "SubDBSplineNets.h"
#include "SubDOracleSupport.h"
#include "SubDDooSabinRules.h"
#include "SubDDualSplit.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

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
    subd::Level level = subdtest::BaseLevel(mesh);
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
      level = std::move(child);
    }
  }
}

// The numbering, the faces (written in blocks) and the rows on threads equal the serial
// ones, smooth and with creases and semi-sharp edges (welded corners).
TEST(DualSplit, ThreadsGiveTheSerialPointsFacesAndRows)
{
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
  {
    for (bool creased : { false, true })
    {
      subd::Level level = subdtest::BaseLevel(mesh);
      for (Index e = 0; creased && e < level.Topology.GetNumEdges(); ++e)
      {
        level.EdgeSharpness[e] = e % 5 == 0 ? 1.6f : (e % 7 == 0 ? subd::SharpnessInfinite : 0.0f);
      }
      for (int l = 1; l <= 2; ++l)
      {
        SCOPED_TRACE(mesh.Name + (creased ? " creased" : "") + " level " + std::to_string(l));
        const subd::DualPoints serial = subd::NumberDualPoints(level);
        const subd::DualPoints threaded = subd::NumberDualPoints(level, subdtest::ThreeThreadFor);
        EXPECT_EQ(serial.PointOfCorner, threaded.PointOfCorner);
        EXPECT_EQ(serial.CornerOfPoint, threaded.CornerOfPoint);
        EXPECT_EQ(serial.IsCornerVertex, threaded.IsCornerVertex);
        EXPECT_EQ(serial.PinsEveryCorner, threaded.PinsEveryCorner);
        EXPECT_EQ(serial.TurnCorners, threaded.TurnCorners);
        EXPECT_EQ(serial.PointBeforeTurnCorner, threaded.PointBeforeTurnCorner);
        EXPECT_EQ(serial.Unwelded, threaded.Unwelded);
        EXPECT_EQ(serial.NumPoints, threaded.NumPoints);
        const subd::StencilTable rows = subd::BuildDooSabinStencils(level, serial);
        const subd::StencilTable threadedRows = subd::BuildDooSabinStencils(level, threaded, subdtest::ThreeThreadFor);
        ASSERT_EQ(rows.GetNumRows(), threadedRows.GetNumRows());
        for (Index r = 0; r < rows.GetNumRows(); ++r)
        {
          const subd::IndexSpan s = rows.GetSources(r), t = threadedRows.GetSources(r);
          ASSERT_EQ(s.size(), t.size()) << "row " << r;
          EXPECT_TRUE(std::equal(s.begin(), s.end(), t.begin())) << "row " << r;
          EXPECT_TRUE(std::equal(rows.GetWeights(r), rows.GetWeights(r) + s.size(), threadedRows.GetWeights(r)))
            << "row " << r;
        }
        subd::Level child = subd::SplitDual(level, serial, subd::ChildTopology::Full);
        const subd::Level threadedChild = subd::SplitDual(level, threaded, subd::ChildTopology::Full, subdtest::ThreeThreadFor);
        EXPECT_EQ(child.Topology.GetFaceOffsetArray(), threadedChild.Topology.GetFaceOffsetArray());
        EXPECT_EQ(child.Topology.GetFaceVertexArray(), threadedChild.Topology.GetFaceVertexArray());
        EXPECT_EQ(child.FaceOrigin, threadedChild.FaceOrigin);
        EXPECT_EQ(child.FaceIsHole, threadedChild.FaceIsHole);
        EXPECT_EQ(child.EdgeSharpness, threadedChild.EdgeSharpness);
        level = std::move(child);
      }
    }
  }
}

TEST(DualSplit, OpenGridFaces)
{
  // A 3x3 grid: 9 F-faces, E-faces only for the 12 interior edges, V-faces for the 4
  // interior vertices (boundary vertices have at most two faces).
  const subdtest::TestMesh grid = subdtest::Grid(3, 3, false, false);
  const subd::Level base = subdtest::BaseLevel(grid);
  const subd::Level child = subd::DooSabinScheme().Split(base, subd::ChildTopology::Full);
  EXPECT_EQ(child.Topology.GetNumFaces(), 9 + 12 + 4);
  EXPECT_EQ(child.Topology.GetNumNonManifoldEdges(), 0);
}

TEST(DooSabinProperties, RegularGridReproducesBiquadraticBSpline)
{
  const int n = 10;
  const subdtest::TestMesh mesh = subdtest::WavyGrid(n, 0.6, 0.5, 0.02);
  // The point of a corner sits halfway between its vertex and the face centre (in the
  // parameter domain of a regular grid).
  auto childParameters = [](const subd::MeshTopology& t, const std::vector<double>& param) {
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
    return childParam;
  };
  const std::vector<double> differences = subdtest::GridBSplineDifferences(
    subd::DooSabinScheme(), mesh, n, 3, subdtest::QuadraticBSpline, childParameters);
  for (size_t l = 0; l < differences.size(); ++l)
    EXPECT_LT(differences[l], 1e-12) << "level " << l + 1;
}

namespace
{
// Clamped Chaikin refinement of an open polygon (end points kept): the uniform quadratic
// B-spline with end interpolation, refined once. Written independently of the kernel.
std::vector<std::array<double, 3>> ClampedChaikin(const std::vector<std::array<double, 3>>& p)
{
  const size_t n = p.size() - 1; // edges
  auto mix = [](const std::array<double, 3>& a, const std::array<double, 3>& b, double t) {
    return std::array<double, 3>{ (1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2] };
  };
  std::vector<std::array<double, 3>> q;
  // First edge -> its midpoint, middle edges -> their 1/4 and 3/4 points, last edge -> its
  // midpoint; a single edge stays as it is.
  q.assign(1, p[0]);
  for (size_t i = 0; i < n; ++i)
  {
    if (n == 1)
      break;
    if (i == 0)
      q.push_back(mix(p[0], p[1], 0.5));
    else if (i + 1 == n)
      q.push_back(mix(p[i], p[i + 1], 0.5));
    else
    {
      q.push_back(mix(p[i], p[i + 1], 0.25));
      q.push_back(mix(p[i], p[i + 1], 0.75));
    }
  }
  q.push_back(p[n]);
  return q;
}
}

TEST(DooSabinProperties, OpenBoundaryFollowsTheClampedQuadraticBSpline)
{
  // A 4x3 grid with heights: four sides between four corners.
  const int nx = 4, ny = 3;
  subdtest::TestMesh mesh = subdtest::Grid(nx, ny, false, false).Jitter(0.2);
  auto point = [&](int i, int j) {
    const Index v = j * (nx + 1) + i;
    return std::array<double, 3>{ mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] };
  };
  std::vector<std::vector<std::array<double, 3>>> sides(4);
  for (int i = 0; i <= nx; ++i)
  {
    sides[0].push_back(point(i, 0));
    sides[1].push_back(point(i, ny));
  }
  for (int j = 0; j <= ny; ++j)
  {
    sides[2].push_back(point(0, j));
    sides[3].push_back(point(nx, j));
  }
  const int levels = 3;
  for (auto& side : sides)
    for (int l = 0; l < levels; ++l)
      side = ClampedChaikin(side);

  subd::DooSabinScheme scheme;
  subd::Hierarchy h;
  const std::vector<double> out = subdtest::RefineFixture(scheme, mesh, levels, h);
  const subd::MeshTopology finest = subd::MeshTopology::Build(
    h.GetNumFinestPoints(), h.Finest.Topology.GetFaceOffsetArray(), h.Finest.Topology.GetFaceVertexArray());
  EXPECT_EQ(finest.GetNumNonManifoldEdges(), 0) << "consistently oriented";
  EXPECT_EQ(finest.GetNumNonManifoldVertices(), 0);

  // Every refined boundary point is a point of the independently refined sides, and the
  // counts agree (the four corners are shared by two sides each).
  size_t expected = 0;
  for (const auto& side : sides)
    expected += side.size();
  expected -= 4;
  std::vector<double> candidates;
  for (const auto& side : sides)
  {
    const std::vector<double> flat = subdtest::Flatten(side);
    candidates.insert(candidates.end(), flat.begin(), flat.end());
  }
  Index boundaryPoints = 0;
  EXPECT_LT(subdtest::FarthestBoundaryPoint(finest, out, candidates, boundaryPoints), 1e-12);
  EXPECT_EQ(static_cast<size_t>(boundaryPoints), expected);
}

TEST(DualSplit, OpenMeshWithBoundaryFansStaysConsistentlyOriented)
{
  // The open house: boundary vertices with three faces get V-faces closed along the boundary.
  const subdtest::TestMesh mesh = subdtest::House(true);
  subd::DooSabinScheme scheme;
  subd::Level level = subdtest::BaseLevel(mesh);
  for (int l = 1; l <= 3; ++l)
  {
    level = scheme.Split(level, subd::ChildTopology::Full);
    EXPECT_EQ(level.Topology.GetNumNonManifoldEdges(), 0) << "level " << l;
    EXPECT_EQ(level.Topology.GetNumNonManifoldVertices(), 0) << "level " << l;
  }
}
