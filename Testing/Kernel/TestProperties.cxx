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
  // Parameters of child points, from the split's numbering: vertex points keep theirs, edge
  // and face points sit at the centres.
  auto childParameters = [](const subd::MeshTopology& t, const std::vector<double>& param) {
    const subd::QuadSplitNumbering number{ t.GetNumFaces(), t.GetNumEdges() };
    std::vector<double> childParam(static_cast<size_t>(t.GetNumFaces() + t.GetNumEdges() + t.GetNumVertices()) * 2);
    for (Index f = 0; f < t.GetNumFaces(); ++f)
      for (Index v : t.GetFaceVertices(f))
        for (int k = 0; k < 2; ++k)
          childParam[2 * number.FacePoint(f) + k] += param[2 * v + k] / t.GetFaceSize(f);
    for (Index e = 0; e < t.GetNumEdges(); ++e)
      for (int k = 0; k < 2; ++k)
        childParam[2 * number.EdgePoint(e) + k] =
          0.5 * (param[2 * t.GetEdgeVertices(e)[0] + k] + param[2 * t.GetEdgeVertices(e)[1] + k]);
    for (Index v = 0; v < t.GetNumVertices(); ++v)
      for (int k = 0; k < 2; ++k)
        childParam[2 * number.VertexPoint(v) + k] = param[2 * v + k];
    return childParam;
  };
  const std::vector<double> differences = subdtest::GridBSplineDifferences(
    subd::CatmullClarkScheme(), mesh, n, 3, subdtest::CubicBSpline, childParameters);
  for (size_t l = 0; l < differences.size(); ++l)
    EXPECT_LT(differences[l], 1e-12) << "level " << l + 1;
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
