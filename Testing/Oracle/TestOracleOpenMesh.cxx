// Oracle test against OpenMesh 9 (Debian's libopenmesh-dev), an independent implementation:
// the modified butterfly (tension 0) on closed and open triangle meshes, sqrt(3) and the
// midpoint scheme on closed ones, levels 1..3.
//
// OpenMesh numbers its points its own way: each OpenMesh point is matched to the nearest of
// ours (within 1e-9 of the bounding-box diagonal, one-to-one) and every OpenMesh face,
// mapped through the matching, must be one of ours with the same cyclic order.
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDOracleSupport.h"
#include "SubDTestMeshes.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/MidpointT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

namespace
{
using subd::Index;

struct DoubleTraits : OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

template <typename OMMesh>
OMMesh ToOpenMesh(const subdtest::TestMesh& m)
{
  OMMesh mesh;
  std::vector<typename OMMesh::VertexHandle> vertices;
  for (Index v = 0; v < m.NumVertices(); ++v)
    vertices.push_back(mesh.add_vertex(typename OMMesh::Point(m.Points[3 * v], m.Points[3 * v + 1], m.Points[3 * v + 2])));
  for (Index f = 0; f < m.NumFaces(); ++f)
  {
    std::vector<typename OMMesh::VertexHandle> face;
    for (Index k = m.Offsets[f]; k < m.Offsets[f + 1]; ++k)
      face.push_back(vertices[m.Vertices[k]]);
    mesh.add_face(face);
  }
  return mesh;
}

// Compares our refinement of `input` with OpenMesh's `mesh` (already refined).
template <typename OMMesh>
void Compare(const char* scheme, const subdtest::TestMesh& input, int levels, const subd::Hierarchy& h,
  const std::vector<double>& ours, OMMesh& mesh)
{
  const subd::MeshTopology& topo = h.Finest.Topology;
  ASSERT_EQ(static_cast<Index>(mesh.n_vertices()), h.GetNumFinestPoints()) << input.Name;
  ASSERT_EQ(static_cast<Index>(mesh.n_faces()), topo.GetNumFaces()) << input.Name;
  const double diagonal = subdtest::Diagonal(input.Points);
  std::vector<Index> match(mesh.n_vertices());
  std::vector<int> taken(static_cast<size_t>(h.GetNumFinestPoints()), 0);
  double worst = 0;
  for (const auto& v : mesh.vertices())
  {
    const double p[3] = { mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2] };
    double bestDistance = 0;
    const Index best = subdtest::NearestPoint(ours, p, bestDistance);
    worst = std::max(worst, bestDistance);
    match[v.idx()] = best;
    ++taken[best];
  }
  EXPECT_LE(worst, 1e-9 * diagonal) << scheme << " " << input.Name << " level " << levels;
  EXPECT_EQ(std::count(taken.begin(), taken.end(), 1), h.GetNumFinestPoints()) << "one-to-one";
  std::printf("%s %s level %d: largest difference to OpenMesh %.3g of the diagonal\n", scheme,
    input.Name.c_str(), levels, worst / diagonal);
  std::map<std::vector<Index>, int> ourFaces;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
    ++ourFaces[subdtest::Canonical(std::vector<Index>(topo.GetFaceVertices(f).begin(), topo.GetFaceVertices(f).end()))];
  for (const auto& f : mesh.faces())
  {
    std::vector<Index> face;
    for (const auto& v : mesh.fv_range(f))
      face.push_back(match[v.idx()]);
    EXPECT_EQ(ourFaces.count(subdtest::Canonical(face)), 1u) << input.Name << ": an OpenMesh face is not ours";
  }
}

// The manifold triangle fixtures (OpenMesh cannot hold the non-manifold ones), closed or not.
std::vector<subdtest::TestMesh> ManifoldTriangleMeshes(bool closedOnly)
{
  std::vector<subdtest::TestMesh> meshes;
  for (const subdtest::TestMesh& m : subdtest::TriangleMeshes())
  {
    const subd::MeshTopology t = subd::MeshTopology::Build(m.NumVertices(), m.Offsets, m.Vertices);
    if ((!closedOnly || t.GetNumBoundaryEdges() == 0) && t.GetNumNonManifoldEdges() == 0 &&
      t.GetNumNonManifoldVertices() == 0)
      meshes.push_back(m);
  }
  return meshes;
}
}

// Refines `input` with our `scheme` and with OpenMesh's subdivider, and compares.
template <typename OMMesh, typename Subdivider>
void RefineAndCompare(const subd::Scheme& scheme, const subdtest::TestMesh& input, int levels)
{
  subd::Hierarchy h;
  const std::vector<double> ours = subdtest::RefineFixture(scheme, input, levels, h);
  OMMesh mesh = ToOpenMesh<OMMesh>(input);
  Subdivider subdivider;
  subdivider.attach(mesh);
  subdivider(static_cast<size_t>(levels));
  subdivider.detach();
  Compare(scheme.GetName(), input, levels, h, ours, mesh);
}

// Closed meshes, as the issue asks, and open ones too: OpenMesh's boundary treatment (4-point
// boundary edges, reflected wings) is the one SubD documents, so they must agree there as well.
TEST(OracleOpenMesh, ModifiedButterflyLevels1To3)
{
  const std::vector<subdtest::TestMesh> meshes = ManifoldTriangleMeshes(false);
  ASSERT_GE(meshes.size(), ManifoldTriangleMeshes(true).size() + 2);
  for (const subdtest::TestMesh& input : meshes)
    for (int levels = 1; levels <= 3; ++levels)
      RefineAndCompare<TriMesh, OpenMesh::Subdivider::Uniform::ModifiedButterflyT<TriMesh>>(
        subd::ButterflyScheme(0.0), input, levels);
}

TEST(OracleOpenMesh, Sqrt3ClosedMeshesLevels1To3)
{
  for (const subdtest::TestMesh& input : ManifoldTriangleMeshes(true))
    for (int levels = 1; levels <= 3; ++levels)
      RefineAndCompare<TriMesh, OpenMesh::Subdivider::Uniform::Sqrt3T<TriMesh>>(subd::Sqrt3Scheme(), input, levels);
}

TEST(OracleOpenMesh, MidpointClosedMeshesLevels1To3)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::Cube().Jitter(0.1), subdtest::Grid(6, 5, true, true).Jitter(0.05),
    subdtest::House(false).Jitter(0.1) };
  for (int n = 3; n <= 8; ++n)
    meshes.push_back(subdtest::Star(n).Jitter(0.1));
  for (const subdtest::TestMesh& input : meshes)
    for (int levels = 1; levels <= 3; ++levels)
      RefineAndCompare<PolyMesh, OpenMesh::Subdivider::Uniform::MidpointT<PolyMesh>>(subd::MidpointScheme(), input, levels);
}
