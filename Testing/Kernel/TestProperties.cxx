// Catmull-Clark properties: on a regular grid the refined net is the knot-inserted net of the
// uniform bicubic B-spline (both nets evaluate to the same surface). Properties shared by every
// scheme (affine invariance, ...) are in TestAllSchemes.cxx.
#include "SubDBSplineNets.h"
#include "SubDQuadSplit.h"
#include "SubDRefiner.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <gtest/gtest.h>

using subd::Index;

namespace
{
std::vector<double> RefinePoints(const subdtest::TestMesh& mesh, const std::vector<double>& points,
  int levels, subd::BoundaryRule rule, subd::Hierarchy* out = nullptr)
{
  subd::CatmullClarkScheme scheme;
  subd::Hierarchy h;
  subd::Refine(scheme,
    subdtest::BaseLevel(mesh, rule),
    levels, h);
  std::vector<double> finest(static_cast<size_t>(h.GetNumFinestPoints()) * 3);
  h.Evaluate(points.data(), 3, finest.data());
  if (out)
    *out = std::move(h);
  return finest;
}
}

TEST(Properties, RegularGridReproducesBicubicBSpline)
{
  const int n = 10; // 10x10 quads, 11x11 control points at integer parameters
  const subdtest::TestMesh mesh = subdtest::WavyGrid(n, 0.7, 0.45, 0.03);


  // Parameters of the level-0 points, then propagated through the same split numbering
  // (vertex points keep theirs, edge and face points sit at the centres).
  std::vector<double> param = subdtest::GridParameters(n);
  const std::vector<double> level0Param = param;

  subd::CatmullClarkScheme scheme;
  subd::Level level = subdtest::BaseLevel(mesh);
  std::vector<double> points = mesh.Points;
  for (int l = 1; l <= 3; ++l)
  {
    const subd::StencilTable table = scheme.BuildStencils(level);
    std::vector<double> child = subdtest::ApplyToPoints(table, points);
    // Parameters of child points: the same stencils with bilinear weights would average, so
    // compute them directly from the split.
    const subd::MeshTopology& t = level.Topology;
    const subd::QuadSplitNumbering number{ t.GetNumFaces(), t.GetNumEdges() };
    std::vector<double> childParam(static_cast<size_t>(table.GetNumRows()) * 2);
    for (Index f = 0; f < t.GetNumFaces(); ++f)
    {
      double c[2] = { 0, 0 };
      for (Index v : t.GetFaceVertices(f))
        for (int k = 0; k < 2; ++k)
          c[k] += param[2 * v + k] / t.GetFaceSize(f);
      childParam[2 * number.FacePoint(f)] = c[0];
      childParam[2 * number.FacePoint(f) + 1] = c[1];
    }
    for (Index e = 0; e < t.GetNumEdges(); ++e)
      for (int k = 0; k < 2; ++k)
        childParam[2 * number.EdgePoint(e) + k] =
          0.5 * (param[2 * t.GetEdgeVertices(e)[0] + k] + param[2 * t.GetEdgeVertices(e)[1] + k]);
    for (Index v = 0; v < t.GetNumVertices(); ++v)
      for (int k = 0; k < 2; ++k)
        childParam[2 * number.VertexPoint(v) + k] = param[2 * v + k];
    level = scheme.Split(level, subd::ChildTopology::Full);
    points.swap(child);
    param.swap(childParam);

    // Away from the boundary (whose rules differ from the infinite grid's), both nets give
    // the same surface.
    const double worst = subdtest::MaxSurfaceDifference(
      subdtest::CubicBSpline, mesh.Points, level0Param, points, param, l, 3.0, n - 3.0);
    EXPECT_LT(worst, 1e-12) << "level " << l;
  }
}

TEST(Properties, EvaluateMatchesLevelByLevelAndComponentsAreIndependent)
{
  const subdtest::TestMesh mesh = subdtest::Star(5).Jitter(0.1);
  subd::Hierarchy h;
  const std::vector<double> finest = RefinePoints(mesh, mesh.Points, 3, subd::BoundaryRule::EdgeOnly, &h);
  // Evaluating x alone (1 component) gives the same x as evaluating xyz together.
  std::vector<double> x(static_cast<size_t>(mesh.NumVertices()));
  for (Index v = 0; v < mesh.NumVertices(); ++v)
    x[v] = mesh.Points[3 * v];
  std::vector<double> xFinest(static_cast<size_t>(h.GetNumFinestPoints()));
  h.Evaluate(x.data(), 1, xFinest.data());
  for (Index v = 0; v < h.GetNumFinestPoints(); ++v)
    EXPECT_EQ(xFinest[v], finest[3 * v]);
}
