// Kernel unit tests: the quad split's counts and the Catmull-Clark masks, checked against the
// rules as published (Catmull & Clark 1978: v' = (Q + 2R + (n-3)S)/n with Q the average of
// the new face points, R the average of the edge midpoints, S the old point), computed here
// independently from positions rather than from the stencil code.
#include "SubDQuadSplit.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

#include <array>

using subd::Index;

namespace
{
using Vec3 = std::array<double, 3>;

Vec3 At(const std::vector<double>& p, Index i)
{
  return { p[3 * i], p[3 * i + 1], p[3 * i + 2] };
}

double Distance(const Vec3& a, const Vec3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

Vec3 Centroid(const std::vector<double>& p, subd::IndexSpan corners)
{
  Vec3 c{ 0, 0, 0 };
  for (Index v : corners)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[3 * v + k] / corners.size();
    }
  }
  return c;
}

struct Refined
{
  subd::Level Parent;
  std::vector<double> Child;
  subd::QuadSplitNumbering Number;
};

Refined RefineOnce(const subdtest::TestMesh& mesh, subd::BoundaryRule rule)
{
  subd::Level base = subdtest::BaseLevel(mesh, rule);
  subd::CatmullClarkScheme scheme;
  subd::StencilTable table = scheme.BuildStencils(base);
  std::vector<double> child = subdtest::ApplyToPoints(table, mesh.Points);
  const subd::QuadSplitNumbering number{ base.Topology.GetNumFaces(), base.Topology.GetNumEdges() };
  return { std::move(base), std::move(child), number };
}
}

TEST(QuadSplit, CountsAndEulerCharacteristic)
{
  subd::CatmullClarkScheme scheme;
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
  {
    subd::Level level = subdtest::BaseLevel(mesh);
    for (int l = 1; l <= 3; ++l)
    {
      const subd::MeshTopology& p = level.Topology;
      const Index V = p.GetNumVertices(), E = p.GetNumEdges(), F = p.GetNumFaces();
      const Index H = p.GetNumFaceCorners();
      subd::Level child = scheme.Split(level, subd::ChildTopology::Full);
      const subd::MeshTopology& c = child.Topology;
      EXPECT_EQ(c.GetNumVertices(), V + E + F) << mesh.Name;
      EXPECT_EQ(c.GetNumFaces(), H) << mesh.Name;
      EXPECT_EQ(c.GetNumEdges(), 2 * E + H) << mesh.Name;
      EXPECT_EQ(c.GetNumVertices() - c.GetNumEdges() + c.GetNumFaces(), V - E + F) << mesh.Name;
      EXPECT_EQ(c.GetNumBoundaryEdges(), 2 * p.GetNumBoundaryEdges()) << mesh.Name;
      level = std::move(child);
    }
  }
}

TEST(CatmullClarkRules, RowsSumToOne)
{
  subd::CatmullClarkScheme scheme;
  for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
  {
    for (auto rule : { subd::BoundaryRule::None, subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
    {
      subd::Level level = subdtest::BaseLevel(mesh, rule);
      const subd::StencilTable table = scheme.BuildStencils(level);
      for (Index r = 0; r < table.GetNumRows(); ++r)
      {
        EXPECT_NEAR(table.GetRowSum(r), 1.0, 1e-14) << mesh.Name << " row " << r;
      }
    }
  }
}

TEST(CatmullClarkRules, InteriorVertexMatchesPublishedRuleForValences3To64)
{
  for (int n = 3; n <= 64; ++n)
  {
    const subdtest::TestMesh mesh = subdtest::Star(n).Jitter(0.2);
    const Refined r = RefineOnce(mesh, subd::BoundaryRule::EdgeOnly);
    const subd::MeshTopology& t = r.Parent.Topology;
    const Index apex = 2 * n;
    ASSERT_EQ(t.GetVertexEdges(apex).size(), n);
    // Q: average of the new face points (centroids) around the apex.
    Vec3 Q{ 0, 0, 0 }, R{ 0, 0, 0 };
    for (Index f : t.GetVertexFaces(apex))
    {
      const Vec3 c = Centroid(mesh.Points, t.GetFaceVertices(f));
      for (int k = 0; k < 3; ++k)
        Q[k] += c[k] / n;
    }
    // R: average of the midpoints of the edges at the apex.
    for (Index e : t.GetVertexEdges(apex))
    {
      const Vec3 a = At(mesh.Points, t.GetEdgeVertices(e)[0]), b = At(mesh.Points, t.GetEdgeVertices(e)[1]);
      for (int k = 0; k < 3; ++k)
        R[k] += 0.5 * (a[k] + b[k]) / n;
    }
    const Vec3 S = At(mesh.Points, apex);
    Vec3 expected;
    for (int k = 0; k < 3; ++k)
    {
      expected[k] = (Q[k] + 2 * R[k] + (n - 3) * S[k]) / n;
    }
    EXPECT_LT(Distance(At(r.Child, r.Number.VertexPoint(apex)), expected), 1e-14) << "valence " << n;
  }
}

TEST(CatmullClarkRules, FaceAndInteriorEdgePoints)
{
  const subdtest::TestMesh mesh = subdtest::House(false).Jitter(0.2);
  const Refined r = RefineOnce(mesh, subd::BoundaryRule::EdgeOnly);
  const subd::MeshTopology& t = r.Parent.Topology;
  for (Index f = 0; f < t.GetNumFaces(); ++f)
  {
    EXPECT_LT(Distance(At(r.Child, r.Number.FacePoint(f)), Centroid(mesh.Points, t.GetFaceVertices(f))), 1e-15);
  }
  for (Index e = 0; e < t.GetNumEdges(); ++e)
  {
    const subd::IndexSpan ef = t.GetEdgeFaces(e);
    ASSERT_EQ(ef.size(), 2);
    const Vec3 f0 = Centroid(mesh.Points, t.GetFaceVertices(ef[0]));
    const Vec3 f1 = Centroid(mesh.Points, t.GetFaceVertices(ef[1]));
    const Vec3 a = At(mesh.Points, t.GetEdgeVertices(e)[0]), b = At(mesh.Points, t.GetEdgeVertices(e)[1]);
    Vec3 expected;
    for (int k = 0; k < 3; ++k)
      expected[k] = (a[k] + b[k] + f0[k] + f1[k]) / 4;
    EXPECT_LT(Distance(At(r.Child, r.Number.EdgePoint(e)), expected), 1e-15);
  }
}

TEST(CatmullClarkRules, BoundaryEdgesVerticesAndCorners)
{
  const subdtest::TestMesh mesh = subdtest::Grid(3, 3, false, false).Jitter(0.2);
  for (auto rule : { subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::EdgeAndCorner })
  {
    const Refined r = RefineOnce(mesh, rule);
    const subd::MeshTopology& t = r.Parent.Topology;
    for (Index e = 0; e < t.GetNumEdges(); ++e)
    {
      if (!t.GetEdgeTag(e).Boundary)
        continue;
      const Vec3 a = At(mesh.Points, t.GetEdgeVertices(e)[0]), b = At(mesh.Points, t.GetEdgeVertices(e)[1]);
      const Vec3 mid{ (a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2 };
      EXPECT_LT(Distance(At(r.Child, r.Number.EdgePoint(e)), mid), 1e-15);
    }
    for (Index v = 0; v < t.GetNumVertices(); ++v)
    {
      if (!t.GetVertexTag(v).Boundary)
        continue;
      // The two boundary neighbours.
      std::vector<Index> ends;
      for (Index e : t.GetVertexEdges(v))
        if (t.GetEdgeTag(e).Boundary)
          ends.push_back(t.GetOtherEndpoint(e, v));
      ASSERT_EQ(ends.size(), 2u);
      const bool corner = t.GetVertexFaces(v).size() == 1;
      Vec3 expected = At(mesh.Points, v);
      if (!(corner && rule == subd::BoundaryRule::EdgeAndCorner))
      {
        const Vec3 a = At(mesh.Points, ends[0]), b = At(mesh.Points, ends[1]);
        for (int k = 0; k < 3; ++k)
          expected[k] = 0.75 * expected[k] + 0.125 * (a[k] + b[k]);
      }
      EXPECT_LT(Distance(At(r.Child, r.Number.VertexPoint(v)), expected), 1e-15)
        << subd::ToString(rule) << " vertex " << v << (corner ? " (corner)" : "");
    }
  }
}

TEST(CatmullClarkRules, BoundaryRuleNoneMakesBoundaryFacesHoles)
{
  const subdtest::TestMesh mesh = subdtest::Grid(4, 4, false, false);
  const subd::Level base = subdtest::BaseLevel(mesh, subd::BoundaryRule::None);
  Index holes = 0;
  for (std::uint8_t h : base.FaceIsHole)
    holes += h;
  EXPECT_EQ(holes, 12); // the ring of faces touching the boundary; the inner 2x2 remain
}
