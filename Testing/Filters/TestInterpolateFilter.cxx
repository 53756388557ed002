// vtkSubDInterpolateFilter: the solved cage's limit surface passes through the targets.
// Checked independently of the solver: Catmull-Clark and Loop limit points through
// vtkSubDLimitFilter (exact evaluation, itself checked against OpenSubdiv), Doo-Sabin limit
// points by the closed form (the centroid of the vertex's V-face, Doo and Sabin's weights).
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDInterpolateFilter.h"
#include "vtkSubDLimitFilter.h"

#include "SubDFilterTestSupport.h"
#include "SubDTestMeshes.h"

#include "vtkCellArray.h"
#include "vtkCellLocator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using subdtest::ToPolyData;

// The limit point of every vertex used by a face, through vtkSubDLimitFilter evaluated at a
// corner of one of its faces (FaceUV at that corner).
std::vector<double> PrimalLimitPoints(vtkPolyData* cage, int scheme)
{
  const vtkIdType n = cage->GetNumberOfPoints();
  vtkNew<vtkPolyData> locations;
  vtkNew<vtkPoints> dummy;
  vtkNew<vtkDoubleArray> faceId, uv;
  vtkNew<vtkIntArray> subFace;
  faceId->SetName("FaceId");
  uv->SetName("FaceUV");
  uv->SetNumberOfComponents(2);
  subFace->SetName("SubFace");
  std::vector<char> seen(static_cast<size_t>(n), 0);
  std::vector<vtkIdType> order;
  const bool quads = scheme == vtkSubDLimitFilter::CATMULL_CLARK;
  const vtkIdType firstPolygon = cage->GetNumberOfVerts() + cage->GetNumberOfLines(); // crease lines first
  for (vtkIdType c = firstPolygon; c < cage->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cage->GetCellPoints(c, size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (seen[ids[k]])
      {
        continue;
      }
      seen[ids[k]] = 1;
      order.push_back(ids[k]);
      dummy->InsertNextPoint(0, 0, 0);
      faceId->InsertNextValue(static_cast<double>(c));
      if (quads && size != 4)
      {
        uv->InsertNextTuple2(0, 0); // corner k of its sub-face k
        subFace->InsertNextValue(static_cast<int>(k));
      }
      else
      {
        static const double quadCorner[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
        static const double triCorner[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
        const double* corner = quads ? quadCorner[k] : triCorner[k];
        uv->InsertNextTuple2(corner[0], corner[1]);
        subFace->InsertNextValue(0);
      }
    }
  }
  locations->SetPoints(dummy);
  locations->GetPointData()->AddArray(faceId);
  locations->GetPointData()->AddArray(uv);
  locations->GetPointData()->AddArray(subFace);
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetScheme(scheme);
  limit->SetInputData(cage);
  limit->SetInputData(1, locations);
  limit->Update();
  std::vector<double> points(static_cast<size_t>(3 * n), std::nan(""));
  EXPECT_EQ(limit->GetOutput()->GetNumberOfPoints(), static_cast<vtkIdType>(order.size()));
  for (size_t i = 0; i < order.size() && static_cast<vtkIdType>(i) < limit->GetOutput()->GetNumberOfPoints(); ++i)
  {
    limit->GetOutput()->GetPoint(static_cast<vtkIdType>(i), &points[3 * order[i]]);
  }
  return points;
}

// Doo-Sabin's limit point of a smooth vertex: the centroid of its V-face, whose corner in
// face F (n corners P_j, the vertex at corner i) is sum_j a_ij P_j with a_ii = (n + 5) / 4n,
// a_ij = (3 + 2 cos(2 pi (i - j) / n)) / 4n (Doo and Sabin 1978).
std::vector<double> DooSabinLimitPoints(vtkPolyData* cage)
{
  const vtkIdType n = cage->GetNumberOfPoints();
  std::vector<double> sum(static_cast<size_t>(3 * n), 0.0);
  std::vector<int> count(static_cast<size_t>(n), 0);
  const double pi = 3.14159265358979323846;
  for (vtkIdType c = 0; c < cage->GetNumberOfCells(); ++c)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cage->GetCellPoints(c, size, ids);
    for (vtkIdType i = 0; i < size; ++i)
    {
      for (vtkIdType j = 0; j < size; ++j)
      {
        const double a = i == j ? (size + 5.0) / (4.0 * size)
                                : (3.0 + 2.0 * std::cos(2 * pi * static_cast<double>(i - j) / size)) / (4.0 * size);
        double p[3];
        cage->GetPoint(ids[j], p);
        for (int d = 0; d < 3; ++d)
        {
          sum[3 * ids[i] + d] += a * p[d];
        }
      }
      ++count[ids[i]];
    }
  }
  for (vtkIdType v = 0; v < n; ++v)
  {
    for (int d = 0; d < 3; ++d)
    {
      sum[3 * v + d] /= count[v];
    }
  }
  return sum;
}

vtkSmartPointer<vtkPolyData> Solve(vtkPolyData* targets, int scheme, int boundaryRule = 1,
  int solver = vtkSubDInterpolateFilter::SOLVER_AUTOMATIC)
{
  vtkNew<vtkSubDInterpolateFilter> filter;
  filter->SetSolver(solver);
  subdtest::Messages messages;
  messages.Watch(filter);
  filter->SetScheme(scheme);
  filter->SetBoundaryRule(boundaryRule);
  filter->SetInputData(targets);
  filter->Update();
  EXPECT_EQ(messages.Errors, "");
  EXPECT_LT(filter->GetResidual(), 1e-13);
  auto cage = vtkSmartPointer<vtkPolyData>::New();
  cage->DeepCopy(filter->GetOutput());
  return cage;
}

void ExpectPointsNear(const std::vector<double>& actual, vtkPolyData* expected, double tolerance, const std::string& what)
{
  for (vtkIdType v = 0; v < expected->GetNumberOfPoints(); ++v)
  {
    double p[3];
    expected->GetPoint(v, p);
    for (int d = 0; d < 3; ++d)
    {
      EXPECT_NEAR(actual[3 * v + d], p[d], tolerance) << what << " vertex " << v;
    }
  }
}

// An open grid with an infinitely sharp crease along an interior row and a semi-sharp
// continuation of it.
vtkSmartPointer<vtkPolyData> CreasedGrid()
{
  auto grid = ToPolyData(subdtest::Grid(4, 3, false, false).Jitter(0.1)); // rows of 5 points
  vtkNew<vtkCellArray> lines;
  const vtkIdType sharp[3] = { 5, 6, 7 }, semi[2] = { 7, 8 };
  lines->InsertNextCell(3, sharp);
  lines->InsertNextCell(2, semi);
  grid->SetLines(lines);
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("Sharpness");
  sharpness->InsertNextValue(10.0f); // lines come first in a polydata's cells
  sharpness->InsertNextValue(1.5f);
  for (vtkIdType f = 0; f < grid->GetNumberOfPolys(); ++f)
  {
    sharpness->InsertNextValue(0.0f);
  }
  grid->GetCellData()->AddArray(sharpness);
  return grid;
}
}

TEST(InterpolateFilter, CatmullClarkLimitPassesThroughEveryVertex)
{
  for (const subdtest::TestMesh& mesh :
    { subdtest::Grid(4, 3, false, false).Jitter(0.1), subdtest::Star(5).Jitter(0.1),
      subdtest::House(false).Jitter(0.1), subdtest::Grid(6, 5, true, true).Jitter(0.05),
      subdtest::RepeatedCornerPole(8) }) // cap quads (a, b, T, T) kept as the Catmull-Clark filter keeps them
  {
    auto targets = ToPolyData(mesh);
    for (int solver : { vtkSubDInterpolateFilter::SOLVER_DIRECT, vtkSubDInterpolateFilter::SOLVER_ITERATIVE })
    {
      auto cage = Solve(targets, vtkSubDInterpolateFilter::CATMULL_CLARK, 1, solver);
      ExpectPointsNear(PrimalLimitPoints(cage, vtkSubDLimitFilter::CATMULL_CLARK), targets, 1e-12,
        mesh.Name + (solver == vtkSubDInterpolateFilter::SOLVER_DIRECT ? " (SparseLU)" : " (BiCGSTAB)"));
    }
  }
}

// A closed cube's Catmull-Clark limit masks annihilate the alternating +1/-1 pattern of its
// (bipartite) vertices: no cage has arbitrary limit points there, and where one does (the
// cube's own corners are consistent targets) any multiple of the pattern can be added. Both
// are a clear error, with no output - not an arbitrary one of many cages.
TEST(InterpolateFilter, SingularSystemIsAClearError)
{
  for (int solver : { vtkSubDInterpolateFilter::SOLVER_DIRECT, vtkSubDInterpolateFilter::SOLVER_ITERATIVE })
  {
    for (const subdtest::TestMesh& cube : { subdtest::Cube().Jitter(0.1), subdtest::Cube() })
    {
      vtkNew<vtkSubDInterpolateFilter> filter;
      subdtest::Messages messages;
      messages.Watch(filter);
      filter->SetSolver(solver);
      filter->SetInputData(ToPolyData(cube));
      filter->Update();
      EXPECT_NE(messages.Errors.find("singular or ill-conditioned"), std::string::npos) << messages.Errors;
      EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
      EXPECT_GT(filter->GetConditionEstimate(), 1e10);
    }
  }
  // A well-posed system reports a modest condition number.
  vtkNew<vtkSubDInterpolateFilter> filter;
  filter->SetInputData(ToPolyData(subdtest::Grid(5, 4, false, false).Jitter(0.1)));
  filter->Update();
  EXPECT_GT(filter->GetConditionEstimate(), 1.0);
  EXPECT_LT(filter->GetConditionEstimate(), 20.0);
}

TEST(InterpolateFilter, CatmullClarkWithSharpAndSemiSharpCreases)
{
  auto targets = CreasedGrid();
  auto cage = Solve(targets, vtkSubDInterpolateFilter::CATMULL_CLARK);
  ExpectPointsNear(PrimalLimitPoints(cage, vtkSubDLimitFilter::CATMULL_CLARK), targets, 1e-12, "creased grid");
  // The creases matter: without them the same targets need another cage.
  targets->SetLines(nullptr);
  targets->GetCellData()->Initialize();
  auto smoothCage = Solve(targets, vtkSubDInterpolateFilter::CATMULL_CLARK);
  EXPECT_GT(subdtest::LargestDistanceToNearestPoint(cage, smoothCage), 1e-3);
}

TEST(InterpolateFilter, LoopLimitPassesThroughEveryVertex)
{
  for (const subdtest::TestMesh& mesh : { subdtest::Bipyramid(5).Jitter(0.1), subdtest::Cube().Jitter(0.1).Triangulated(),
         subdtest::Grid(4, 3, false, false).Jitter(0.1).Triangulated(), subdtest::RepeatedCornerPole(8).Triangulated() })
  {
    auto targets = ToPolyData(mesh);
    auto cage = Solve(targets, vtkSubDInterpolateFilter::LOOP);
    ExpectPointsNear(PrimalLimitPoints(cage, vtkSubDLimitFilter::LOOP), targets, 1e-12, mesh.Name);
  }
}

TEST(InterpolateFilter, DooSabinVFaceCentroidsPassThroughEveryVertex)
{
  for (const subdtest::TestMesh& mesh : { subdtest::Grid(6, 5, true, true).Jitter(0.05), subdtest::Bipyramid(5).Jitter(0.1) })
  {
    auto targets = ToPolyData(mesh);
    auto cage = Solve(targets, vtkSubDInterpolateFilter::DOO_SABIN);
    ExpectPointsNear(DooSabinLimitPoints(cage), targets, 1e-12, mesh.Name);
  }
}

// Open meshes and creases, checked through refinement instead of a closed form. Doo-Sabin
// maps every face to a polygon with the same centroid, and along boundaries and creases
// Chaikin's rule keeps the midpoint of every edge; so a vertex's limit point is, at every
// level, the centroid of a face (its V-face's descendant), the midpoint of a boundary or
// crease edge, or (a pinned corner) a vertex. Two levels of vtkSubDDooSabinFilter make these
// landmarks; each target must be one of them to round-off. The distance to 7 refined levels'
// faces (VTK's cell locator) checks the same independently of those facts, more loosely.
TEST(InterpolateFilter, DooSabinOnOpenAndCreasedMeshesPassesThroughTheTargets)
{
  vtkSmartPointer<vtkPolyData> open = ToPolyData(subdtest::Grid(4, 3, false, false).Jitter(0.1));
  vtkSmartPointer<vtkPolyData> creased = ToPolyData(subdtest::Grid(4, 3, false, false).Jitter(0.1));
  vtkNew<vtkCellArray> crease; // across the grid, boundary to boundary: Doo-Sabin has no dart rule
  const vtkIdType row[5] = { 5, 6, 7, 8, 9 };
  crease->InsertNextCell(5, row);
  creased->SetLines(crease);
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("Sharpness");
  sharpness->InsertNextValue(10.0f);
  for (vtkIdType f = 0; f < creased->GetNumberOfPolys(); ++f)
  {
    sharpness->InsertNextValue(0.0f);
  }
  creased->GetCellData()->AddArray(sharpness);
  for (vtkPolyData* targets : { open.GetPointer(), creased.GetPointer() })
  {
    auto largestDistance = [targets](vtkPolyData* cage) {
      vtkNew<vtkSubDDooSabinFilter> refine;
      refine->SetInputData(cage);
      refine->SetNumberOfSubdivisions(7);
      refine->Update();
      vtkNew<vtkPolyData> faces; // without the crease lines, which are no surface
      faces->SetPoints(refine->GetOutput()->GetPoints());
      faces->SetPolys(refine->GetOutput()->GetPolys());
      vtkNew<vtkCellLocator> locator;
      locator->SetDataSet(faces);
      locator->BuildLocator();
      double worst = 0.0;
      for (vtkIdType v = 0; v < targets->GetNumberOfPoints(); ++v)
      {
        double target[3], closest[3], distance2;
        vtkIdType cell;
        int subId;
        targets->GetPoint(v, target);
        locator->FindClosestPoint(target, closest, cell, subId, distance2);
        worst = std::max(worst, std::sqrt(distance2));
      }
      return worst;
    };
    auto largestMissOfLandmarks = [targets](vtkPolyData* cage) {
      vtkNew<vtkSubDDooSabinFilter> refine;
      refine->SetInputData(cage);
      refine->SetNumberOfSubdivisions(2);
      refine->Update();
      vtkPolyData* refined = refine->GetOutput();
      vtkNew<vtkPolyData> landmarks;
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      for (vtkIdType c = 0; c < refined->GetNumberOfCells(); ++c)
      {
        vtkIdType n;
        const vtkIdType* ids;
        refined->GetCellPoints(c, n, ids);
        double centroid[3] = { 0, 0, 0 };
        for (vtkIdType k = 0; k < n; ++k)
        {
          double a[3], b[3];
          refined->GetPoint(ids[k], a);
          refined->GetPoint(ids[(k + 1) % n], b);
          points->InsertNextPoint(a);
          points->InsertNextPoint((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2);
          for (int d = 0; d < 3; ++d)
            centroid[d] += a[d] / n;
        }
        points->InsertNextPoint(centroid);
      }
      landmarks->SetPoints(points);
      return subdtest::LargestDistanceToNearestPoint(targets, landmarks);
    };
    auto cage = Solve(targets, vtkSubDInterpolateFilter::DOO_SABIN);
    EXPECT_LT(largestMissOfLandmarks(cage), 1e-12);
    EXPECT_LT(largestDistance(cage), 1e-3);
    EXPECT_GT(largestDistance(targets), 1e-2); // the unsolved cage misses them
    EXPECT_GT(largestMissOfLandmarks(targets), 1e-3);
  }

  // With a dart (the semi-sharp crease of CreasedGrid ends inside), Doo-Sabin has no limit
  // point there, and the error says so.
  vtkNew<vtkSubDInterpolateFilter> filter;
  subdtest::Messages messages;
  messages.Watch(filter);
  filter->SetSchemeToDooSabin();
  filter->SetInputData(CreasedGrid());
  filter->Update();
  EXPECT_NE(messages.Errors.find("The doo-sabin scheme has no limit points for this cage: vertex 8 (a dart"),
    std::string::npos)
    << messages.Errors;
}

// Scale: a 100k-vertex cage takes the automatic choice's iterative path (BiCGSTAB). Its limit
// points, by the Catmull-Clark filter's ProjectToLimit (OpenSubdiv's masks), are the targets.
TEST(InterpolateFilter, AHundredThousandVertexCageSolves)
{
  auto targets = ToPolyData(subdtest::Grid(316, 316, false, false).Jitter(0.2));
  ASSERT_GT(targets->GetNumberOfPoints(), 100000);
  vtkNew<vtkSubDInterpolateFilter> filter;
  filter->SetInputData(targets);
  filter->Update();
  ASSERT_EQ(filter->GetErrorCode(), 0UL);
  EXPECT_EQ(filter->GetNumberOfTaggedPoints(), targets->GetNumberOfPoints());
  EXPECT_LT(filter->GetConditionEstimate(), 20.0);
  vtkNew<vtkSubDCatmullClarkFilter> limit;
  limit->SetInputConnection(filter->GetOutputPort());
  limit->SetNumberOfSubdivisions(0);
  limit->ProjectToLimitOn();
  limit->Update();
  EXPECT_LT(subdtest::LargestPointwiseDifference(subdtest::Coordinates(targets), subdtest::Coordinates(limit->GetOutput())), 1e-10);
}

TEST(InterpolateFilter, UntaggedVerticesKeepTheirPositions)
{
  auto targets = ToPolyData(subdtest::Grid(5, 4, false, false).Jitter(0.1));
  vtkNew<vtkIntArray> tags;
  tags->SetName("Interpolate");
  for (vtkIdType v = 0; v < targets->GetNumberOfPoints(); ++v)
  {
    tags->InsertNextValue(v % 3 == 0 ? 1 : 0);
  }
  targets->GetPointData()->AddArray(tags);
  vtkNew<vtkSubDInterpolateFilter> filter;
  filter->SetInputData(targets);
  filter->Update();
  vtkPolyData* cage = filter->GetOutput();
  ASSERT_EQ(cage->GetNumberOfPoints(), targets->GetNumberOfPoints());
  EXPECT_EQ(filter->GetNumberOfTaggedPoints(), (targets->GetNumberOfPoints() + 2) / 3);
  const std::vector<double> limit = PrimalLimitPoints(cage, vtkSubDLimitFilter::CATMULL_CLARK);
  bool moved = false;
  for (vtkIdType v = 0; v < targets->GetNumberOfPoints(); ++v)
  {
    double t[3], c[3];
    targets->GetPoint(v, t);
    cage->GetPoint(v, c);
    for (int d = 0; d < 3; ++d)
    {
      if (v % 3 == 0)
      {
        EXPECT_NEAR(limit[3 * v + d], t[d], 1e-12) << "tagged vertex " << v;
        moved = moved || c[d] != t[d];
      }
      else
      {
        EXPECT_EQ(c[d], t[d]) << "untagged vertex " << v;
      }
    }
  }
  EXPECT_TRUE(moved); // the tagged vertices had to move for their limits to reach the targets
  EXPECT_NE(cage->GetPointData()->GetArray("Interpolate"), nullptr); // point data is kept
}

TEST(InterpolateFilter, AnInterpolatingConfigurationIsAFixedPoint)
{
  // A uniform planar grid: every limit mask reproduces linear functions, so each vertex is
  // already its own limit point (corners kept by the edge-and-corner rule).
  subdtest::TestMesh grid = subdtest::Grid(5, 4, false, false);
  for (size_t k = 2; k < grid.Points.size(); k += 3)
  {
    grid.Points[k] = 0.0;
  }
  auto targets = ToPolyData(grid);
  auto cage = Solve(targets, vtkSubDInterpolateFilter::CATMULL_CLARK, 2);
  ExpectPointsNear(subdtest::Coordinates(cage), targets, 1e-12, "planar grid");
}

TEST(InterpolateFilter, RefinedSurfaceOutputAndClearErrors)
{
  auto targets = ToPolyData(subdtest::Star(5).Jitter(0.1));
  vtkNew<vtkSubDInterpolateFilter> filter;
  subdtest::Messages messages;
  messages.Watch(filter);
  filter->SetInputData(targets);
  filter->OutputRefinedSurfaceOn();
  filter->SetNumberOfSubdivisions(2);
  filter->Update();
  EXPECT_EQ(messages.Errors, "");
  // The same as refining the solved cage with the scheme's filter.
  vtkNew<vtkPolyData> refined;
  refined->DeepCopy(filter->GetOutput());
  filter->OutputRefinedSurfaceOff();
  filter->Update();
  vtkNew<vtkSubDCatmullClarkFilter> catmullClark;
  catmullClark->SetInputData(filter->GetOutput());
  catmullClark->SetNumberOfSubdivisions(2);
  catmullClark->Update();
  EXPECT_GT(refined->GetNumberOfPolys(), targets->GetNumberOfPolys() * 4);
  EXPECT_EQ(refined->GetNumberOfPolys(), catmullClark->GetOutput()->GetNumberOfPolys());
  EXPECT_EQ(subdtest::Coordinates(refined), subdtest::Coordinates(catmullClark->GetOutput()));

  // Loop needs triangles: a clear error and an empty output.
  filter->SetSchemeToLoop();
  filter->Update();
  EXPECT_NE(messages.Errors.find("Loop needs triangles"), std::string::npos) << messages.Errors;
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}
