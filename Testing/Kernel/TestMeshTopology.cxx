// Kernel unit tests: topology construction, tags, and face screening.
#include "SubDCoincidentPoints.h"
#include "SubDDualSplit.h"
#include "SubDFaceBlocks.h"
#include "SubDMeshTopology.h"
#include "SubDMeshValidation.h"
#include "SubDPrimalSplitShape.h"
#include "SubDQuadSplit.h"
#include "SubDSqrt3Rules.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"
#include "SubDTriangleSplit.h"

#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <stdexcept>

using subd::Index;
using subd::MeshTopology;

namespace
{
MeshTopology Build(const subdtest::TestMesh& m)
{
  return MeshTopology::Build(m.NumVertices(), m.Offsets, m.Vertices);
}
}

TEST(MeshTopology, CubeCountsAndRelations)
{
  const MeshTopology t = Build(subdtest::Cube());
  EXPECT_EQ(t.GetNumVertices(), 8);
  EXPECT_EQ(t.GetNumEdges(), 12);
  EXPECT_EQ(t.GetNumFaces(), 6);
  EXPECT_EQ(t.GetNumBoundaryEdges(), 0);
  EXPECT_EQ(t.GetNumNonManifoldEdges(), 0);
  EXPECT_EQ(t.GetNumNonManifoldVertices(), 0);
  for (Index v = 0; v < 8; ++v)
  {
    EXPECT_EQ(t.GetVertexEdges(v).size(), 3);
    EXPECT_EQ(t.GetVertexFaces(v).size(), 3);
  }
  for (Index f = 0; f < 6; ++f)
  {
    const subd::IndexSpan fv = t.GetFaceVertices(f), fe = t.GetFaceEdges(f);
    for (Index j = 0; j < 4; ++j)
    {
      // Edge j of a face joins corners j and j+1.
      const Index* ev = t.GetEdgeVertices(fe[j]);
      const Index a = fv[j], b = fv[(j + 1) % 4];
      EXPECT_TRUE((ev[0] == a && ev[1] == b) || (ev[0] == b && ev[1] == a));
      EXPECT_EQ(t.FindEdge(a, b), fe[j]);
      EXPECT_EQ(t.FindEdge(b, a), fe[j]);
    }
  }
  for (Index e = 0; e < 12; ++e)
  {
    EXPECT_EQ(t.GetEdgeFaces(e).size(), 2);
  }
}

TEST(MeshTopology, OpenGridBoundary)
{
  const MeshTopology t = Build(subdtest::Grid(4, 3, false, false));
  EXPECT_EQ(t.GetNumVertices(), 20);
  EXPECT_EQ(t.GetNumEdges(), 4 * 4 + 5 * 3);
  EXPECT_EQ(t.GetNumBoundaryEdges(), 2 * (4 + 3));
  Index boundaryVertices = 0;
  for (Index v = 0; v < t.GetNumVertices(); ++v)
  {
    boundaryVertices += t.GetVertexTag(v).Boundary;
  }
  EXPECT_EQ(boundaryVertices, 14);
  EXPECT_EQ(t.GetNumNonManifoldVertices(), 0);
}

TEST(MeshTopology, NonManifoldEdgeAndBowTie)
{
  const MeshTopology t = Build(subdtest::NonManifold());
  const Index fin = t.FindEdge(0, 1);
  ASSERT_NE(fin, subd::InvalidIndex);
  EXPECT_EQ(t.GetEdgeFaces(fin).size(), 3);
  EXPECT_TRUE(t.GetEdgeTag(fin).NonManifold);
  EXPECT_EQ(t.GetNumNonManifoldEdges(), 1);
  EXPECT_TRUE(t.GetVertexTag(0).NonManifold);
  EXPECT_TRUE(t.GetVertexTag(1).NonManifold);
  EXPECT_TRUE(t.GetVertexTag(3).NonManifold) << "bow-tie vertex";
  EXPECT_FALSE(t.GetVertexTag(2).NonManifold);
}

TEST(MeshTopology, PinchedClosedFansAreNonManifold)
{
  const MeshTopology t = Build(subdtest::PinchedCubes());
  EXPECT_EQ(t.GetNumNonManifoldEdges(), 0);
  EXPECT_EQ(t.GetNumBoundaryEdges(), 0);
  EXPECT_EQ(t.GetNumNonManifoldVertices(), 1);
  EXPECT_TRUE(t.GetVertexTag(6).NonManifold);
}

// A closed fan (a tetrahedron's corner) and an open one (a triangle touching it there).
TEST(MeshTopology, ClosedAndOpenFanAtOneVertexAreNonManifold)
{
  subdtest::TestMesh mesh;
  mesh.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, -1, 0, -1, -0.5, -1 };
  mesh.Offsets = { 0, 3, 6, 9, 12, 15 };
  mesh.Vertices = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 5 };
  const MeshTopology t = Build(mesh);
  EXPECT_EQ(t.GetNumNonManifoldEdges(), 0);
  EXPECT_TRUE(t.GetVertexTag(0).NonManifold);
  EXPECT_EQ(t.GetNumNonManifoldVertices(), 1);
  EXPECT_TRUE(t.GetVertexTag(4).Boundary);
}

TEST(MeshTopology, InconsistentOrientationIsNonManifold)
{
  // Both triangles run along edge 0->1 in the same direction.
  const MeshTopology t = MeshTopology::Build(4, subd::IndexArray{ 0, 3, 6 }, subd::IndexArray{ 0, 1, 2, 0, 1, 3 });
  EXPECT_TRUE(t.GetEdgeTag(t.FindEdge(0, 1)).NonManifold);
  const MeshTopology ok = MeshTopology::Build(4, subd::IndexArray{ 0, 3, 6 }, subd::IndexArray{ 0, 1, 2, 1, 0, 3 });
  EXPECT_FALSE(ok.GetEdgeTag(ok.FindEdge(0, 1)).NonManifold);
}

TEST(MeshTopology, HighValenceHubAndIsolatedVertex)
{
  const Index n = 1000;
  std::vector<Index> offsets{ 0 }, verts;
  for (Index k = 0; k < n; ++k)
  {
    verts.insert(verts.end(), { 0, 1 + k, 1 + (k + 1) % n });
    offsets.push_back(static_cast<Index>(verts.size()));
  }
  const MeshTopology t = MeshTopology::Build(n + 2, offsets, verts); // vertex n+1 unused
  EXPECT_EQ(t.GetMaxValence(), n);
  EXPECT_EQ(t.GetVertexFaces(0).size(), n);
  EXPECT_EQ(t.GetNumNonManifoldVertices(), 0);
  EXPECT_EQ(t.GetVertexFaces(n + 1).size(), 0);
  EXPECT_EQ(t.GetNumEdges(), 2 * n);
}

// Two closed cones of `sides` triangles sharing their apex 0 (a double cone pinched at its
// tip): every edge is manifold, the apex has two closed fans. Fans of up to 32 faces are
// counted while pairing the half-edges, larger ones by a union-find: both must see it.
TEST(MeshTopology, PinchedConesAreNonManifoldAtAnyValence)
{
  for (const Index sides : { 3, 10, 16, 17, 40 })
  {
    std::vector<Index> offsets{ 0 }, verts;
    for (Index cone = 0; cone < 2; ++cone)
    {
      const Index first = 1 + cone * (sides + 1), tip = first + sides; // rim, then the far tip
      for (Index k = 0; k < sides; ++k)
      {
        const Index a = first + k, b = first + (k + 1) % sides;
        verts.insert(verts.end(), { 0, a, b, b, a, tip });
        offsets.push_back(static_cast<Index>(verts.size()) - 3);
        offsets.push_back(static_cast<Index>(verts.size()));
      }
    }
    const MeshTopology t = MeshTopology::Build(1 + 2 * (sides + 1), offsets, verts);
    EXPECT_EQ(t.GetVertexFaces(0).size(), 2 * sides);
    EXPECT_EQ(t.GetNumNonManifoldEdges(), 0) << sides;
    EXPECT_EQ(t.GetNumBoundaryEdges(), 0) << sides;
    EXPECT_TRUE(t.GetVertexTag(0).NonManifold) << sides << " faces per cone";
    EXPECT_EQ(t.GetNumNonManifoldVertices(), 1) << sides;
  }
}

namespace
{
bool SameSpan(subd::IndexSpan a, subd::IndexSpan b)
{
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}

// The faces, edges, faces of each edge and edge tags of `known` equal those of `searched`.
void ExpectSameFacesAndEdges(const MeshTopology& known, const MeshTopology& searched)
{
  ASSERT_EQ(known.GetNumVertices(), searched.GetNumVertices());
  ASSERT_EQ(known.GetNumEdges(), searched.GetNumEdges());
  ASSERT_EQ(known.GetNumFaces(), searched.GetNumFaces());
  EXPECT_EQ(known.GetFaceOffsetArray(), searched.GetFaceOffsetArray());
  EXPECT_EQ(known.GetFaceVertexArray(), searched.GetFaceVertexArray());
  EXPECT_EQ(known.GetNumBoundaryEdges(), searched.GetNumBoundaryEdges());
  EXPECT_EQ(known.GetNumNonManifoldEdges(), searched.GetNumNonManifoldEdges());
  for (Index f = 0; f < known.GetNumFaces(); ++f)
  {
    EXPECT_TRUE(SameSpan(known.GetFaceEdges(f), searched.GetFaceEdges(f))) << "face " << f;
  }
  for (Index e = 0; e < known.GetNumEdges(); ++e)
  {
    EXPECT_EQ(known.GetEdgeVertices(e)[0], searched.GetEdgeVertices(e)[0]) << "edge " << e;
    EXPECT_EQ(known.GetEdgeVertices(e)[1], searched.GetEdgeVertices(e)[1]) << "edge " << e;
    EXPECT_TRUE(SameSpan(known.GetEdgeFaces(e), searched.GetEdgeFaces(e))) << "edge " << e;
    EXPECT_EQ(known.GetEdgeTag(e).Boundary, searched.GetEdgeTag(e).Boundary) << "edge " << e;
    EXPECT_EQ(known.GetEdgeTag(e).NonManifold, searched.GetEdgeTag(e).NonManifold) << "edge " << e;
  }
}

// Every relation and tag of `known` (a split's child, derived from its parent) equals that
// of `searched` (the same faces through the general builder).
void ExpectSameTopology(const MeshTopology& known, const MeshTopology& searched, const std::string& what)
{
  SCOPED_TRACE(what);
  ExpectSameFacesAndEdges(known, searched);
  EXPECT_EQ(known.GetNumNonManifoldVertices(), searched.GetNumNonManifoldVertices());
  EXPECT_EQ(known.GetMaxValence(), searched.GetMaxValence());
  for (Index v = 0; v < known.GetNumVertices(); ++v)
  {
    EXPECT_TRUE(SameSpan(known.GetVertexFaces(v), searched.GetVertexFaces(v))) << "vertex " << v;
    EXPECT_TRUE(SameSpan(known.GetVertexFaceCorners(v), searched.GetVertexFaceCorners(v))) << "vertex " << v;
    EXPECT_TRUE(SameSpan(known.GetVertexEdges(v), searched.GetVertexEdges(v))) << "vertex " << v;
    EXPECT_EQ(known.GetVertexTag(v).Boundary, searched.GetVertexTag(v).Boundary) << "vertex " << v;
    EXPECT_EQ(known.GetVertexTag(v).NonManifold, searched.GetVertexTag(v).NonManifold) << "vertex " << v;
  }
}

// Splits `mesh` twice with `split`, serially and on threads, and checks each child's
// topology, derived from its parent, against the general builder on the same faces.
template <typename Split>
void ExpectSplitKnowsItsChild(const subdtest::TestMesh& mesh, Split split, const std::string& what)
{
  for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
  {
    subd::Level level = subdtest::BaseLevel(mesh);
    for (int l = 1; l <= 2; ++l)
    {
      subd::Level child = split(level, subd::ChildTopology::Full, parallelFor);
      const MeshTopology& t = child.Topology;
      const MeshTopology searched =
        MeshTopology::Build(t.GetNumVertices(), t.GetFaceOffsetArray(), t.GetFaceVertexArray());
      ExpectSameTopology(t, searched, what + " level " + std::to_string(l));
      level = std::move(child);
    }
  }
}

// Meshes with every kind of vertex the tags distinguish: boundary, non-manifold edges,
// bow-ties, pinched fans, inconsistent orientation, an isolated vertex.
std::vector<subdtest::TestMesh> TagFixtures()
{
  std::vector<subdtest::TestMesh> meshes = subdtest::StandardMeshes();
  subdtest::TestMesh flipped;
  flipped.Points = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 5, 5, 5 };
  flipped.Offsets = { 0, 3, 6 };
  flipped.Vertices = { 0, 1, 2, 0, 1, 3 }; // both run along 0->1; point 4 unused
  meshes.push_back(flipped);
  return meshes;
}
}

TEST(MeshTopology, QuadSplitChildEqualsSearchedTopology)
{
  int i = 0;
  for (const subdtest::TestMesh& mesh : TagFixtures())
  {
    ExpectSplitKnowsItsChild(mesh, subd::SplitQuads, "mesh " + std::to_string(i++));
  }
}

TEST(MeshTopology, TriangleSplitChildEqualsSearchedTopology)
{
  int i = 0;
  std::vector<subdtest::TestMesh> meshes = subdtest::TriangleMeshes();
  meshes.push_back(TagFixtures().back());
  for (const subdtest::TestMesh& mesh : meshes)
  {
    ExpectSplitKnowsItsChild(mesh, subd::SplitTriangles, "mesh " + std::to_string(i++));
  }
}

// The general builder runs every pass on threads (counting sorts by item blocks, half-edges
// paired per vertex): it gives the serial topology, also around a hub whose lists are long.
TEST(MeshTopology, BuildOnThreadsEqualsSerialBuild)
{
  int i = 0;
  std::vector<subdtest::TestMesh> meshes = TagFixtures();
  subdtest::TestMesh hub;
  const Index n = 200;
  hub.Points.assign(3 * (n + 1), 0.0);
  hub.Offsets = { 0 };
  for (Index k = 0; k < n; ++k)
  {
    hub.Vertices.insert(hub.Vertices.end(), { 0, 1 + k, 1 + (k + 1) % n });
    hub.Offsets.push_back(static_cast<Index>(hub.Vertices.size()));
  }
  meshes.push_back(hub);
  for (const subdtest::TestMesh& mesh : meshes)
  {
    const MeshTopology serial = Build(mesh);
    ExpectSameTopology(MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices, subdtest::ThreeThreadFor), serial,
      "mesh " + std::to_string(i++));
  }
}

// The faces around a manifold vertex in fan order: each one's edge entering the vertex is the
// next one's edge leaving it (matched by the vertices across them up to 64 faces, walked
// across edges beyond), a boundary vertex's fan from boundary edge to boundary edge; none
// for a non-manifold vertex.
TEST(MeshTopology, OrderedVertexFacesWalkEachFanAcrossItsEdges)
{
  std::vector<subdtest::TestMesh> meshes = TagFixtures();
  for (Index sides : { 5, 64, 65, 90 })
  {
    for (bool closed : { true, false })
    {
      subdtest::TestMesh fan;
      fan.Points.assign(3 * static_cast<size_t>(sides + 1), 0.0);
      fan.Offsets = { 0 };
      for (Index k = 0; k < (closed ? sides : sides - 1); ++k)
      {
        fan.Vertices.insert(fan.Vertices.end(), { 0, 1 + k, 1 + (k + 1) % sides });
        fan.Offsets.push_back(static_cast<Index>(fan.Vertices.size()));
      }
      meshes.push_back(fan);
    }
  }
  int i = 0;
  for (const subdtest::TestMesh& mesh : meshes)
  {
    SCOPED_TRACE("mesh " + std::to_string(i++));
    const MeshTopology t = Build(mesh);
    std::vector<Index> faces, corners;
    for (Index v = 0; v < t.GetNumVertices(); ++v)
    {
      const bool ordered = t.GetOrderedVertexFaces(v, faces, corners);
      if (t.GetVertexTag(v).NonManifold || t.GetVertexFaces(v).empty())
      {
        EXPECT_FALSE(ordered) << "vertex " << v;
        continue;
      }
      ASSERT_TRUE(ordered) << "vertex " << v;
      const subd::IndexSpan vf = t.GetVertexFaces(v);
      ASSERT_EQ(faces.size(), static_cast<size_t>(vf.size()));
      std::vector<Index> sorted = faces;
      std::sort(sorted.begin(), sorted.end());
      EXPECT_TRUE(std::equal(sorted.begin(), sorted.end(), vf.begin())) << "vertex " << v;
      auto edgeAt = [&](size_t k, bool leaving) {
        const subd::IndexSpan fe = t.GetFaceEdges(faces[k]);
        EXPECT_EQ(t.GetFaceVertices(faces[k])[corners[k]], v);
        return fe[leaving ? corners[k] : (corners[k] == 0 ? fe.size() - 1 : corners[k] - 1)];
      };
      for (size_t k = 0; k + 1 < faces.size(); ++k)
      {
        EXPECT_EQ(edgeAt(k, false), edgeAt(k + 1, true)) << "vertex " << v << ", face " << k;
      }
      const Index first = edgeAt(0, true), last = edgeAt(faces.size() - 1, false);
      if (t.GetVertexTag(v).Boundary)
      {
        EXPECT_TRUE(t.GetEdgeTag(first).Boundary && t.GetEdgeTag(last).Boundary) << "vertex " << v;
      }
      else
      {
        EXPECT_EQ(last, first) << "vertex " << v; // the fan closes
      }
    }
  }
}

// Rows that must follow one order around a vertex whatever the edges' numbers read each
// vertex's ring in increasing order of the vertices across its edges.
TEST(MeshTopology, RingsAreTheVerticesAcrossEachEdgeInOrder)
{
  std::vector<subdtest::TestMesh> meshes = TagFixtures();
  meshes.push_back(subdtest::Cube());
  meshes.push_back(subdtest::Bipyramid(70)); // apices of valence 70: rings sorted past the stack
  for (size_t i = 0; i < meshes.size(); ++i)
  {
    SCOPED_TRACE("mesh " + std::to_string(i));
    const MeshTopology whole = Build(meshes[i]);
    for (Index v = 0; v < whole.GetNumVertices(); ++v)
    {
      std::vector<Index> expected, ring;
      for (Index e : whole.GetVertexEdges(v))
      {
        const Index* ends = whole.GetEdgeVertices(e);
        expected.push_back(ends[0] == v ? ends[1] : ends[0]);
      }
      std::sort(expected.begin(), expected.end());
      whole.ForEachRingVertex(v, [&ring](Index w) { ring.push_back(w); });
      EXPECT_EQ(ring, expected) << "vertex " << v;
    }
  }
}

TEST(MeshValidation, CollapsesDropsAndReports)
{
  // face 0 ok, face 1 has a repeated consecutive corner (kept as a triangle), face 2 collapses
  // to two corners (dropped), face 3 repeats a vertex non-consecutively (dropped).
  const std::vector<long long> offsets{ 0, 3, 7, 10, 15 };
  const std::vector<long long> verts{ 0, 1, 2, 0, 2, 2, 3, 1, 1, 2, 0, 1, 2, 0, 3 };
  subd::FaceScreening s = subd::ScreenFaces(4, 4, offsets.data(), verts.data());
  EXPECT_EQ(s.NumOutOfRange, 0);
  EXPECT_EQ(s.KeptFaces, (subd::IndexArray{ 0, 1 }));
  EXPECT_EQ(s.NumDropped, 2);
  EXPECT_EQ(s.FirstDroppedFace, 2);
  EXPECT_EQ(s.Vertices, (subd::IndexArray{ 0, 1, 2, 0, 2, 3 }));
  EXPECT_EQ(s.NumCollapsedCorners, 2);

  const std::vector<long long> bad{ 0, 1, 7 };
  const std::vector<long long> badOffsets{ 0, 3 };
  subd::FaceScreening r = subd::ScreenFaces(4, 1, badOffsets.data(), bad.data());
  EXPECT_EQ(r.NumOutOfRange, 1);
  EXPECT_EQ(r.FirstOutOfRangeFace, 0);
  EXPECT_EQ(r.FirstOutOfRangeId, 7);
  EXPECT_TRUE(r.KeptFaces.empty());

  // Offsets that go down (a corrupt cell array): the faces whose corners leave the array's
  // range are dropped unread, on threads or not.
  const std::vector<long long> corrupt{ 0, 3, 100, 6, 9 };
  const std::vector<long long> corners{ 0, 1, 2, 1, 2, 3, 2, 3, 0 };
  for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
  {
    const subd::FaceScreening c = subd::ScreenFaces(4, 4, corrupt.data(), corners.data(), parallelFor);
    EXPECT_EQ(c.KeptFaces, (subd::IndexArray{ 0, 3 }));
    EXPECT_EQ(c.NumDropped, 2);
    EXPECT_EQ(c.FirstDroppedFace, 1);
    EXPECT_EQ(c.Vertices, (subd::IndexArray{ 0, 1, 2, 2, 3, 0 }));
  }
}

// A mesh needing no repair is copied as it is (on threads); one bad face among clean ones, or
// a face of more than 16 corners, sends every face through the repairing loop, with the
// same result for the clean ones.
TEST(MeshValidation, CleanFacesKeptAsTheyAreOnThreads)
{
  std::vector<long long> offsets{ 5 }, verts(5, -1); // offsets need not start at 0
  subd::IndexArray expectedVerts, expectedOffsets{ 0 };
  for (int f = 0; f < 300; ++f)
  {
    const int n = 3 + f % 4 + (f == 250 ? 20 : 0); // triangles to hexagons, one 25-gon
    for (int k = 0; k < n; ++k)
    {
      verts.push_back((7 * f + 3 * k) % 400);
      expectedVerts.push_back(static_cast<Index>(verts.back()));
    }
    offsets.push_back(static_cast<long long>(verts.size()));
    expectedOffsets.push_back(static_cast<Index>(expectedVerts.size()));
  }
  subd::IndexArray all(300);
  std::iota(all.begin(), all.end(), 0);
  for (bool bigFace : { false, true })
  {
    std::vector<long long> o = offsets, v = verts;
    subd::IndexArray ev = expectedVerts, eo = expectedOffsets;
    if (!bigFace) // the 25-gon becomes a hexagon
    {
      const long long removed = o[251] - o[250] - 6;
      v.erase(v.begin() + o[250] + 6, v.begin() + o[251]);
      ev.erase(ev.begin() + eo[250] + 6, ev.begin() + eo[251]);
      for (size_t f = 251; f < o.size(); ++f)
      {
        o[f] -= removed;
        eo[f] -= static_cast<Index>(removed);
      }
    }
    const subd::FaceScreening clean = subd::ScreenFaces(400, 300, o.data(), v.data(), subdtest::ThreeThreadFor);
    EXPECT_EQ(clean.Offsets, eo);
    EXPECT_EQ(clean.Vertices, ev);
    EXPECT_EQ(clean.KeptFaces, all);
    EXPECT_EQ(clean.NumDropped + clean.NumOutOfRange + clean.NumCollapsedCorners, 0);
    // Face 100, a triangle, repeats its first corner: dropped, the others as before.
    v[static_cast<size_t>(o[100] + 2)] = v[static_cast<size_t>(o[100])];
    const subd::FaceScreening repaired = subd::ScreenFaces(400, 300, o.data(), v.data(), subdtest::ThreeThreadFor);
    EXPECT_EQ(repaired.NumDropped, 1);
    EXPECT_EQ(repaired.FirstDroppedFace, 100);
    EXPECT_EQ(repaired.KeptFaces.size(), 299u);
    EXPECT_EQ(repaired.Vertices.size(), ev.size() - static_cast<size_t>(eo[101] - eo[100]));
  }
}

namespace
{
// Build's relations worked out the obvious way, for comparing: an edge per vertex pair met
// walking the faces, numbered in that order; a vertex's fans joined across its edges of two
// faces by a union-find.
void ExpectBuildEqualsBruteForce(Index numVertices, const std::vector<Index>& offsets,
  const std::vector<Index>& vertices, const std::string& what)
{
  SCOPED_TRACE(what);
  const MeshTopology t = MeshTopology::Build(numVertices, offsets, vertices, subdtest::ThreeThreadFor);
  const Index numFaces = static_cast<Index>(offsets.size()) - 1;
  std::vector<std::pair<Index, Index>> pairs;           // per edge, (lower, upper)
  std::vector<std::vector<Index>> edgeFaces;            // per edge
  std::vector<Index> forward;                           // per edge, faces running it as its first does
  std::vector<Index> faceEdges(vertices.size());
  std::vector<std::vector<Index>> vertexFaces(numVertices), vertexEdges(numVertices);
  for (Index f = 0; f < numFaces; ++f)
  {
    const Index n = offsets[f + 1] - offsets[f];
    for (Index c = 0; c < n; ++c)
    {
      const Index a = vertices[offsets[f] + c], b = vertices[offsets[f] + (c + 1) % n];
      const std::pair<Index, Index> key(std::min(a, b), std::max(a, b));
      Index e = static_cast<Index>(std::find(pairs.begin(), pairs.end(), key) - pairs.begin());
      if (e == static_cast<Index>(pairs.size()))
      {
        pairs.push_back(key);
        edgeFaces.emplace_back();
        forward.push_back(0);
        ASSERT_EQ(t.GetEdgeVertices(e)[0], a) << "edge " << e;
        ASSERT_EQ(t.GetEdgeVertices(e)[1], b) << "edge " << e;
        vertexEdges[key.first].push_back(e);
        vertexEdges[key.second].push_back(e);
      }
      edgeFaces[e].push_back(f);
      forward[e] += a == t.GetEdgeVertices(e)[0];
      faceEdges[offsets[f] + c] = e;
      vertexFaces[a].push_back(f);
    }
  }
  ASSERT_EQ(t.GetNumEdges(), static_cast<Index>(pairs.size()));
  for (Index f = 0; f < numFaces; ++f)
  {
    const subd::IndexSpan fe = t.GetFaceEdges(f);
    EXPECT_TRUE(std::equal(fe.begin(), fe.end(), faceEdges.begin() + offsets[f])) << "face " << f;
  }
  std::vector<bool> edgeNonManifold(pairs.size()), edgeBoundary(pairs.size());
  for (size_t e = 0; e < pairs.size(); ++e)
  {
    const Index faces = static_cast<Index>(edgeFaces[e].size());
    edgeBoundary[e] = faces == 1;
    edgeNonManifold[e] = faces > 2 || (faces == 2 && forward[e] == 2);
    const subd::IndexSpan ef = t.GetEdgeFaces(static_cast<Index>(e));
    EXPECT_TRUE(std::equal(ef.begin(), ef.end(), edgeFaces[e].begin(), edgeFaces[e].end())) << "edge " << e;
    EXPECT_EQ(t.GetEdgeTag(static_cast<Index>(e)).Boundary, edgeBoundary[e]) << "edge " << e;
    EXPECT_EQ(t.GetEdgeTag(static_cast<Index>(e)).NonManifold, edgeNonManifold[e]) << "edge " << e;
  }
  EXPECT_EQ(t.GetNumBoundaryEdges(), std::count(edgeBoundary.begin(), edgeBoundary.end(), true));
  EXPECT_EQ(t.GetNumNonManifoldEdges(), std::count(edgeNonManifold.begin(), edgeNonManifold.end(), true));
  for (Index v = 0; v < numVertices; ++v)
  {
    std::sort(vertexEdges[v].begin(), vertexEdges[v].end());
    const subd::IndexSpan vf = t.GetVertexFaces(v), ve = t.GetVertexEdges(v);
    EXPECT_TRUE(std::equal(vf.begin(), vf.end(), vertexFaces[v].begin(), vertexFaces[v].end())) << "vertex " << v;
    EXPECT_TRUE(std::equal(ve.begin(), ve.end(), vertexEdges[v].begin(), vertexEdges[v].end())) << "vertex " << v;
    bool boundary = false, nonManifold = false;
    for (Index e : vertexEdges[v])
    {
      boundary = boundary || edgeBoundary[e];
      nonManifold = nonManifold || edgeNonManifold[e];
    }
    // Fans: v's faces (by slot), joined across v's edges of exactly two faces.
    const std::vector<Index>& faces = vertexFaces[v];
    std::vector<Index> parent(faces.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&parent](Index i) {
      while (parent[i] != i)
      {
        i = parent[i];
      }
      return i;
    };
    Index fans = static_cast<Index>(faces.size());
    for (Index e : vertexEdges[v])
    {
      if (edgeFaces[e].size() == 2)
      {
        const Index a = root(static_cast<Index>(std::find(faces.begin(), faces.end(), edgeFaces[e][0]) - faces.begin()));
        const Index b = root(static_cast<Index>(std::find(faces.begin(), faces.end(), edgeFaces[e][1]) - faces.begin()));
        fans -= a != b;
        parent[a] = b;
      }
    }
    nonManifold = nonManifold || fans > 1;
    EXPECT_EQ(t.GetVertexTag(v).Boundary, boundary) << "vertex " << v;
    EXPECT_EQ(t.GetVertexTag(v).NonManifold, nonManifold) << "vertex " << v;
  }
}
}

// Random polygons over few vertices: every valence (the comparisons of up to 8 corners at
// once, up to 32, and the sorted lists beyond), repeated and flipped edges, pinched fans.
TEST(MeshTopology, BuildEqualsBruteForceOnRandomPolygonSoups)
{
  std::uint32_t state = 12345;
  auto random = [&state](Index n) {
    state = state * 1664525u + 1013904223u;
    return static_cast<Index>((state >> 8) % static_cast<std::uint32_t>(n));
  };
  for (int round = 0; round < 60; ++round)
  {
    const Index numVertices = 5 + random(40);
    const Index numFaces = 1 + random(round < 30 ? 40 : 200);
    std::vector<Index> offsets{ 0 }, vertices;
    for (Index f = 0; f < numFaces; ++f)
    {
      const Index size = 3 + (round % 3 == 0 ? random(3) : 0);
      std::vector<Index> face;
      while (static_cast<Index>(face.size()) < size)
      {
        // Half the corners at vertex 0: a hub of high valence in the larger rounds.
        const Index v = random(4) == 0 ? 0 : random(numVertices);
        if (std::find(face.begin(), face.end(), v) == face.end())
        {
          face.push_back(v);
        }
      }
      vertices.insert(vertices.end(), face.begin(), face.end());
      offsets.push_back(static_cast<Index>(vertices.size()));
    }
    ExpectBuildEqualsBruteForce(numVertices, offsets, vertices, "round " + std::to_string(round));
  }
}

// Edges are counted while pairing, per block of faces starting in 1024 corners or more, and
// numbered per block: polygons of mixed sizes straddle the blocks' bounds, a few edges are
// repeated, flipped or open, and the first half-edge of an edge often lies in a later block
// than its pair.
TEST(MeshTopology, BuildEqualsBruteForceAcrossEdgeCountBlocks)
{
  std::uint32_t state = 777;
  auto random = [&state](Index n) {
    state = state * 1664525u + 1013904223u;
    return static_cast<Index>((state >> 8) % static_cast<std::uint32_t>(n));
  };
  // A band of quads (closed around), a third of them cut into triangles: most edges have two
  // faces; then random triangles for more boundary and non-manifold edges.
  const Index columns = 700;
  std::vector<Index> offsets{ 0 }, vertices;
  auto at = [columns](Index row, Index column) { return row * columns + column % columns; };
  for (Index row = 0; row + 1 < 4; ++row)
  {
    for (Index column = 0; column < columns; ++column)
    {
      const Index a = at(row, column), b = at(row, column + 1), c = at(row + 1, column + 1), d = at(row + 1, column);
      if (random(3) == 0)
      {
        vertices.insert(vertices.end(), { a, b, c, d });
        offsets.push_back(static_cast<Index>(vertices.size()));
      }
      else
      {
        vertices.insert(vertices.end(), { a, b, c });
        offsets.push_back(static_cast<Index>(vertices.size()));
        vertices.insert(vertices.end(), { a, c, d });
        offsets.push_back(static_cast<Index>(vertices.size()));
      }
    }
  }
  const Index numVertices = 4 * columns;
  for (Index extra = 0; extra < 300; ++extra)
  {
    const Index a = random(numVertices), b = random(numVertices), c = random(numVertices);
    if (a != b && b != c && a != c)
    {
      vertices.insert(vertices.end(), { a, b, c });
      offsets.push_back(static_cast<Index>(vertices.size()));
    }
  }
  ASSERT_GT(vertices.size(), 8u * 1024u); // several blocks
  ExpectBuildEqualsBruteForce(numVertices, offsets, vertices, "strip");
}

// Closed and open fans of every size around one vertex, manifold: no vertex tagged.
TEST(MeshTopology, BuildEqualsBruteForceOnFansOfEverySize)
{
  for (Index sides = 3; sides <= 40; ++sides)
  {
    for (bool closed : { true, false })
    {
      std::vector<Index> offsets{ 0 }, vertices;
      for (Index k = 0; k < (closed ? sides : sides - 1); ++k)
      {
        vertices.insert(vertices.end(), { 0, 1 + k, 1 + (k + 1) % sides });
        offsets.push_back(static_cast<Index>(vertices.size()));
      }
      ExpectBuildEqualsBruteForce(1 + sides, offsets, vertices, std::to_string(sides) + (closed ? " closed" : " open"));
      EXPECT_EQ(MeshTopology::Build(1 + sides, offsets, vertices).GetNumNonManifoldVertices(), 0);
    }
  }
}

// vtkSMPTools does not split a range shorter than its grain (2048 indices): a loop over a
// few blocks (64 ranges of faces) must still reach several of the
// chunks a ParallelFor so made hands to its threads, or it runs on one thread.
TEST(Parallel, FewBlocksReachSeveralChunksOfAGrainedFor)
{
  int chunks = 0;
  const subd::ParallelFor grained = [&chunks](Index begin, Index end, const subd::RangeTask& task) {
    for (Index b = begin; b < end; b += 2048, ++chunks)
    {
      task(b, std::min(end, b + 2048));
    }
  };
  std::vector<int> chunkOf(64, -1);
  subd::ForEachBlock(64, grained, [&](Index b) {
    EXPECT_EQ(chunkOf[b], -1) << "block " << b << " run twice";
    chunkOf[b] = chunks;
  });
  EXPECT_EQ(std::count(chunkOf.begin(), chunkOf.end(), -1), 0);
  std::sort(chunkOf.begin(), chunkOf.end());
  EXPECT_EQ(std::unique(chunkOf.begin(), chunkOf.end()) - chunkOf.begin(), 64); // one chunk each
}

// The branch-free lookups the rules use on edges' ends and faces and triangles' corners.
TEST(MeshTopology, BranchFreeLookupsFindTheOtherEntryAndThePlace)
{
  const subd::Index pair[2] = { 7, 123456 };
  EXPECT_EQ(subd::OtherOfTwo(subd::IndexSpan{ pair, 2 }, 7), 123456);
  EXPECT_EQ(subd::OtherOfTwo(subd::IndexSpan{ pair, 2 }, 123456), 7);
  const subd::Index triangle[3] = { 40, 0, 2147483647 };
  for (subd::Index place = 0; place < 3; ++place)
  {
    EXPECT_EQ(subd::PlaceInTriangle(triangle, triangle[place]), place);
  }
}

// Faces written in blocks (the dual split's): element i gives a face of 3 + i % 4 corners, or
// none when i % 5 == 0. The faces come in element order whatever the threads, and the
// elements are cut into at most 64 ranges however finely the ParallelFor cuts its range: its
// many small blocks churned through the C library's per-thread arenas, which kept the pieces.
TEST(FaceBlocks, FacesInElementOrderFromFewRanges)
{
  const Index numElements = 20000;
  std::vector<Index> expectedVertices, expectedOffsets{ 0 }, expectedOrigins;
  for (Index i = 0; i < numElements; ++i)
  {
    if (i % 5 == 0)
    {
      continue;
    }
    for (Index k = 0; k < 3 + i % 4; ++k)
    {
      expectedVertices.push_back(i + k);
    }
    expectedOffsets.push_back(static_cast<Index>(expectedVertices.size()));
    expectedOrigins.push_back(i);
  }
  const subd::ParallelFor fine = [](Index begin, Index end, const subd::RangeTask& task) {
    for (Index b = begin; b < end; b += 10)
    {
      task(b, std::min(end, b + 10));
    }
  };
  for (const subd::ParallelFor& parallelFor :
    { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor), fine })
  {
    std::atomic<int> ranges{ 0 };
    const subd::EmittedFaces faces =
      subd::EmitFacesInParallel(numElements, parallelFor, [&](Index begin, Index end, subd::FaceBlock& block) {
        ++ranges;
        for (Index i = begin; i < end; ++i)
        {
          if (i % 5 == 0)
          {
            continue;
          }
          for (Index k = 0; k < 3 + i % 4; ++k)
          {
            block.Vertices.push_back(i + k);
          }
          block.EndFace(i, static_cast<std::uint8_t>(i % 2));
        }
      });
    EXPECT_LE(ranges.load(), 64);
    ASSERT_EQ(std::vector<Index>(faces.Vertices.begin(), faces.Vertices.end()), expectedVertices);
    ASSERT_EQ(std::vector<Index>(faces.Offsets.begin(), faces.Offsets.end()), expectedOffsets);
    ASSERT_EQ(std::vector<Index>(faces.Origins.begin(), faces.Origins.end()), expectedOrigins);
    for (size_t f = 0; f < expectedOrigins.size(); ++f)
    {
      ASSERT_EQ(faces.Holes[f], expectedOrigins[f] % 2);
    }
  }
}

// Points at one position, found exactly: each names the first point there, -0 and +0 are one
// position, points a rounding apart are not.
TEST(CoincidentPoints, FirstPointAtSamePosition)
{
  const double xyz[] = { 0, 0, 0, 1, 2, 3, -0.0, 0, -0.0, 1, 2, 3, 1, 2, std::nextafter(3.0, 4.0), 1, 2, 3 };
  const std::vector<subd::Index> first = subd::FirstPointAtSamePosition(xyz, 6);
  EXPECT_EQ(first, (std::vector<subd::Index>{ 0, 1, 0, 1, 4, 1 }));
}
