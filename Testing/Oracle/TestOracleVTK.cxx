// Oracle test against VTK's own triangle subdivision filters (Debian's libvtk9):
// vtkLinearSubdivisionFilter, vtkButterflySubdivisionFilter (tension 0, agrees fully) and
// vtkLoopSubdivisionFilter, on closed triangle meshes.
//
// VTK numbers its output points differently, so the outputs are compared as point sets
// (each of ours must have a point of VTK's within 1e-9 of the bounding-box diagonal, and the
// counts must be equal) and by face count.
//
// Where the rules disagree: VTK's Loop filter uses Warren's simplified weight beta = 3/(8n)
// for n > 3, not Loop's beta(n) that SubD and OpenSubdiv use, so only valence-3 and valence-6
// vertices agree with it (both formulas give 3/16 and 1/16 there); the Loop comparison is
// therefore restricted to edge points, which both compute with 3/8-3/8-1/8-1/8.
//
// VTK's filters write single-precision points whatever the input's precision, so the
// tolerance follows the type of VTK's output points: 1e-9 of the diagonal for double,
// 1e-6 (a few float ulps) for float.
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"

#include "SubDTestMeshes.h"

#include "vtkCellArray.h"
#include "vtkButterflySubdivisionFilter.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkKdTreePointLocator.h"
#include "vtkMath.h"

#include <algorithm>
#include <cmath>

#include "SubDFilterTestSupport.h"

#include <gtest/gtest.h>

namespace
{
using subdtest::ToPolyData;

// Largest distance from a point of `ours` (among `which`, or all) to the nearest of `theirs`.
double WorstDistance(vtkPolyData* ours, vtkPolyData* theirs, vtkIdType first = 0, vtkIdType last = -1)
{
  vtkNew<vtkKdTreePointLocator> locator;
  locator->SetDataSet(theirs);
  locator->BuildLocator();
  double worst = 0;
  if (last < 0)
    last = ours->GetNumberOfPoints();
  for (vtkIdType i = first; i < last; ++i)
  {
    double p[3], q[3];
    ours->GetPoint(i, p);
    theirs->GetPoint(locator->FindClosestPoint(p), q);
    worst = std::max(worst, std::sqrt(vtkMath::Distance2BetweenPoints(p, q)));
  }
  return worst;
}

double Tolerance(vtkPolyData* vtkOutput, vtkPolyData* input)
{
  const bool single = vtkOutput->GetPoints()->GetDataType() == VTK_FLOAT;
  return (single ? 1e-6 : 1e-9) * input->GetLength();
}

std::vector<subdtest::TestMesh> ClosedTriangleMeshes()
{
  std::vector<subdtest::TestMesh> meshes;
  meshes.push_back(subdtest::Cube().Jitter(0.1).Triangulated());
  meshes.push_back(subdtest::Grid(6, 5, true, true).Jitter(0.05).Triangulated());
  meshes.push_back(subdtest::House(false).Jitter(0.1).Triangulated());
  for (int n : { 3, 5, 8 })
    meshes.push_back(subdtest::Bipyramid(n).Jitter(0.1));
  return meshes;
}
}

TEST(OracleVTK, LinearTrianglesMatchVtkLinearSubdivision)
{
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    vtkSmartPointer<vtkPolyData> input = ToPolyData(mesh);
    for (int levels = 1; levels <= 3; ++levels)
    {
      vtkNew<vtkSubDLinearFilter> ours;
      ours->SetInputData(input);
      ours->SetNumberOfSubdivisions(levels);
      ours->Update();
      vtkNew<vtkLinearSubdivisionFilter> theirs;
      theirs->SetInputData(input);
      theirs->SetNumberOfSubdivisions(levels);
      theirs->Update();
      ASSERT_EQ(ours->GetOutput()->GetNumberOfPoints(), theirs->GetOutput()->GetNumberOfPoints()) << mesh.Name;
      ASSERT_EQ(ours->GetOutput()->GetNumberOfPolys(), theirs->GetOutput()->GetNumberOfPolys()) << mesh.Name;
      const double tolerance = Tolerance(theirs->GetOutput(), input);
      EXPECT_LE(WorstDistance(ours->GetOutput(), theirs->GetOutput()), tolerance) << mesh.Name;
      EXPECT_LE(WorstDistance(theirs->GetOutput(), ours->GetOutput()), tolerance) << mesh.Name;
    }
  }
}

TEST(OracleVTK, LoopEdgePointsMatchVtkLoopSubdivision)
{
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    vtkSmartPointer<vtkPolyData> input = ToPolyData(mesh);
    vtkNew<vtkSubDLoopFilter> ours;
    ours->SetInputData(input);
    ours->SetNumberOfSubdivisions(1);
    ours->Update();
    vtkNew<vtkLoopSubdivisionFilter> theirs;
    theirs->SetInputData(input);
    theirs->SetNumberOfSubdivisions(1);
    theirs->Update();
    ASSERT_EQ(ours->GetOutput()->GetNumberOfPoints(), theirs->GetOutput()->GetNumberOfPoints()) << mesh.Name;
    ASSERT_EQ(ours->GetOutput()->GetNumberOfPolys(), theirs->GetOutput()->GetNumberOfPolys()) << mesh.Name;
    // Our level-1 points: edge points first (E of them), then vertex points.
    const vtkIdType numEdges = ours->GetOutput()->GetNumberOfPoints() - input->GetNumberOfPoints();
    EXPECT_LE(WorstDistance(ours->GetOutput(), theirs->GetOutput(), 0, numEdges),
      Tolerance(theirs->GetOutput(), input))
      << mesh.Name;
  }
}

TEST(OracleVTK, ButterflyMatchesVtkButterflySubdivision)
{
  for (const subdtest::TestMesh& mesh : ClosedTriangleMeshes())
  {
    vtkSmartPointer<vtkPolyData> input = ToPolyData(mesh);
    for (int levels = 1; levels <= 2; ++levels)
    {
      vtkNew<vtkSubDButterflyFilter> ours;
      ours->SetInputData(input);
      ours->SetNumberOfSubdivisions(levels);
      ours->Update();
      vtkNew<vtkButterflySubdivisionFilter> theirs;
      theirs->SetInputData(input);
      theirs->SetNumberOfSubdivisions(levels);
      theirs->Update();
      ASSERT_EQ(ours->GetOutput()->GetNumberOfPoints(), theirs->GetOutput()->GetNumberOfPoints()) << mesh.Name;
      const double tolerance = Tolerance(theirs->GetOutput(), input);
      const double worst = WorstDistance(ours->GetOutput(), theirs->GetOutput());
      std::printf("butterfly %s level %d: largest distance to VTK %.3g of the diagonal\n", mesh.Name.c_str(), levels,
        worst / input->GetLength());
      EXPECT_LE(worst, tolerance) << mesh.Name << " level " << levels;
    }
  }
}
