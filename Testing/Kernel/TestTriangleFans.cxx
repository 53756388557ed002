// The fans of a closed manifold triangle mesh (SubDTriangleFans.h), against the topology's
// own lists around the vertices.
#include "SubDMeshTopology.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"
#include "SubDTestParallel.h"
#include "SubDTriangleFans.h"

#include <gtest/gtest.h>

#include <vector>

using subd::Index;
using subd::TriangleFans;

namespace
{
std::shared_ptr<const TriangleFans> FansOf(const subd::MeshTopology& topology, const subd::ParallelFor& parallelFor)
{
  return TriangleFans::Build(
    topology.GetFaceVertexArray().data(), topology.GetNumFaces(), topology.GetNumVertices(), parallelFor);
}

bool ClosedManifold(const subd::MeshTopology& topology)
{
  return topology.GetNumBoundaryEdges() == 0 && topology.GetNumNonManifoldEdges() == 0 &&
    topology.GetNumNonManifoldVertices() == 0;
}
}

// Each vertex's neighbours and triangles, walked around its fan and sorted, are its ring and
// its faces; each corner's twin runs back along its edge, and is paired with it. On the
// closed triangle fixtures, their sqrt(3) children (valences 6 and doubled) and an apex of
// valence 70 (past the walk's room on the stack), serially and on threads.
TEST(TriangleFans, GiveEachVertexItsNeighboursAndTrianglesInOrder)
{
  const subd::Sqrt3Scheme scheme;
  std::vector<subdtest::TestMesh> meshes = subdtest::TriangleMeshes();
  meshes.push_back(subdtest::Bipyramid(70));
  int checked = 0;
  for (const subdtest::TestMesh& mesh : meshes)
  {
    subd::Level level = subdtest::BaseLevel(mesh);
    if (!ClosedManifold(level.Topology))
    {
      continue;
    }
    for (int depth = 0; depth < 2; ++depth, level = scheme.Split(level, subd::ChildTopology::Full))
    {
      SCOPED_TRACE(mesh.Name + " depth " + std::to_string(depth));
      const subd::MeshTopology& topology = level.Topology;
      const Index* corners = topology.GetFaceVertexArray().data();
      for (const subd::ParallelFor& parallelFor :
        { subd::ParallelFor(subd::SerialFor), subd::ParallelFor(subdtest::ThreeThreadFor) })
      {
        const std::shared_ptr<const TriangleFans> fans = FansOf(topology, parallelFor);
        ASSERT_NE(fans, nullptr);
        EXPECT_EQ(fans->GetMaxValence(), topology.GetMaxValence());
        std::vector<Index> out(static_cast<size_t>(fans->GetMaxValence()));
        for (Index v = 0; v < topology.GetNumVertices(); ++v)
        {
          std::vector<Index> ring;
          topology.ForEachRingVertex(v, [&ring](Index w) { ring.push_back(w); });
          const Index n = fans->SortedNeighbours(corners, v, out.data());
          EXPECT_EQ(std::vector<Index>(out.begin(), out.begin() + n), ring);
          const subd::IndexSpan faces = topology.GetVertexFaces(v);
          const Index m = fans->SortedFaces(v, out.data());
          EXPECT_EQ(std::vector<Index>(out.begin(), out.begin() + m), std::vector<Index>(faces.begin(), faces.end()));
        }
        for (Index h = 0; h < topology.GetNumFaceCorners(); ++h)
        {
          const Index t = fans->GetTwin(h);
          EXPECT_EQ(corners[t], corners[TriangleFans::NextCorner(h)]);
          EXPECT_EQ(corners[TriangleFans::NextCorner(t)], corners[h]);
          EXPECT_EQ(fans->GetTwin(t), h);
        }
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
}

// Anything but a closed manifold without unused vertices has no fans: an open mesh, a
// non-manifold edge, two closed fans at one vertex (a pinch, without any open or
// non-manifold edge), a vertex without faces, a triangle turned the other way.
TEST(TriangleFans, NoneWhereAVertexHasNoSingleClosedFan)
{
  for (const subdtest::TestMesh& mesh :
    { subdtest::House(true).Triangulated(), subdtest::NonManifold().Triangulated(),
      subdtest::PinchedCubes().Triangulated() })
  {
    SCOPED_TRACE(mesh.Name);
    const subd::MeshTopology topology = subdtest::BaseLevel(mesh).Topology;
    EXPECT_EQ(FansOf(topology, subd::SerialFor), nullptr);
    EXPECT_EQ(FansOf(topology, subdtest::ThreeThreadFor), nullptr);
  }
  const subdtest::TestMesh closed = subdtest::Bipyramid(5);
  ASSERT_NE(TriangleFans::Build(closed.Vertices.data(), closed.NumFaces(), closed.NumVertices()), nullptr);
  EXPECT_EQ(TriangleFans::Build(closed.Vertices.data(), closed.NumFaces(), closed.NumVertices() + 1), nullptr);
  std::vector<Index> turned = closed.Vertices;
  std::swap(turned[0], turned[1]);
  EXPECT_EQ(TriangleFans::Build(turned.data(), closed.NumFaces(), closed.NumVertices()), nullptr);
}
