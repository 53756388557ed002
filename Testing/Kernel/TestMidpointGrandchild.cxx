// The midpoint scheme's finest level written from its grandparent in closed form
// (SubDMidpointGrandchild.h), against two splits by the split itself (SubDMidpointSplit.h).
#include "SubDMemoryEstimate.h"
#include "SubDMidpointGrandchild.h"
#include "SubDMidpointSplit.h"
#include "SubDScheme.h"
#include "SubDTestHeap.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using subd::Index;

namespace
{
// A closed surface of two quads glued along their boundary: every vertex has two faces.
subdtest::TestMesh Pillow()
{
  subdtest::TestMesh m;
  m.Name = "pillow";
  m.AddPoint(0, 0, 0);
  m.AddPoint(1, 0, 0);
  m.AddPoint(1, 1, 0);
  m.AddPoint(0, 1, 0);
  m.AddFace({ 0, 1, 2, 3 });
  m.AddFace({ 3, 2, 1, 0 });
  return m;
}

// A lean split (MidpointChildWithEdges) has the faces' offsets and edges, the edges' ends and
// the origins of the split itself, and no corners or relations around its vertices.
void ExpectSameFacesEdgesAndOrigins(const subd::Level& lean, const subd::Level& split, const std::string& what)
{
  const subd::MeshTopology& a = lean.Topology;
  const subd::MeshTopology& b = split.Topology;
  ASSERT_EQ(a.GetFaceOffsetArray(), b.GetFaceOffsetArray()) << what;
  ASSERT_EQ(a.GetFaceEdgeArray(), b.GetFaceEdgeArray()) << what;
  EXPECT_TRUE(a.GetFaceVertexArray().empty()) << what;
  EXPECT_EQ(a.GetNumFaceCorners(), b.GetNumFaceCorners()) << what;
  ASSERT_EQ(a.GetNumEdges(), b.GetNumEdges()) << what;
  ASSERT_EQ(a.GetNumVertices(), b.GetNumVertices()) << what;
  for (Index e = 0; e < a.GetNumEdges(); ++e)
  {
    ASSERT_EQ(a.GetEdgeVertices(e)[0], b.GetEdgeVertices(e)[0]) << what << " edge " << e;
    ASSERT_EQ(a.GetEdgeVertices(e)[1], b.GetEdgeVertices(e)[1]) << what << " edge " << e;
  }
  EXPECT_EQ(lean.FaceOrigin, split.FaceOrigin) << what;
  EXPECT_EQ(lean.Depth, split.Depth) << what;
  EXPECT_FALSE(a.HasVertexRelations()) << what;
}

// Values of `rows` applied to `parents` (components values each) in ranges of two rows on
// three threads.
std::vector<double> ApplyOnThreads(const subd::StencilTable& rows, const std::vector<double>& parents, int components)
{
  std::vector<double> children(static_cast<size_t>(rows.GetNumRows()) * components);
  for (Index b = 0; b < rows.GetNumBlocks(); ++b)
  {
    subdtest::ThreeThreadFor(rows.GetBlockBegin(b), rows.GetBlockEnd(b), [&](Index begin, Index end) {
      rows.ApplyRows(parents.data(), children.data(), components, begin, end);
    });
  }
  return children;
}
}

// On every closed smooth fixture (n-gons, a torus, valences 3 to 8 and an apex of valence 70,
// past the fan walk's room on the stack), from the base level and from one split down: the
// faces, their origins (scrambled in the grandparent, so that each child's lowest one is
// tested) and the rows' values equal, bit for bit, those of splitting twice, serially and on
// threads, with the grandparent trimmed to what Refine keeps of it (Part::FacesWithEdges);
// and the lean split (MidpointChildWithEdges) has the faces, edges and origins of the split.
TEST(MidpointGrandchild, EqualsTwoSplits)
{
  std::vector<subdtest::TestMesh> meshes = subdtest::StandardMeshes();
  for (const subdtest::TestMesh& m : subdtest::TriangleMeshes())
  {
    meshes.push_back(m);
  }
  meshes.push_back(subdtest::Bipyramid(70));
  int checked = 0;
  for (const subdtest::TestMesh& mesh : meshes)
  {
    subd::Level grandparent = subdtest::BaseLevel(mesh);
    for (int depth = 0; depth < 2; ++depth)
    {
      if (depth == 1)
      {
        grandparent = subd::SplitMidpoint(grandparent, subd::ChildTopology::Full);
      }
      if (!subd::MidpointGrandchildHasClosedForm(grandparent))
      {
        continue;
      }
      const std::string what = mesh.Name + " from depth " + std::to_string(depth);
      for (Index f = 0; f < grandparent.Topology.GetNumFaces(); ++f)
      {
        grandparent.FaceOrigin[f] = (f * 7919) % 1009; // not increasing
      }
      const subd::Level parent = subd::SplitMidpoint(grandparent, subd::ChildTopology::Full);
      const subd::Level fine = subd::SplitMidpoint(parent, subd::ChildTopology::FacesOnly);
      const auto parentRows = subd::StencilTable::FromSource(
        subd::MakeMidpointRowSource(std::make_shared<const subd::Level>(parent)));

      // The split with what the grandchild reads alone: the full split's faces, edges and
      // origins.
      for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor),
             subd::ParallelFor(subdtest::ThreeThreadFor) })
      {
        const subd::Level lean = subd::MidpointChildWithEdges(grandparent, true, parallelFor);
        ExpectSameFacesEdgesAndOrigins(lean, parent, what);
        EXPECT_TRUE(subd::MidpointChildWithEdges(grandparent, false, parallelFor).FaceOrigin.empty()) << what;
        // Its own rows are the split's (no vertex kept: none is on a boundary or sharp).
        const auto leanRows = subd::StencilTable::FromSource(
          subd::MakeMidpointRowSource(std::make_shared<const subd::Level>(lean)));
        ASSERT_EQ(leanRows.GetNumRows(), parentRows.GetNumRows()) << what;
        std::vector<double> values(static_cast<size_t>(leanRows.GetNumParents()) * 3);
        for (size_t i = 0; i < values.size(); ++i)
          values[i] = std::cos(0.21 * static_cast<double>(i));
        std::vector<double> expected(static_cast<size_t>(parentRows.GetNumRows()) * 3);
        parentRows.Apply(values.data(), expected.data(), 3);
        EXPECT_EQ(ApplyOnThreads(leanRows, values, 3), expected) << what;
      }

      auto trimmed = std::make_shared<subd::Level>(grandparent);
      subd::KeepOnly(*trimmed, subd::MeshTopology::Part::FacesWithEdges, subd::SerialFor, true);
      ASSERT_FALSE(trimmed->Topology.HasVertexRelations());
      ASSERT_TRUE(trimmed->Topology.GetFaceVertexArray().empty()); // corners from the edges' ends
      ASSERT_EQ(trimmed->Topology.GetNumFaceCorners(), grandparent.Topology.GetNumFaceCorners());
      for (const subd::ParallelFor& parallelFor : { subd::ParallelFor(subd::SerialFor),
             subd::ParallelFor(subdtest::ThreeThreadFor) })
      {
        const subd::MeshTopology faces = subd::MidpointGrandchildFaces(trimmed->Topology, parallelFor);
        ASSERT_EQ(faces.GetFaceOffsetArray(), fine.Topology.GetFaceOffsetArray()) << what;
        ASSERT_EQ(faces.GetFaceVertexArray(), fine.Topology.GetFaceVertexArray()) << what;
        EXPECT_EQ(faces.GetNumVertices(), fine.Topology.GetNumVertices()) << what;
        EXPECT_EQ(subd::CountMidpointGrandchildFaces(trimmed->Topology), fine.Topology.GetNumFaces()) << what;

        const subd::Level tags = subd::MidpointGrandchildTags(*trimmed, true, parallelFor);
        EXPECT_EQ(tags.FaceOrigin, fine.FaceOrigin) << what;
        EXPECT_EQ(tags.Depth, fine.Depth) << what;
        EXPECT_TRUE(subd::MidpointGrandchildTags(*trimmed, false, parallelFor).FaceOrigin.empty()) << what;
      }
      const auto rows = subd::StencilTable::FromSource(subd::MakeMidpointGrandchildRowSource(trimmed));
      ASSERT_EQ(rows.GetNumRows(), parentRows.GetNumRows()) << what;
      ASSERT_EQ(rows.GetNumParents(), parentRows.GetNumParents()) << what;
      for (int components : { 3, 5 })
      {
        std::vector<double> values(static_cast<size_t>(rows.GetNumParents()) * components);
        for (size_t i = 0; i < values.size(); ++i)
          values[i] = std::sin(0.37 * static_cast<double>(i));
        std::vector<double> expected(static_cast<size_t>(rows.GetNumRows()) * components);
        parentRows.Apply(values.data(), expected.data(), components);
        EXPECT_EQ(ApplyOnThreads(rows, values, components), expected) << what;
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

// Levels split lean from lean parents (what Refine does from a closed smooth base down to the
// finest level's grandparent) have the faces' edges, edges' ends and origins of the split
// itself two levels down, and the closed form; the finest faces from the second equal two
// more splits, on threads.
TEST(MidpointGrandchild, LeanSplitsChainFromTheBase)
{
  int checked = 0;
  for (const subdtest::TestMesh& mesh : { subdtest::Cube().Jitter(0.1), subdtest::Grid(6, 5, true, true).Jitter(0.05),
         subdtest::House(false).Jitter(0.1), subdtest::Bipyramid(70) })
  {
    subd::Level base = subdtest::BaseLevel(mesh);
    ASSERT_TRUE(subd::MidpointGrandchildHasClosedForm(base)) << mesh.Name;
    for (Index f = 0; f < base.Topology.GetNumFaces(); ++f)
    {
      base.FaceOrigin[f] = (f * 7919) % 1009;
    }
    const subd::Level full1 = subd::SplitMidpoint(base, subd::ChildTopology::Full);
    const subd::Level full2 = subd::SplitMidpoint(full1, subd::ChildTopology::Full);
    const subd::Level lean1 = subd::MidpointChildWithEdges(base, true, subdtest::ThreeThreadFor);
    ASSERT_TRUE(subd::MidpointGrandchildHasClosedForm(lean1)) << mesh.Name;
    const subd::Level lean2 = subd::MidpointChildWithEdges(lean1, true, subdtest::ThreeThreadFor);
    ASSERT_TRUE(subd::MidpointGrandchildHasClosedForm(lean2)) << mesh.Name;
    ExpectSameFacesEdgesAndOrigins(lean1, full1, mesh.Name + " one split down");
    ExpectSameFacesEdgesAndOrigins(lean2, full2, mesh.Name + " two splits down");
    const subd::Level fine =
      subd::SplitMidpoint(subd::SplitMidpoint(full2, subd::ChildTopology::Full), subd::ChildTopology::FacesOnly);
    const subd::MeshTopology faces = subd::MidpointGrandchildFaces(lean2.Topology, subdtest::ThreeThreadFor);
    EXPECT_EQ(faces.GetFaceOffsetArray(), fine.Topology.GetFaceOffsetArray()) << mesh.Name;
    EXPECT_EQ(faces.GetFaceVertexArray(), fine.Topology.GetFaceVertexArray()) << mesh.Name;
    EXPECT_EQ(subd::MidpointGrandchildTags(lean2, true, subdtest::ThreeThreadFor).FaceOrigin, fine.FaceOrigin)
      << mesh.Name;
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

// Refine with threads and without the finest faces' origins (what the filters do when no cell
// data is carried), in the leaner modes, gives the faces and points of the stored refinement
// bit for bit, from two to four levels, on closed meshes with and without the closed form at
// the base: a torus, a cube, and a cube with a vertex of two faces on one of its edges (no
// V-face there: the closed form first holds one split down).
TEST(MidpointGrandchild, RefineOnThreadsWithoutOriginsEqualsTheStoredRefinement)
{
  // The cube with vertex 8 inserted on its edge from 0 to 1, in both faces of that edge.
  subdtest::TestMesh notched;
  notched.Name = "cube with a vertex of two faces";
  const subdtest::TestMesh cube = subdtest::Cube();
  notched.Points = cube.Points;
  notched.AddPoint(0.5, -0.05, 0.0);
  notched.AddFace({ 0, 3, 2, 1, 8 });
  notched.AddFace({ 4, 5, 6, 7 });
  notched.AddFace({ 0, 8, 1, 5, 4 });
  notched.AddFace({ 1, 2, 6, 5 });
  notched.AddFace({ 2, 3, 7, 6 });
  notched.AddFace({ 3, 0, 4, 7 });
  const std::vector<subdtest::TestMesh> meshes = { subdtest::Grid(6, 5, true, true).Jitter(0.05),
    subdtest::Cube().Jitter(0.1), notched };
  const subd::Level notchedBase = subdtest::BaseLevel(notched);
  ASSERT_EQ(notchedBase.Topology.GetNumVertexFaces(8), 2);
  ASSERT_EQ(notchedBase.Topology.GetNumBoundaryEdges(), 0);
  ASSERT_FALSE(subd::MidpointGrandchildHasClosedForm(notchedBase));
  subd::MidpointScheme threaded;
  threaded.SetParallelFor(subdtest::ThreeThreadFor);
  threaded.SetFacesOnlyOrigins(false);
  const subd::MidpointScheme serial;
  int closedForms = 0;
  for (const subdtest::TestMesh& mesh : meshes)
  {
    for (int levels = 2; levels <= 4; ++levels)
    {
      const std::string what = mesh.Name + " L" + std::to_string(levels);
      subd::Hierarchy stored;
      subd::Refine(serial, subdtest::BaseLevel(mesh), levels, stored);
      subd::Hierarchy above;
      subd::Refine(serial, subdtest::BaseLevel(mesh), levels - 2, above, nullptr, subd::ChildTopology::Full);
      const bool closedForm = subd::MidpointGrandchildHasClosedForm(above.Finest);
      closedForms += closedForm;
      for (subd::LevelRows rows : { subd::LevelRows::WrittenLean, subd::LevelRows::WrittenFromGrandparent })
      {
        subd::Hierarchy written;
        subd::Refine(threaded, subdtest::BaseLevel(mesh), levels, written, nullptr, subd::ChildTopology::FacesOnly, rows);
        EXPECT_EQ(written.HasFinestFaces(), !closedForm) << what;
        std::vector<double> a(static_cast<size_t>(stored.GetNumFinestPoints()) * 3), b(a.size());
        ASSERT_EQ(written.GetNumFinestPoints(), stored.GetNumFinestPoints()) << what;
        stored.Evaluate(mesh.Points.data(), 3, a.data());
        written.Evaluate(mesh.Points.data(), 3, b.data(), subdtest::ThreeThreadFor);
        EXPECT_EQ(a, b) << what;
        written.MakeFinestFaces();
        EXPECT_EQ(written.Finest.Topology.GetFaceOffsetArray(), stored.Finest.Topology.GetFaceOffsetArray()) << what;
        EXPECT_EQ(written.Finest.Topology.GetFaceVertexArray(), stored.Finest.Topology.GetFaceVertexArray()) << what;
        EXPECT_EQ(written.Finest.FaceOrigin.empty(), closedForm) << what; // origins not made
      }
    }
  }
  EXPECT_GE(closedForms, 7); // torus and cube at every level, the notched cube from level 3
}

// No closed form where the level between keeps a vertex or misses a V-face: a boundary, a
// non-manifold edge or vertex, a sharp edge or vertex (semi-sharp included), a hole, a vertex
// of two faces.
TEST(MidpointGrandchild, NoneWhereTheSplitKeepsVerticesOrLeavesVFacesOut)
{
  const subdtest::TestMesh cube = subdtest::Cube();
  EXPECT_TRUE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(cube)));
  EXPECT_TRUE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(subdtest::Grid(6, 5, true, true))));
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(subdtest::Grid(4, 3, false, false))));
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(subdtest::House(true))));
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(subdtest::NonManifold())));
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(subdtest::PinchedCubes())));
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(subdtest::BaseLevel(Pillow())));
  const subd::MeshTopology topology = subd::MeshTopology::Build(cube.NumVertices(), cube.Offsets, cube.Vertices);
  subd::BaseTags semiSharpEdge;
  semiSharpEdge.EdgeSharpness.assign(static_cast<size_t>(topology.GetNumEdges()), 0.0f);
  semiSharpEdge.EdgeSharpness[3] = 0.5f;
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(
    subd::MakeBaseLevel(topology, semiSharpEdge, subd::BoundaryRule::EdgeOnly)));
  subd::BaseTags sharpVertex;
  sharpVertex.VertexSharpness.assign(static_cast<size_t>(topology.GetNumVertices()), 0.0f);
  sharpVertex.VertexSharpness[5] = 2.0f;
  EXPECT_FALSE(subd::MidpointGrandchildHasClosedForm(
    subd::MakeBaseLevel(topology, sharpVertex, subd::BoundaryRule::EdgeOnly)));
  subd::BaseTags hole;
  hole.FaceIsHole.assign(static_cast<size_t>(topology.GetNumFaces()), 0);
  hole.FaceIsHole[2] = 1;
  EXPECT_FALSE(
    subd::MidpointGrandchildHasClosedForm(subd::MakeBaseLevel(topology, hole, subd::BoundaryRule::EdgeOnly)));
  // The semi-sharp edge has decayed one split down: the closed form holds there.
  const subd::Level creased = subd::MakeBaseLevel(topology, semiSharpEdge, subd::BoundaryRule::EdgeOnly);
  EXPECT_TRUE(subd::MidpointGrandchildHasClosedForm(subd::SplitMidpoint(creased, subd::ChildTopology::Full)));
}

// The memory estimate counts the finest level from its grandparent alone only for a closed
// manifold base whose vertices have three faces or more (RefinementRequest::ClosedManifoldBase,
// ThreeFacesAtEveryBaseVertex): it still covers what the refinement
// and its evaluation hold (the heap in use, the finest faces made), and stays below the
// general path's, from two to four levels (the grandparent whole, then split lean).
#if defined(SUBD_HEAP_MEASURABLE)
TEST(MidpointGrandchild, MemoryEstimateCoversTheHeldMemory)
{
  const subd::MidpointScheme scheme;
  const subdtest::TestMesh mesh = subdtest::Grid(40, 40, true, true); // a torus
  const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  for (int levels = 2; levels <= 4; ++levels)
  {
    subd::RefinementRequest request;
    request.Base = { double(topology.GetNumFaces()), double(topology.GetNumEdges()),
      double(topology.GetNumVertices()), double(topology.GetNumFaceCorners()),
      double(topology.GetNumBoundaryEdges()) };
    request.Levels = levels;
    request.Rows = subd::LevelRows::WrittenLean;
    const double general = subd::EstimatePeakBytes(scheme, request);
    request.ClosedManifoldBase = true;
    EXPECT_EQ(subd::EstimatePeakBytes(scheme, request), general) << levels; // vertices of two faces?
    request.ThreeFacesAtEveryBaseVertex = true;
    const double predicted = subd::EstimatePeakBytes(scheme, request) - subd::EstimateLibraryBytes;
    EXPECT_LT(predicted + subd::EstimateLibraryBytes, general) << levels;
    const size_t before = subdtest::HeapInUse();
    double held = 0.0;
    {
      subd::Hierarchy hierarchy;
      subd::Refine(scheme, subd::MakeBaseLevel(topology, {}, subd::BoundaryRule::EdgeOnly), request.Levels,
        hierarchy, nullptr, request.Finest, request.Rows);
      EXPECT_FALSE(hierarchy.HasFinestFaces()) << levels; // written from the grandparent
      std::vector<double> finest(static_cast<size_t>(hierarchy.GetNumFinestPoints()) * 3);
      hierarchy.Evaluate(mesh.Points.data(), 3, finest.data());
      hierarchy.MakeFinestFaces();
      held = static_cast<double>(subdtest::HeapInUse() - before);
    }
    EXPECT_GT(held, 1.0e5) << levels; // a measurement, not noise
    EXPECT_LE(held, predicted) << levels;
  }
}
#endif
