// Kernel tests of the limit masks of sqrt(3), Doo-Sabin and the midpoint scheme
// (SubDSqrt3Limit.h, SubDDualLimit.h): each limit point is checked against the subdivision
// process itself, never against the formula that made it.
//  - sqrt(3) keeps its vertices: the limit of a vertex equals the limit of its child one
//    step down (limit(P) == limit(subdivide(P))), for either parity of the step, on closed,
//    open and non-manifold meshes; and many steps bring the vertex towards it.
//  - The dual schemes turn a vertex into a face whose descendants (the same face index at
//    every further level: F-faces come first) shrink towards the limit point, and keep it as
//    their centroid.
//  - Tangent planes: the refined neighbourhood's own plane approaches the mask's plane.
#include "SubDDualLimit.h"
#include "SubDDualSplit.h"
#include "SubDMidpointRules.h"
#include "SubDRingTangents.h"
#include "SubDScheme.h"
#include "SubDSqrt3Limit.h"
#include "SubDSqrt3Rules.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using subd::Index;

namespace
{
// A level and its points, refined one step at a time.
struct Stage
{
  subd::Level Level;
  std::vector<double> Points;
};

Stage Step(const subd::Scheme& scheme, const Stage& parent)
{
  subd::LevelRefinement r = scheme.RefineLevel(parent.Level, subd::ChildTopology::Full);
  Stage child;
  child.Points = subdtest::ApplyToPoints(r.Stencils, parent.Points);
  child.Level = std::move(r.Child);
  return child;
}

Stage Start(const subdtest::TestMesh& mesh)
{
  return { subdtest::BaseLevel(mesh), mesh.Points };
}

double Distance(const double* a, const double* b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

void Cross(const double* a, const double* b, double* out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// Angle between the unit normal of two tangent rows (t1 x t2) and a direction.
double AngleTo(const double* t, const double* direction)
{
  double n[3];
  Cross(t, t + 3, n);
  const double dot = n[0] * direction[0] + n[1] * direction[1] + n[2] * direction[2];
  const double norms = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) *
    std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  return std::acos(std::max(-1.0, std::min(1.0, dot / norms)));
}

// Newell's normal of a polygon of points.
void PolygonNormal(const std::vector<const double*>& corners, double* n)
{
  n[0] = n[1] = n[2] = 0.0;
  for (size_t i = 0; i < corners.size(); ++i)
  {
    const double* a = corners[i];
    const double* b = corners[(i + 1) % corners.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
}

// Follows every vertex of `mesh` down `steps` sqrt(3) steps (an old vertex v is child
// Sqrt3FirstVertexPoint + v) and returns, per step, the worst of measure(stage, vertex,
// its descendant) over the vertices.
std::vector<double> FollowSqrt3Vertices(const subdtest::TestMesh& mesh, int steps,
  const std::function<double(const Stage&, Index, Index)>& measure)
{
  const subd::Sqrt3Scheme scheme;
  Stage stage = Start(mesh);
  std::vector<Index> descendant(static_cast<size_t>(mesh.NumVertices()));
  for (Index v = 0; v < mesh.NumVertices(); ++v)
    descendant[v] = v;
  std::vector<double> worst;
  for (int step = 1; step <= steps; ++step)
  {
    const Index first = subd::Sqrt3FirstVertexPoint(stage.Level);
    stage = Step(scheme, stage);
    worst.push_back(0.0);
    for (Index v = 0; v < mesh.NumVertices(); ++v)
    {
      descendant[v] += first;
      worst.back() = std::max(worst.back(), measure(stage, v, descendant[v]));
    }
  }
  return worst;
}

bool IsManifold(const subdtest::TestMesh& mesh)
{
  return mesh.Name.find("non-manifold") == std::string::npos && mesh.Name.find("pinched") == std::string::npos;
}
}

TEST(Sqrt3LimitMasks, TheLimitOfAVertexIsTheLimitOfItsChild)
{
  const subd::Sqrt3Scheme scheme;
  for (const subdtest::TestMesh& mesh : subdtest::TriangleMeshes())
  {
    Stage stage = Start(mesh);
    for (int level = 0; level < 3; ++level) // both parities of the next step
    {
      subd::StencilTable here, below;
      std::string error;
      ASSERT_TRUE(subd::BuildSqrt3LimitStencils(stage.Level, false, here, error)) << mesh.Name << ": " << error;
      const Index first = subd::Sqrt3FirstVertexPoint(stage.Level);
      Stage next = Step(scheme, stage);
      ASSERT_TRUE(subd::BuildSqrt3LimitStencils(next.Level, false, below, error)) << mesh.Name << ": " << error;
      const std::vector<double> limitHere = subdtest::ApplyToPoints(here, stage.Points);
      const std::vector<double> limitBelow = subdtest::ApplyToPoints(below, next.Points);
      for (Index v = 0; v < stage.Level.Topology.GetNumVertices(); ++v)
      {
        EXPECT_NEAR(here.GetRowSum(v), 1.0, 1e-12);
        EXPECT_LT(Distance(&limitHere[3 * v], &limitBelow[3 * (first + v)]), 1e-12)
          << mesh.Name << " level " << level << " vertex " << v;
      }
      stage = std::move(next);
    }
  }
}

TEST(Sqrt3LimitMasks, VerticesApproachTheirLimitPoints)
{
  for (const subdtest::TestMesh& mesh : { subdtest::Bipyramid(3).Jitter(0.1), subdtest::Bipyramid(8).Jitter(0.1),
         subdtest::Grid(3, 2, false, false).Triangulated().Jitter(0.1) })
  {
    subd::StencilTable masks;
    std::string error;
    ASSERT_TRUE(subd::BuildSqrt3LimitStencils(Start(mesh).Level, false, masks, error)) << error;
    const std::vector<double> limit = subdtest::ApplyToPoints(masks, mesh.Points);
    const std::vector<double> errors = FollowSqrt3Vertices(mesh, 6, [&](const Stage& stage, Index v, Index d) {
      return Distance(&limit[3 * v], &stage.Points[3 * d]);
    });
    // Boundaries are refined every second step: compare steps two apart.
    for (size_t k = 2; k < errors.size(); ++k)
    {
      EXPECT_LT(errors[k], 0.6 * errors[k - 2]) << mesh.Name << " step " << k + 1;
    }
    EXPECT_LT(errors.back(), 2e-3) << mesh.Name;
  }
}

// The plane of a vertex's ring of triangles many steps down approaches the mask's plane.
TEST(Sqrt3LimitMasks, TangentPlanesAreThoseOfTheRefinedRings)
{
  for (const subdtest::TestMesh& mesh : { subdtest::Bipyramid(3).Jitter(0.1), subdtest::Bipyramid(8).Jitter(0.1),
         subdtest::Star(5).Triangulated().Jitter(0.1) })
  {
    subd::StencilTable tangents;
    std::string error;
    ASSERT_TRUE(subd::BuildSqrt3LimitStencils(Start(mesh).Level, true, tangents, error)) << error;
    const std::vector<double> t = subdtest::ApplyToPoints(tangents, mesh.Points);
    const std::vector<double> errors = FollowSqrt3Vertices(mesh, 6, [&](const Stage& stage, Index v, Index d) {
      std::vector<Index> faces, corners, ring;
      EXPECT_TRUE(subd::GetOrderedRing(stage.Level.Topology, d, faces, corners, ring));
      std::vector<const double*> polygon;
      for (Index p : ring)
        polygon.push_back(&stage.Points[3 * p]);
      double n[3];
      PolygonNormal(polygon, n);
      return AngleTo(&t[6 * v], n);
    });
    EXPECT_LT(errors.back(), 0.3 * errors[1] + 1e-7) << mesh.Name; // valence 3: exact at once
    EXPECT_LT(errors.back(), 0.02) << mesh.Name;
  }
}

// Doo-Sabin and midpoint: vertex v's V-face, one level down, is a face whose descendants
// keep its index; they shrink onto the limit point, which stays their centroid, and their
// planes turn to the mask's tangent plane.
TEST(DualLimitMasks, VFaceDescendantsShrinkOntoTheLimitPoint)
{
  const subd::DooSabinScheme dooSabin;
  const subd::MidpointScheme midpoint;
  for (const subd::Scheme* scheme : { static_cast<const subd::Scheme*>(&dooSabin), static_cast<const subd::Scheme*>(&midpoint) })
  {
    const bool isDooSabin = scheme == &dooSabin;
    for (const subdtest::TestMesh& mesh : subdtest::StandardMeshes())
    {
      if (!IsManifold(mesh))
        continue;
      Stage stage = Start(mesh);
      subd::StencilTable masks, tangents;
      std::string error;
      ASSERT_TRUE(scheme->BuildLimitStencils(stage.Level, masks, error)) << mesh.Name << ": " << error;
      const std::vector<double> limit = subdtest::ApplyToPoints(masks, stage.Points);
      const bool closed = stage.Level.Topology.GetNumBoundaryEdges() == 0;
      if (closed)
      {
        ASSERT_TRUE(scheme->BuildLimitTangentStencils(stage.Level, tangents, error)) << mesh.Name << ": " << error;
      }
      const std::vector<double> t = closed ? subdtest::ApplyToPoints(tangents, stage.Points) : std::vector<double>();
      // The V-face of each smooth vertex: the child face holding its corner points.
      const subd::MeshTopology& topo = stage.Level.Topology;
      const subd::DualPoints dual = subd::NumberDualPoints(stage.Level);
      Stage next = Step(*scheme, stage);
      std::vector<std::pair<Index, Index>> vertexFaces; // (vertex, face one level down)
      for (Index v = 0; v < topo.GetNumVertices(); ++v)
      {
        std::vector<Index> faces, corners, ring;
        if (!subd::GetOrderedRing(topo, v, faces, corners, ring))
          continue; // boundary vertices: no V-face
        const Index corner = isDooSabin ? dual.PointOf(topo.GetFaceOffset(faces[0]) + corners[0])
                                        : topo.FindEdge(v, ring[0]); // midpoint child e: edge e
        for (Index g : next.Level.Topology.GetVertexFaces(corner))
        {
          const subd::IndexSpan gv = next.Level.Topology.GetFaceVertices(g);
          if (gv.size() == static_cast<Index>(ring.size()) && g >= next.Level.Topology.GetNumFaces() - topo.GetNumVertices())
          {
            bool all = true; // every corner is a child of v's corners
            for (Index j = 0; j < gv.size(); ++j)
            {
              const Index expected = isDooSabin ? dual.PointOf(topo.GetFaceOffset(faces[j]) + corners[j])
                                                : topo.FindEdge(v, ring[j]);
              all = all && std::find(gv.begin(), gv.end(), expected) != gv.end();
            }
            if (all)
              vertexFaces.emplace_back(v, g);
          }
        }
      }
      ASSERT_FALSE(vertexFaces.empty()) << mesh.Name;
      std::vector<double> firstSize(vertexFaces.size(), 0.0), lastSize(vertexFaces.size(), 0.0);
      const int steps = 7;
      std::vector<double> angles;
      for (int step = 1; step <= steps; ++step)
      {
        double worstAngle = 0.0;
        for (size_t k = 0; k < vertexFaces.size(); ++k)
        {
          const Index v = vertexFaces[k].first, g = vertexFaces[k].second;
          const subd::IndexSpan gv = next.Level.Topology.GetFaceVertices(g);
          double centroid[3] = { 0, 0, 0 }, size = 0.0;
          std::vector<const double*> polygon;
          for (Index p : gv)
          {
            polygon.push_back(&next.Points[3 * p]);
            for (int c = 0; c < 3; ++c)
              centroid[c] += next.Points[3 * p + c] / gv.size();
            size = std::max(size, Distance(&next.Points[3 * p], &limit[3 * v]));
          }
          EXPECT_LT(Distance(centroid, &limit[3 * v]), 1e-12) << scheme->GetName() << " " << mesh.Name << " vertex " << v;
          (step == 1 ? firstSize : lastSize)[k] = size;
          if (closed)
          {
            double n[3];
            PolygonNormal(polygon, n);
            worstAngle = std::max(worstAngle, AngleTo(&t[6 * v], n));
          }
        }
        angles.push_back(worstAngle);
        if (step < steps)
          next = Step(*scheme, next);
      }
      for (size_t k = 0; k < vertexFaces.size(); ++k)
      {
        // Doo-Sabin shrinks a face by 1/2 per step, the midpoint polygon by cos(pi/n), in the
        // norm of its Fourier modes; the largest corner distance follows up to a constant.
        const double rate = isDooSabin ? 0.5 : std::cos(3.14159265358979323846 / next.Level.Topology.GetFaceSize(vertexFaces[k].second));
        EXPECT_LT(lastSize[k], 1.5 * std::pow(rate, steps - 1) * firstSize[k] + 1e-13)
          << scheme->GetName() << " " << mesh.Name << " vertex " << vertexFaces[k].first;
      }
      if (closed)
      {
        EXPECT_LT(angles.back(), 1e-6 + 0.5 * angles[1]) << scheme->GetName() << " " << mesh.Name;
      }
    }
  }
}

TEST(LimitMasks, DartsAndBoundaryTangentsAreNamedErrors)
{
  // An open grid: boundary vertices have limit points but no tangent masks.
  subd::Level open = subdtest::BaseLevel(subdtest::Grid(3, 3, false, false));
  subd::StencilTable table;
  std::string error;
  for (const subd::Scheme* scheme :
    std::initializer_list<const subd::Scheme*>{ new subd::DooSabinScheme, new subd::MidpointScheme })
  {
    EXPECT_TRUE(scheme->BuildLimitStencils(open, table, error)) << error;
    EXPECT_FALSE(scheme->BuildLimitTangentStencils(open, table, error));
    EXPECT_NE(error.find("on the boundary"), std::string::npos) << error;
    delete scheme;
  }
  // A dart: one sharp edge ending inside a closed mesh.
  subd::Level cube = subdtest::BaseLevel(subdtest::Cube().Triangulated());
  cube.EdgeSharpness[0] = subd::SharpnessInfinite;
  subd::Sqrt3Scheme sqrt3;
  EXPECT_FALSE(sqrt3.BuildLimitStencils(cube, table, error));
  EXPECT_NE(error.find("dart"), std::string::npos) << error;
}
