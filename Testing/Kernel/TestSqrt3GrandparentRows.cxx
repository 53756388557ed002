// The sqrt(3) rows of a level written from the level two above (SubDSqrt3GrandparentRows.h).
#include "SubDMemoryEstimate.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDSqrt3GrandparentRows.h"
#include "SubDSqrt3Rules.h"
#include "SubDTestHeap.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

using subd::Index;

namespace
{
// The closed triangle meshes of the fixtures (every one smooth: no tags).
std::vector<subdtest::TestMesh> ClosedTriangleMeshes()
{
  std::vector<subdtest::TestMesh> meshes;
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    if (subdtest::BaseLevel(mesh).Topology.GetNumBoundaryEdges() == 0 &&
      subdtest::BaseLevel(mesh).Topology.GetNumNonManifoldEdges() == 0 &&
      subdtest::BaseLevel(mesh).Topology.GetNumNonManifoldVertices() == 0)
    {
      meshes.push_back(mesh);
    }
  }
  meshes.push_back(subdtest::Bipyramid(70)); // apices of valence 70: fans past the stack
  return meshes;
}

// `rows` applied to `components` values per point of the level they read.
std::vector<double> Apply(const subd::StencilTable& rows, int components)
{
  std::vector<double> parents(static_cast<size_t>(rows.GetNumParents()) * components);
  for (size_t i = 0; i < parents.size(); ++i)
  {
    parents[i] = std::sin(0.37 * static_cast<double>(i)) + 0.01 * static_cast<double>(i % 7);
  }
  std::vector<double> children(static_cast<size_t>(rows.GetNumRows()) * components);
  rows.Apply(parents.data(), children.data(), components);
  return children;
}
}

// On closed smooth levels the rows written from the grandparent, which keeps its triangles
// alone, are the parent's own rows: the same values to the bit through the rows' closed form
// (3 components) and their written entries (5), serially and on threads.
TEST(Sqrt3GrandparentRows, EqualTheParentsRowsOnClosedSmoothLevels)
{
  const subd::Sqrt3Scheme scheme;
  int checked = 0;
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    subd::Level grandparent = subdtest::BaseLevel(mesh);
    for (int depth = 0; depth < 2; ++depth)
    {
      SCOPED_TRACE(mesh.Name + " depth " + std::to_string(depth));
      subd::Level parent = scheme.Split(grandparent, subd::ChildTopology::Full);
      ASSERT_TRUE(subd::Sqrt3RowsFromGrandparentApply(grandparent, parent));
      ASSERT_TRUE(subd::Sqrt3RowsFromGrandparentApply(grandparent, parent, subdtest::ThreeThreadFor));
      const subd::StencilTable expected = scheme.BuildStencils(parent);
      auto trimmed = std::make_shared<subd::Level>(grandparent);
      subd::KeepOnly(*trimmed, subd::MeshTopology::Part::FacesAndRings); // what Refine keeps of it
      for (const subd::ParallelFor& parallelFor :
        { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
      {
        const subd::StencilTable rows =
          subd::StencilTable::FromSource(subd::MakeSqrt3RowSourceFromGrandparent(trimmed, parallelFor));
        EXPECT_TRUE(subd::IsSqrt3RowSourceFromGrandparent(rows.GetSource()));
        ASSERT_EQ(rows.GetNumParents(), expected.GetNumParents());
        ASSERT_EQ(rows.GetNumRows(), expected.GetNumRows());
        EXPECT_EQ(Apply(rows, 3), Apply(expected, 3));
        EXPECT_EQ(Apply(rows, 5), Apply(expected, 5));
      }
      ++checked;
      grandparent = std::move(parent);
    }
  }
  EXPECT_GE(checked, 10);
}

// A closed level's rows reading each ring from the fans of its triangles are its rows reading
// the rings, to the bit, with nothing of the level kept but its faces; the next level's rows
// written from it share those fans. Other levels have no such rows.
TEST(Sqrt3GrandparentRows, RowsReadingFansEqualTheRowsReadingRings)
{
  const subd::Sqrt3Scheme scheme;
  int checked = 0;
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    subd::Level level = subdtest::BaseLevel(mesh);
    for (int depth = 0; depth < 2; ++depth, level = scheme.Split(level, subd::ChildTopology::Full))
    {
      SCOPED_TRACE(mesh.Name + " depth " + std::to_string(depth));
      const subd::StencilTable expected = scheme.BuildStencils(level);
      const subd::StencilTable expectedNext = scheme.BuildStencils(scheme.Split(level, subd::ChildTopology::Full));
      for (const subd::ParallelFor& parallelFor :
        { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
      {
        auto kept = std::make_shared<subd::Level>(level);
        const auto source = subd::MakeSqrt3RowSourceReadingFans(kept, parallelFor);
        ASSERT_NE(source, nullptr);
        subd::KeepOnly(*kept, subd::MeshTopology::Part::Faces); // what Refine keeps of it then
        const std::shared_ptr<const subd::TriangleFans> fans = subd::Sqrt3RowFans(source.get());
        ASSERT_NE(fans, nullptr);
        const subd::StencilTable rows = subd::StencilTable::FromSource(source);
        ASSERT_EQ(rows.GetNumRows(), expected.GetNumRows());
        EXPECT_EQ(Apply(rows, 3), Apply(expected, 3));
        EXPECT_EQ(Apply(rows, 5), Apply(expected, 5));
        const subd::StencilTable next =
          subd::StencilTable::FromSource(subd::MakeSqrt3RowSourceFromGrandparent(kept, parallelFor, fans));
        EXPECT_EQ(fans.use_count(), 3); // here, in the level's rows and in the next level's
        ASSERT_EQ(next.GetNumRows(), expectedNext.GetNumRows());
        EXPECT_EQ(Apply(next, 3), Apply(expectedNext, 3));
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
  const auto open = std::make_shared<subd::Level>(subdtest::BaseLevel(subdtest::House(true).Triangulated()));
  EXPECT_EQ(subd::MakeSqrt3RowSourceReadingFans(open), nullptr);
  EXPECT_EQ(scheme.MakeRowSourceWithoutVertexLists(open), nullptr);
  const auto closed = std::make_shared<subd::Level>(subdtest::BaseLevel(subdtest::Bipyramid(5)));
  EXPECT_EQ(subd::Sqrt3RowFans(subd::MakeSqrt3RowSource(closed).get()), nullptr);
  EXPECT_NE(subd::Sqrt3RowFans(scheme.MakeRowSourceWithoutVertexLists(closed).get()), nullptr);
  auto creased = std::make_shared<subd::Level>(*closed);
  creased->EdgeSharpness[0] = 2.0f; // its child is not in the closed form
  EXPECT_EQ(scheme.MakeRowSourceWithoutVertexLists(creased), nullptr);
}

// A child split to be split alone (LeanChild::SplitAlone) keeps its faces, edges and face
// counts, but no list around its vertices and, where nothing is sharp, no sharpness: what
// its own split and the check for the rows from its parent read. Split alone, it gives the
// whole child's children; RestoreSplitAloneTrim gives back the whole child's lists and
// sharpness. A sharp child keeps its sharpness.
TEST(Sqrt3GrandparentRows, ChildSplitAloneKeepsWhatItsSplitReads)
{
  const subd::Sqrt3Scheme scheme;
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    SCOPED_TRACE(mesh.Name);
    const subd::Level base = subdtest::BaseLevel(mesh);
    const subd::Level whole = scheme.Split(base, subd::ChildTopology::Full);
    subd::Level lean =
      subd::SplitSqrt3(base, subd::ChildTopology::Full, subd::SerialFor, {}, nullptr, subd::LeanChild::SplitAlone);
    EXPECT_FALSE(lean.Topology.HasVertexRelations());
    EXPECT_FALSE(lean.Topology.HasVertexFaceLists());
    EXPECT_TRUE(lean.Topology.HasVertexFaceCounts());
    EXPECT_TRUE(lean.EdgeSharpness.empty());
    EXPECT_TRUE(lean.VertexSharpness.empty());
    EXPECT_EQ(lean.Topology.GetFaceVertexArray(), whole.Topology.GetFaceVertexArray());
    ASSERT_EQ(lean.Topology.GetNumEdges(), whole.Topology.GetNumEdges());
    EXPECT_TRUE(subd::Sqrt3RowsFromGrandparentApply(base, lean));
    subd::Level restored = lean;
    const subd::Level grandchild = scheme.SplitFinestAlone(lean);
    EXPECT_EQ(grandchild.Topology.GetFaceVertexArray(),
      scheme.Split(whole, subd::ChildTopology::FacesOnly).Topology.GetFaceVertexArray());
    subd::RestoreSplitAloneTrim(restored, subdtest::ThreeThreadFor);
    ASSERT_TRUE(restored.Topology.HasVertexRelations());
    for (Index v = 0; v < whole.Topology.GetNumVertices(); ++v)
    {
      const subd::IndexSpan a = restored.Topology.GetVertexEdges(v), b = whole.Topology.GetVertexEdges(v);
      EXPECT_EQ(std::vector<Index>(a.begin(), a.end()), std::vector<Index>(b.begin(), b.end()));
    }
    EXPECT_EQ(restored.EdgeSharpness, whole.EdgeSharpness);
    EXPECT_EQ(restored.VertexSharpness, whole.VertexSharpness);
  }
  subd::Level creased = subdtest::BaseLevel(subdtest::Bipyramid(5));
  creased.EdgeSharpness[0] = 2.0f;
  const subd::Level lean =
    subd::SplitSqrt3(creased, subd::ChildTopology::Full, subd::SerialFor, {}, nullptr, subd::LeanChild::SplitAlone);
  EXPECT_FALSE(lean.Topology.HasVertexRelations());
  EXPECT_TRUE(lean.HasSharpFeatures());
}

// Anything sharp, open or not flipped keeps the parent's own rows.
TEST(Sqrt3GrandparentRows, ApplyToClosedSmoothLevelsOnly)
{
  const subd::Sqrt3Scheme scheme;
  const subd::Level open = subdtest::BaseLevel(subdtest::House(true).Triangulated());
  EXPECT_FALSE(subd::Sqrt3RowsFromGrandparentApply(open, scheme.Split(open, subd::ChildTopology::Full)));
  const subdtest::TestMesh closed = subdtest::Bipyramid(5);
  subd::Level creased = subdtest::BaseLevel(closed);
  creased.EdgeSharpness[0] = 2.0f; // a crease: its edge is not flipped
  EXPECT_FALSE(subd::Sqrt3RowsFromGrandparentApply(creased, scheme.Split(creased, subd::ChildTopology::Full)));
  subd::Level pinned = subdtest::BaseLevel(closed);
  pinned.VertexSharpness[0] = subd::SharpnessInfinite; // a sharp vertex stays put in the child
  EXPECT_FALSE(subd::Sqrt3RowsFromGrandparentApply(pinned, scheme.Split(pinned, subd::ChildTopology::Full)));
  // A parent that is not the grandparent's split.
  const subd::Level smooth = subdtest::BaseLevel(closed);
  subd::Level other = scheme.Split(smooth, subd::ChildTopology::Full);
  EXPECT_TRUE(subd::Sqrt3RowsFromGrandparentApply(smooth, other));
  EXPECT_FALSE(subd::Sqrt3RowsFromGrandparentApply(other, other));
}

// Refine takes them for a faces-only finest level with the lean row modes, and frees the
// finest level's parent; the grandparent's own rows then read its fans, shared with its
// grandchild's: the hierarchy evaluates as the stored one does.
TEST(Sqrt3GrandparentRows, RefineWritesTheFinestRowsFromTheGrandparent)
{
  const subd::Sqrt3Scheme scheme;
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    for (subd::LevelRows mode : { subd::LevelRows::WrittenLean, subd::LevelRows::WrittenFromGrandparent,
           subd::LevelRows::Written })
    {
      for (int levels = 1; levels <= 3; ++levels)
      {
        SCOPED_TRACE(mesh.Name + " L" + std::to_string(levels));
        subd::Hierarchy stored, written;
        subd::Refine(scheme, subdtest::BaseLevel(mesh), levels, stored);
        subd::Refine(scheme, subdtest::BaseLevel(mesh), levels, written, nullptr, subd::ChildTopology::FacesOnly, mode);
        const bool fromGrandparent = subd::IsSqrt3RowSourceFromGrandparent(written.Stencils.back().GetSource());
        EXPECT_EQ(fromGrandparent, levels >= 2 && mode != subd::LevelRows::Written);
        if (levels >= 2) // the grandparent's own rows read its fans, which its grandchild's share
        {
          const auto fans = subd::Sqrt3RowFans(written.Stencils[levels - 2].GetSource());
          EXPECT_EQ(fans != nullptr, fromGrandparent);
          EXPECT_EQ(fans.use_count(), fromGrandparent ? 3 : 0);
        }
        EXPECT_EQ(written.Finest.Topology.GetFaceVertexArray(), stored.Finest.Topology.GetFaceVertexArray());
        std::vector<double> a(static_cast<size_t>(stored.GetNumFinestPoints()) * 3), b(a.size());
        stored.Evaluate(mesh.Points.data(), 3, a.data());
        written.Evaluate(mesh.Points.data(), 3, b.data());
        EXPECT_EQ(a, b);
      }
    }
  }
}

// The memory estimate counts the finest rows from the grandparent only for a closed manifold
// base (RefinementRequest::ClosedManifoldBase): it still covers what the refinement and its
// evaluation hold (the heap in use), and stays below the general path's.
#if defined(SUBD_HEAP_MEASURABLE)
TEST(Sqrt3GrandparentRows, MemoryEstimateCoversTheHeldMemory)
{
  const subd::Sqrt3Scheme scheme;
  const subdtest::TestMesh mesh = subdtest::Grid(40, 40, true, true).Triangulated(); // a torus
  const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  subd::RefinementRequest request;
  request.Base = { double(topology.GetNumFaces()), double(topology.GetNumEdges()), double(topology.GetNumVertices()),
    double(topology.GetNumFaceCorners()), double(topology.GetNumBoundaryEdges()) };
  request.Levels = 4;
  request.Rows = subd::LevelRows::WrittenLean;
  const double general = subd::EstimatePeakBytes(scheme, request);
  request.ClosedManifoldBase = true;
  const double predicted = subd::EstimatePeakBytes(scheme, request) - subd::EstimateLibraryBytes;
  EXPECT_LT(predicted + subd::EstimateLibraryBytes, general);
  const size_t before = subdtest::HeapInUse();
  double held = 0.0;
  {
    subd::Hierarchy hierarchy;
    subd::Refine(scheme, subd::MakeBaseLevel(topology, {}, subd::BoundaryRule::EdgeOnly), request.Levels, hierarchy,
      nullptr, request.Finest, request.Rows);
    EXPECT_TRUE(subd::IsSqrt3RowSourceFromGrandparent(hierarchy.Stencils.back().GetSource()));
    std::vector<double> finest(static_cast<size_t>(hierarchy.GetNumFinestPoints()) * 3);
    hierarchy.Evaluate(mesh.Points.data(), 3, finest.data());
    held = static_cast<double>(subdtest::HeapInUse() - before);
  }
  EXPECT_GT(held, 1.0e6); // a measurement, not noise
  EXPECT_LE(held, predicted);
}
#endif
