// Kernel unit tests: the triangle split's counts and Loop's masks against the published
// rules (Loop 1987), computed here from positions.
#include "SubDLoopRules.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTriangleSplit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using subd::Index;

TEST(LoopRules, BetaPublishedValues)
{
  EXPECT_NEAR(subd::LoopBeta(3), 3.0 / 16.0, 1e-15);
  EXPECT_NEAR(subd::LoopBeta(6), 1.0 / 16.0, 1e-15);
  // For large valences n beta tends to 5/8 - (5/8)^2 = 15/64.
  EXPECT_NEAR(subd::LoopBeta(1000) * 1000, 15.0 / 64.0, 1e-4);
}

TEST(TriangleSplit, CountsAndEulerCharacteristic)
{
  subd::LoopScheme scheme;
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    subd::Level level = subdtest::BaseLevel(mesh);
    for (int l = 1; l <= 3; ++l)
    {
      const subd::MeshTopology& p = level.Topology;
      const Index V = p.GetNumVertices(), E = p.GetNumEdges(), F = p.GetNumFaces();
      subd::Level child = scheme.Split(level, subd::ChildTopology::Full);
      const subd::MeshTopology& c = child.Topology;
      EXPECT_EQ(c.GetNumVertices(), V + E) << mesh.Name;
      EXPECT_EQ(c.GetNumFaces(), 4 * F) << mesh.Name;
      EXPECT_EQ(c.GetNumEdges(), 2 * E + 3 * F) << mesh.Name;
      EXPECT_EQ(c.GetNumVertices() - c.GetNumEdges() + c.GetNumFaces(), V - E + F) << mesh.Name;
      level = std::move(child);
    }
  }
}

TEST(LoopRules, MasksMatchPublishedRules)
{
  for (int n = 3; n <= 64; ++n)
  {
    const subdtest::TestMesh mesh = subdtest::Bipyramid(n).Jitter(0.2);
    const subd::Level base = subdtest::BaseLevel(mesh);
    const subd::StencilTable table = subd::BuildLoopStencils(base);
    const std::vector<double> child = subdtest::ApplyToPoints(table, mesh.Points);
    const subd::MeshTopology& t = base.Topology;
    const subd::TriangleSplitNumbering number{ t.GetNumEdges() };
    auto P = [&](Index v, int k) { return mesh.Points[3 * v + k]; };

    // Apex (valence n): (1 - n b) v + b sum of neighbours, b = (5/8 - (3/8 + cos(2pi/n)/4)^2)/n.
    const Index apex = n;
    const double c = 3.0 / 8.0 + 0.25 * std::cos(2 * 3.14159265358979323846 / n);
    const double b = (5.0 / 8.0 - c * c) / n;
    for (int k = 0; k < 3; ++k)
    {
      double ring = 0;
      for (int i = 0; i < n; ++i)
        ring += P(i, k);
      EXPECT_NEAR(child[3 * number.VertexPoint(apex) + k], (1 - n * b) * P(apex, k) + b * ring, 1e-14);
    }
    // Every edge: 3/8 of its ends + 1/8 of the two opposite vertices (found here by search).
    for (Index e = 0; e < t.GetNumEdges(); ++e)
    {
      const Index a = t.GetEdgeVertices(e)[0], z = t.GetEdgeVertices(e)[1];
      std::vector<Index> opposite;
      for (Index f = 0; f < t.GetNumFaces(); ++f)
      {
        const subd::IndexSpan fv = t.GetFaceVertices(f);
        if (std::count(fv.begin(), fv.end(), a) && std::count(fv.begin(), fv.end(), z))
          for (Index v : fv)
            if (v != a && v != z)
              opposite.push_back(v);
      }
      ASSERT_EQ(opposite.size(), 2u);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(child[3 * number.EdgePoint(e) + k],
          0.375 * (P(a, k) + P(z, k)) + 0.125 * (P(opposite[0], k) + P(opposite[1], k)), 1e-15);
    }
  }
}

TEST(LoopRules, RowsSumToOneAndAffineInvariance)
{
  subd::LoopScheme scheme;
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    for (auto rule : { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
    {
      const subd::Level level = subdtest::BaseLevel(mesh, rule);
      const subd::StencilTable table = scheme.BuildStencils(level);
      for (Index r = 0; r < table.GetNumRows(); ++r)
        EXPECT_NEAR(table.GetRowSum(r), 1.0, 1e-14) << mesh.Name << " row " << r;
      // Translating the input translates the output.
      std::vector<double> moved = mesh.Points;
      for (size_t i = 0; i < moved.size(); ++i)
        moved[i] += (i % 3 == 0) ? 2.5 : -1.0;
      std::vector<double> a(static_cast<size_t>(table.GetNumRows()) * 3), b(a.size());
      table.Apply(mesh.Points.data(), a.data(), 3);
      table.Apply(moved.data(), b.data(), 3);
      for (size_t i = 0; i < a.size(); ++i)
        EXPECT_NEAR(b[i] - a[i], (i % 3 == 0) ? 2.5 : -1.0, 1e-13);
    }
  }
}
