// Kernel unit tests: the quad split's counts and the Catmull-Clark masks, checked against the
// rules as published (Catmull & Clark 1978: v' = (Q + 2R + (n-3)S)/n with Q the average of
// the new face points, R the average of the edge midpoints, S the old point), computed here
// independently from positions rather than from the stencil code.
#include "SubDCatmullClarkGrandchildRows.h"
#include "SubDCatmullClarkRules.h"
#include "SubDQuadSplit.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

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

// The finest level's rows written from its grandparent (the level between is not kept) are
// the rows the level between writes, entry for entry and bit for bit, in the same blocks;
// applied in small chunks on threads they give the stored table's values; and the faces two
// quad splits down equal those of splitting twice. Over meshes with n-gons, boundaries,
// non-manifold edges and pinched fans, semi-sharp and sharp creases, a sharp vertex, holes,
// under both crease methods, from the base level and from one level down.
TEST(CatmullClarkRules, GrandchildRowsEqualTheParentsRows)
{
  subd::CatmullClarkScheme scheme;
  Index storedRows = 0, writtenRows = 0;
  for (subd::CreaseMethod method : { subd::CreaseMethod::Uniform, subd::CreaseMethod::Chaikin })
  {
    for (subd::BoundaryRule rule : { subd::BoundaryRule::EdgeOnly, subd::BoundaryRule::None })
    {
      for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
      {
        const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
        const subd::BaseTags tags = subdtest::MixedSharpnessTags(topology, method);
        auto grandparent = std::make_shared<subd::Level>(subd::MakeBaseLevel(topology, tags, rule));
        for (int depth = 0; depth < 2; ++depth)
        {
          const std::string what = mesh.Name + " depth " + std::to_string(depth);
          const subd::Level parent = subd::SplitQuads(*grandparent, subd::ChildTopology::Full);
          const subd::CatmullClarkGrandchildRows rows(grandparent, parent, subdtest::ThreeThreadFor);
          const subd::StencilTable expected = subd::BuildCatmullClarkStencils(parent);
          const subd::StencilTable written = rows.ToStencilTable();
          ASSERT_EQ(written.GetNumRows(), expected.GetNumRows()) << what;
          ASSERT_EQ(written.GetNumBlocks(), expected.GetNumBlocks()) << what;
          for (Index b = 0; b < expected.GetNumBlocks(); ++b)
            EXPECT_EQ(written.GetBlockEnd(b), expected.GetBlockEnd(b)) << what;
          for (Index row = 0; row < expected.GetNumRows(); ++row)
          {
            const subd::IndexSpan a = written.GetSources(row), b = expected.GetSources(row);
            ASSERT_EQ(std::vector<Index>(a.begin(), a.end()), std::vector<Index>(b.begin(), b.end())) << what << " row " << row;
            for (Index k = 0; k < a.size(); ++k)
              ASSERT_EQ(written.GetWeights(row)[k], expected.GetWeights(row)[k]) << what << " row " << row;
          }
          storedRows += rows.GetNumStoredRows();
          writtenRows += rows.GetNumRows() - rows.GetNumStoredRows();

          std::vector<float> parents(static_cast<size_t>(rows.GetNumParents()) * 5);
          for (size_t i = 0; i < parents.size(); ++i)
            parents[i] = static_cast<float>(std::cos(0.3 * i));
          std::vector<float> fromTable(static_cast<size_t>(rows.GetNumRows()) * 5), chunked(fromTable.size());
          expected.Apply(parents.data(), fromTable.data(), 5);
          const std::vector<Index> ends = rows.GetBlockEnds();
          for (size_t b = 0; b < ends.size(); ++b)
            subdtest::ThreeThreadFor(b == 0 ? 0 : ends[b - 1], ends[b], [&](Index begin, Index end) {
              rows.ApplyRows(parents.data(), chunked.data(), 5, begin, end);
            });
          EXPECT_EQ(chunked, fromTable) << what;

          const subd::Level twice = subd::SplitQuadsTwice(*grandparent, rows.GetParentEdgeNumbering(), subdtest::ThreeThreadFor);
          const subd::Level stepwise = subd::SplitQuads(parent, subd::ChildTopology::FacesOnly);
          EXPECT_EQ(twice.Topology.GetNumVertices(), stepwise.Topology.GetNumVertices()) << what;
          EXPECT_EQ(twice.Topology.GetFaceOffsetArray(), stepwise.Topology.GetFaceOffsetArray()) << what;
          EXPECT_EQ(twice.Topology.GetFaceVertexArray(), stepwise.Topology.GetFaceVertexArray()) << what;
          EXPECT_EQ(twice.FaceIsHole, stepwise.FaceIsHole) << what;
          EXPECT_EQ(twice.FaceOrigin, stepwise.FaceOrigin) << what;
          EXPECT_EQ(twice.Depth, stepwise.Depth) << what;
          grandparent = std::make_shared<subd::Level>(parent);
        }
      }
    }
  }
  // Both kinds of rows were compared: written from the grandparent, and stored.
  EXPECT_GT(storedRows, 0);
  EXPECT_GT(writtenRows, 10 * storedRows);
}
