// Kernel unit tests: the last two levels of a smooth closed mesh made at once
// (SubDSmoothGrandchild.h): where the path is taken, that it gives the points, faces and face
// tags of the two levels made one by one, and the memory it spares.
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDSmoothGrandchild.h"
#include "SubDTestHeap.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using subd::Index;

namespace
{
std::vector<double> Evaluate(const subd::Hierarchy& h, const std::vector<double>& values, int components)
{
  std::vector<double> out(static_cast<size_t>(h.GetNumFinestPoints()) * components);
  h.Evaluate(values.data(), components, out.data());
  return out;
}

std::vector<double> Values(const subdtest::TestMesh& mesh, int components)
{
  std::vector<double> values(static_cast<size_t>(mesh.NumVertices()) * components);
  for (size_t i = 0; i < values.size(); ++i)
    values[i] = std::sin(0.7 * static_cast<double>(i)) + (i < mesh.Points.size() ? mesh.Points[i] : 0.0);
  return values;
}

// The mesh with two points that no face uses (as welded texture seams leave them).
subdtest::TestMesh WithIsolatedPoints(subdtest::TestMesh mesh)
{
  mesh.Points.insert(mesh.Points.end(), { 3.0, 2.0, 1.0, -1.0, 0.5, 2.0 });
  mesh.Name += "-isolated";
  return mesh;
}

subd::Level WithSharpEdge(const subdtest::TestMesh& mesh)
{
  const subd::MeshTopology topology = subd::MeshTopology::Build(mesh.NumVertices(), mesh.Offsets, mesh.Vertices);
  subd::BaseTags tags;
  tags.EdgeSharpness.assign(static_cast<size_t>(topology.GetNumEdges()), 0.0f);
  tags.EdgeSharpness[0] = 0.5f; // semi-sharp: smooth again two levels down, but not at the grandparent
  return subd::MakeBaseLevel(topology, tags, subd::BoundaryRule::EdgeOnly);
}
}

// Catmull-Clark on quads and Loop, on a closed manifold grandparent with nothing sharp and no
// hole: every row of the two levels below is smooth (or, at a point on no face, the point).
TEST(SmoothGrandchild, TakenWhereEveryRowBelowIsSmooth)
{
  const subd::CatmullClarkScheme catmullClark;
  const subd::LoopScheme loop;
  const subdtest::TestMesh cube = subdtest::Cube(), house = subdtest::House(false);
  const subdtest::TestMesh bipyramid = subdtest::Bipyramid(5);
  EXPECT_TRUE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(cube)));
  EXPECT_TRUE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(subdtest::Grid(6, 5, true, true))));
  EXPECT_TRUE(subd::HasSmoothGrandchild(loop, subdtest::BaseLevel(bipyramid)));
  EXPECT_TRUE(subd::HasSmoothGrandchild(loop, subdtest::BaseLevel(cube.Triangulated())));
  EXPECT_TRUE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(WithIsolatedPoints(cube))));
  EXPECT_TRUE(subd::HasSmoothGrandchild(loop, subdtest::BaseLevel(WithIsolatedPoints(bipyramid))));
  // The house has a triangle and a pentagon: not until its faces are quads.
  EXPECT_FALSE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(house)));
  EXPECT_TRUE(subd::HasSmoothGrandchild(
    catmullClark, catmullClark.Split(subdtest::BaseLevel(house), subd::ChildTopology::Full)));
  // A boundary, a sharp edge, a non-manifold edge, another scheme: not taken.
  EXPECT_FALSE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(subdtest::Grid(4, 3, false, false))));
  EXPECT_FALSE(subd::HasSmoothGrandchild(catmullClark, WithSharpEdge(cube)));
  EXPECT_FALSE(subd::HasSmoothGrandchild(loop, WithSharpEdge(bipyramid)));
  EXPECT_FALSE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(subdtest::NonManifold())));
  EXPECT_FALSE(subd::HasSmoothGrandchild(catmullClark, subdtest::BaseLevel(cube.Triangulated())));
  EXPECT_FALSE(subd::HasSmoothGrandchild(subd::ButterflyScheme(), subdtest::BaseLevel(bipyramid)));
  EXPECT_FALSE(subd::HasSmoothGrandchild(subd::BilinearScheme(), subdtest::BaseLevel(cube)));
  // A faces-only level has no edges to read.
  EXPECT_FALSE(subd::HasSmoothGrandchild(
    catmullClark, catmullClark.Split(subdtest::BaseLevel(cube), subd::ChildTopology::FacesOnly)));
}

// The rows written from the grandparent give bit for bit the points the stored rows give, for
// three components (the masks' sums) and five (rows written, then applied); the faces, holes
// and origins equal two splits'; and BuildLevelBetween swaps in the level between's own rows,
// which give the same points again.
TEST(SmoothGrandchild, SameLevelsAsTwoSplits)
{
  const subd::CatmullClarkScheme catmullClark;
  const subd::LoopScheme loop;
  struct Case
  {
    const subd::Scheme& Scheme;
    subdtest::TestMesh Mesh;
  };
  const Case cases[] = { { catmullClark, subdtest::Cube().Jitter(0.1) },
    { catmullClark, subdtest::House(false).Jitter(0.1) }, { catmullClark, subdtest::Grid(6, 5, true, true).Jitter(0.05) },
    { loop, subdtest::Bipyramid(7).Jitter(0.1) }, { loop, subdtest::Cube().Triangulated().Jitter(0.1) },
    { catmullClark, WithIsolatedPoints(subdtest::Cube().Jitter(0.1)) },
    { loop, WithIsolatedPoints(subdtest::Bipyramid(5).Jitter(0.1)) } };
  for (const Case& c : cases)
  {
    for (int levels = 2; levels <= 4; ++levels)
    {
      const std::string what = std::string(c.Scheme.GetName()) + " " + c.Mesh.Name + " L" + std::to_string(levels);
      subd::Hierarchy stored, written;
      subd::Refine(c.Scheme, subdtest::BaseLevel(c.Mesh), levels, stored);
      subd::Refine(c.Scheme, subdtest::BaseLevel(c.Mesh), levels, written, nullptr, subd::ChildTopology::FacesOnly,
        subd::LevelRows::Written);
      ASSERT_EQ(written.Stencils.size(), static_cast<size_t>(levels)) << what;
      for (int components : { 3, 5 })
      {
        const std::vector<double> values = Values(c.Mesh, components);
        EXPECT_EQ(Evaluate(written, values, components), Evaluate(stored, values, components)) << what;
      }
      EXPECT_EQ(written.Finest.Topology.GetFaceVertexArray(), stored.Finest.Topology.GetFaceVertexArray()) << what;
      EXPECT_EQ(written.Finest.Topology.GetFaceOffsetArray(), stored.Finest.Topology.GetFaceOffsetArray()) << what;
      EXPECT_EQ(written.Finest.Topology.GetNumVertices(), stored.Finest.Topology.GetNumVertices()) << what;
      EXPECT_EQ(subdtest::FaceTags(written.Finest), subdtest::FaceTags(stored.Finest)) << what;
      EXPECT_EQ(written.Finest.Depth, stored.Finest.Depth) << what;

      const bool madeAtOnce = c.Mesh.Name != "house" || levels > 2; // the house's base is not all quads
      EXPECT_EQ(subd::BuildLevelBetween(c.Scheme, written), madeAtOnce) << what;
      EXPECT_FALSE(subd::BuildLevelBetween(c.Scheme, written)) << what; // once
      const std::vector<double> values = Values(c.Mesh, 3);
      EXPECT_EQ(Evaluate(written, values, 3), Evaluate(stored, values, 3)) << what;
    }
  }
}

// What the path spares: building the level between afterwards takes more memory than the
// whole finest level's faces.
#if defined(SUBD_HEAP_MEASURABLE)
TEST(SmoothGrandchild, SparesTheLevelBetween)
{
  const subd::CatmullClarkScheme scheme;
  subd::Hierarchy h;
  subd::Refine(scheme, subdtest::BaseLevel(subdtest::Grid(12, 12, true, true)), 4, h, nullptr,
    subd::ChildTopology::FacesOnly, subd::LevelRows::Written);
  const double finestFaces = 4.0 * (h.Finest.Topology.GetNumFaceCorners() + h.Finest.Topology.GetNumFaces());
  const size_t before = subdtest::HeapInUse();
  ASSERT_TRUE(subd::BuildLevelBetween(scheme, h));
  EXPECT_GT(static_cast<double>(subdtest::HeapInUse() - before), finestFaces);
}
#endif
