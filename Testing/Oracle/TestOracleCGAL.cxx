// Oracle test against CGAL 5.5's Subdivision_method_3 (Debian's libcgal-dev), an independent
// implementation: Doo-Sabin on closed meshes (CGAL has no Doo-Sabin boundary rule), and
// sqrt(3) on closed and open meshes (both follow Kobbelt's boundary rule).
//
// CGAL numbers its points its own way, so each CGAL point is matched to the nearest of ours
// (it must be within 1e-9 of the bounding-box diagonal, and the match must be one-to-one),
// and every CGAL face, mapped through that matching, must be one of our faces with the same
// cyclic order.
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDOracleSupport.h"
#include "SubDTestMeshes.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

namespace
{
using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using subd::Index;

Mesh ToCgal(const subdtest::TestMesh& m)
{
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  for (Index v = 0; v < m.NumVertices(); ++v)
    vertices.push_back(mesh.add_vertex(Kernel::Point_3(m.Points[3 * v], m.Points[3 * v + 1], m.Points[3 * v + 2])));
  for (Index f = 0; f < m.NumFaces(); ++f)
  {
    std::vector<Mesh::Vertex_index> face;
    for (Index k = m.Offsets[f]; k < m.Offsets[f + 1]; ++k)
      face.push_back(vertices[m.Vertices[k]]);
    EXPECT_NE(mesh.add_face(face), Mesh::null_face()) << m.Name << " face " << f;
  }
  return mesh;
}

enum class Method
{
  DooSabin,
  Sqrt3
};

void CompareWithCgal(Method method, const subdtest::TestMesh& input, int levels)
{
  // Ours.
  std::unique_ptr<subd::Scheme> schemePointer;
  if (method == Method::DooSabin)
    schemePointer = std::make_unique<subd::DooSabinScheme>();
  else
    schemePointer = std::make_unique<subd::Sqrt3Scheme>();
  const subd::Scheme& scheme = *schemePointer;
  subd::Hierarchy h;
  const std::vector<double> ours = subdtest::RefineFixture(scheme, input, levels, h);
  const subd::MeshTopology& topo = h.Finest.Topology;

  // CGAL's.
  Mesh mesh = ToCgal(input);
  if (method == Method::DooSabin)
    CGAL::Subdivision_method_3::DooSabin_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  else
    CGAL::Subdivision_method_3::Sqrt3_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
  ASSERT_EQ(static_cast<Index>(mesh.number_of_vertices()), h.GetNumFinestPoints()) << input.Name;
  ASSERT_EQ(static_cast<Index>(mesh.number_of_faces()), topo.GetNumFaces()) << input.Name;

  const double tolerance = 1e-9 * subdtest::Diagonal(input.Points);

  std::map<Mesh::Vertex_index, Index> match;
  std::vector<int> taken(static_cast<size_t>(h.GetNumFinestPoints()), 0);
  double worst = 0;
  for (Mesh::Vertex_index v : mesh.vertices())
  {
    const double p[3] = { mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z() };
    double bestDistance = 0;
    const Index best = subdtest::NearestPoint(ours, p, bestDistance);
    worst = std::max(worst, bestDistance);
    match[v] = best;
    ++taken[best];
  }
  EXPECT_LE(worst, tolerance) << input.Name << " level " << levels;
  EXPECT_EQ(std::count(taken.begin(), taken.end(), 1), h.GetNumFinestPoints()) << "one-to-one";
  std::printf("%s %s level %d: largest difference to CGAL %.3g of the diagonal\n", scheme.GetName(),
    input.Name.c_str(), levels, worst / (tolerance * 1e9));

  std::map<std::vector<Index>, int> ourFaces;
  for (Index f = 0; f < topo.GetNumFaces(); ++f)
    ++ourFaces[subdtest::Canonical(std::vector<Index>(topo.GetFaceVertices(f).begin(), topo.GetFaceVertices(f).end()))];
  for (Mesh::Face_index f : mesh.faces())
  {
    std::vector<Index> face;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      face.push_back(match[v]);
    EXPECT_EQ(ourFaces.count(subdtest::Canonical(face)), 1u) << input.Name << ": a CGAL face is not ours";
  }
}
}

TEST(OracleCGAL, DooSabinClosedMeshesLevels1To3)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::Cube().Jitter(0.1), subdtest::Grid(6, 5, true, true).Jitter(0.05),
    subdtest::House(false).Jitter(0.1) };
  for (int n = 3; n <= 8; ++n)
    meshes.push_back(subdtest::Star(n).Jitter(0.1));
  meshes.push_back(subdtest::Bipyramid(5).Jitter(0.1));
  for (const subdtest::TestMesh& mesh : meshes)
    for (int levels = 1; levels <= 3; ++levels)
      CompareWithCgal(Method::DooSabin, mesh, levels);
}

TEST(OracleCGAL, Sqrt3ClosedTriangleMeshesLevels1To3)
{
  std::vector<subdtest::TestMesh> meshes{ subdtest::Cube().Jitter(0.1).Triangulated(),
    subdtest::Grid(6, 5, true, true).Jitter(0.05).Triangulated(), subdtest::House(false).Jitter(0.1).Triangulated() };
  for (int n : { 3, 4, 5, 7, 8, 12 })
    meshes.push_back(subdtest::Bipyramid(n).Jitter(0.1));
  for (const subdtest::TestMesh& mesh : meshes)
    for (int levels = 1; levels <= 3; ++levels)
      CompareWithCgal(Method::Sqrt3, mesh, levels);
}

// CGAL refines the border every second step, as Kobbelt's paper does: open meshes must agree
// too, through two boundary refinements (level 4).
TEST(OracleCGAL, Sqrt3OpenTriangleMeshesLevels1To4)
{
  const std::vector<subdtest::TestMesh> meshes{ subdtest::Grid(4, 3, false, false).Jitter(0.1).Triangulated(),
    subdtest::House(true).Jitter(0.1).Triangulated() };
  for (const subdtest::TestMesh& mesh : meshes)
    for (int levels = 1; levels <= 4; ++levels)
      CompareWithCgal(Method::Sqrt3, mesh, levels);
}
