// Subdivision in pieces, in one process: every surface filter, asked for each of N pieces of a
// mesh split by vtkExtractPolyDataPiece (with the ghost levels the filter requests), must
// give pieces whose union is the serial output (SubDPieceComparison.h). The MPI tests
// (Testing/Parallel) do the same across processes.
#include "SubDPieceComparison.h"
#include "SubDPieceTestCases.h"

#include "vtkSubDCurveFilter.h"
#include "vtkSubDBSplineSurfaceFilter.h"
#include "vtkSubDCurveInterpolateFilter.h"
#include "vtkSubDInterpolateFilter.h"
#include "vtkSubDLimitFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace
{
using namespace subdtest;

class Pieces : public ::testing::TestWithParam<int>
{
};

TEST_P(Pieces, UnionOfPiecesIsTheSerialOutput)
{
  const PieceScheme scheme = PieceSchemes()[GetParam()];
  for (const PieceTestCase& test : PieceTestCases(scheme.Triangles))
  {
    vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
    for (int levels = 1; levels <= 3; ++levels)
    {
      int serialErrors = 0;
      vtkSmartPointer<vtkPolyData> serial = SubdividePiece(scheme, input, levels, 0, 1, serialErrors);
      ASSERT_GT(serial->GetNumberOfPolys(), 0);
      ASSERT_EQ(serialErrors, 0);
      for (int numPieces : { 2, 3, 5 })
      {
        std::vector<vtkSmartPointer<vtkPolyData>> pieces;
        std::vector<vtkPolyData*> raw;
        int errors = 0;
        vtkIdType total = 0;
        for (int p = 0; p < numPieces; ++p)
        {
          pieces.push_back(SubdividePiece(scheme, input, levels, p, numPieces, errors));
          raw.push_back(pieces.back());
          total += pieces.back()->GetNumberOfPolys();
          EXPECT_EQ(pieces.back()->GetCellData()->GetArray("vtkGhostType"), nullptr);
          EXPECT_EQ(pieces.back()->GetPointData()->GetArray("vtkGhostType"), nullptr);
        }
        const std::string where = std::string(scheme.Name) + " " + test.Name + ", " + std::to_string(levels) +
          " level(s), " + std::to_string(numPieces) + " pieces";
        EXPECT_EQ(errors, 0) << where;
        EXPECT_EQ(total, serial->GetNumberOfPolys()) << where;
        vtkIdType lines = 0; // each crease line is in one piece only, those on seams too
        for (vtkPolyData* piece : raw)
          lines += piece->GetNumberOfLines();
        EXPECT_EQ(lines, serial->GetNumberOfLines()) << where;
        EXPECT_EQ(ComparePieces(serial, raw, PieceTolerance(serial), scheme.SameCellData), "") << where;
      }
    }
  }
}

// With ProjectToLimit, each output point moves to its limit point, whose mask reads the
// vertex's neighbourhood: pieces still give the serial output. A piece's rim, where crease
// lines seem to end, must not make the projection fail on vertices the piece does not output.
TEST_P(Pieces, ProjectedToTheLimit)
{
  const PieceScheme scheme = PieceSchemes()[GetParam()];
  int compared = 0;
  for (const PieceTestCase& test : PieceTestCases(scheme.Triangles))
  {
    vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
    PiecePipeline pipeline(scheme, input, 2);
    pipeline.Filter->ProjectToLimitOn();
    vtkSmartPointer<vtkPolyData> serial = pipeline.Run(0, 1);
    if (pipeline.FilterMessages.NumErrors > 0)
    {
      continue; // no limit mask even serially: the creased torus's crease ends in darts, which
                // sqrt(3), Doo-Sabin and midpoint have no closed form for
    }
    ++compared;
    std::vector<vtkSmartPointer<vtkPolyData>> pieces;
    std::vector<vtkPolyData*> raw;
    for (int p = 0; p < 3; ++p)
    {
      pieces.push_back(pipeline.Run(p, 3));
      raw.push_back(pieces.back());
    }
    EXPECT_EQ(pipeline.FilterMessages.NumErrors, 0) << scheme.Name << " " << test.Name << ": "
                                                    << pipeline.FilterMessages.Errors;
    EXPECT_EQ(ComparePieces(serial, raw, PieceTolerance(serial), scheme.SameCellData), "")
      << scheme.Name << " " << test.Name;
  }
  EXPECT_GE(compared, 3) << "the meshes without creases and the creased open grid project in every scheme";
}

// More pieces than cells: some pieces are empty (no error, empty output), and one filter
// asked for every piece in turn (re-executing on each new piece) still gives the serial union.
TEST_P(Pieces, EmptyPiecesAndOneFilterForAllPieces)
{
  const PieceScheme scheme = PieceSchemes()[GetParam()];
  PieceTestCase test{ "cube", scheme.Triangles ? Cube().Triangulated() : Cube(), 4, false };
  vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
  int serialErrors = 0;
  vtkSmartPointer<vtkPolyData> serial = SubdividePiece(scheme, input, 2, 0, 1, serialErrors);
  const int numPieces = 2 * static_cast<int>(input->GetNumberOfCells());
  PiecePipeline pipeline(scheme, input, 2);
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  std::vector<vtkPolyData*> raw;
  int empty = 0;
  for (int p = 0; p < numPieces; ++p)
  {
    pieces.push_back(pipeline.Run(p, numPieces));
    raw.push_back(pieces.back());
    empty += pieces.back()->GetNumberOfCells() == 0;
  }
  EXPECT_GT(empty, 0);
  EXPECT_EQ(serialErrors + pipeline.FilterMessages.NumErrors, 0) << pipeline.FilterMessages.Errors;
  EXPECT_EQ(ComparePieces(serial, raw, PieceTolerance(serial), scheme.SameCellData), "");
}

// The adaptive tessellation asked for pieces: made of the whole mesh on the first piece (the
// serial tessellation, point for point), nothing on the others.
TEST(LimitPieces, AdaptiveTessellationIsMadeWholeOnTheFirstPiece)
{
  const PieceTestCase test = PieceTestCases(false).front();
  PieceSource source(PieceTestInput(test));
  vtkNew<vtkSubDLimitFilter> limit;
  limit->SetInputConnection(source.GetOutputPort());
  limit->SetTessellationToAdaptive();
  limit->SetTolerance(3e-3);
  Messages messages;
  messages.Watch(limit);
  limit->UpdatePiece(0, 1, 0);
  vtkNew<vtkPolyData> serial;
  serial->DeepCopy(limit->GetOutput());
  ASSERT_GT(serial->GetNumberOfPolys(), 0);
  for (int p = 0; p < 3; ++p)
  {
    limit->UpdatePiece(p, 3, 1);
    vtkPolyData* piece = limit->GetOutput();
    ASSERT_EQ(piece->GetNumberOfPoints(), p == 0 ? serial->GetNumberOfPoints() : 0) << "piece " << p;
    for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      piece->GetPoint(i, a);
      serial->GetPoint(i, b);
      EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << "point " << i;
    }
  }
  EXPECT_EQ(messages.NumErrors + messages.NumWarnings, 0) << messages.Errors << messages.Warnings;
}

// The limit surface's tessellation in pieces: the union of the pieces' tessellations of their
// own faces is the whole tessellation (points, carried point data, each cell's input cell),
// for Catmull-Clark on quads and Loop on triangles, with and without creases; asked for a
// ghost level, a piece adds the tessellations of its first layer of ghost faces, marked.
TEST(LimitPieces, UnionOfPiecesIsTheWholeTessellation)
{
  for (const bool loop : { false, true })
  {
    for (const PieceTestCase& test : PieceTestCases(loop))
    {
      PieceSource source(PieceTestInput(test));
      vtkNew<vtkSubDLimitFilter> limit;
      limit->SetInputConnection(source.GetOutputPort());
      limit->SetScheme(loop ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
      limit->SetResolution(2);
      // On a crease each side has its normal: a point there gets the side of the face that
      // evaluates it first, which a piece may see in another order. Positions agree.
      limit->SetComputeNormals(!test.Creases);
      Messages messages;
      messages.Watch(limit);
      limit->UpdatePiece(0, 1, 0);
      vtkNew<vtkPolyData> serial;
      serial->DeepCopy(limit->GetOutput());
      ASSERT_GT(serial->GetNumberOfPolys(), 0);
      const double tolerance = PieceTolerance(serial);
      for (const int numPieces : { 2, 3 })
      {
        for (const int ghostLevels : { 0, 1 })
        {
          std::vector<vtkSmartPointer<vtkPolyData>> own;
          std::vector<vtkPolyData*> raw;
          for (int p = 0; p < numPieces; ++p)
          {
            limit->UpdatePiece(p, numPieces, ghostLevels);
            own.push_back(CellsByGhostMark(limit->GetOutput(), false));
            raw.push_back(own.back());
            vtkSmartPointer<vtkPolyData> ghosts = CellsByGhostMark(limit->GetOutput(), true);
            EXPECT_EQ(ghosts->GetNumberOfPolys() > 0, ghostLevels > 0) << test.Name << ", piece " << p;
            EXPECT_EQ(FacesAreAmong(serial, ghosts, tolerance, true), "") << test.Name << ", piece " << p;
          }
          EXPECT_EQ(ComparePieces(serial, raw, tolerance, true), "")
            << (loop ? "Loop, " : "Catmull-Clark, ") << test.Name << ", " << numPieces << " pieces, "
            << ghostLevels << " ghost levels";
        }
      }
      EXPECT_EQ(messages.NumErrors + messages.NumWarnings, 0) << messages.Errors << messages.Warnings;
    }
  }
}

// The filters whose solve couples every point (interpolation, B-spline fitting) ask for the
// whole mesh even when one piece of several is asked of them: piece 0 is the serial output,
// the other pieces are empty.
TEST(WholeMeshPieces, GlobalSolvesGiveTheirResultAsPieceZero)
{
  vtkSmartPointer<vtkPolyData> grid = PieceTestInput(PieceTestCases(false)[1]); // open grid
  vtkSmartPointer<vtkPolyData> curves = ToPolyData(Grid(6, 4, false, false));
  vtkNew<vtkCellArray> rows;
  for (vtkIdType j = 0; j < 5; ++j)
    rows->InsertNextCell({ 7 * j, 7 * j + 1, 7 * j + 2, 7 * j + 3, 7 * j + 4, 7 * j + 5, 7 * j + 6 });
  curves->SetPolys(nullptr);
  curves->SetLines(rows);
  std::vector<std::pair<vtkSmartPointer<vtkPolyDataAlgorithm>, vtkPolyData*>> cases{
    { vtkSmartPointer<vtkSubDInterpolateFilter>::New(), grid },
    { vtkSmartPointer<vtkSubDCurveInterpolateFilter>::New(), curves },
    { vtkSmartPointer<vtkSubDBSplineSurfaceFilter>::New(), grid } };
  for (auto& c : cases)
  {
    PieceSource source(c.second); // would cut a piece if the filter asked for one
    vtkPolyDataAlgorithm* filter = c.first;
    filter->SetInputConnection(source.GetOutputPort());
    Messages messages;
    messages.Watch(filter);
    filter->UpdatePiece(0, 1, 0);
    vtkNew<vtkPolyData> serial;
    serial->DeepCopy(filter->GetOutput());
    ASSERT_GT(serial->GetNumberOfPoints(), 0) << filter->GetClassName() << ": " << messages.Errors;
    for (int p = 0; p < 3; ++p)
    {
      filter->UpdatePiece(p, 3, 1);
      vtkPolyData* piece = filter->GetOutput();
      if (p == 0)
      {
        EXPECT_EQ(Coordinates(piece), Coordinates(serial)) << filter->GetClassName();
        EXPECT_EQ(piece->GetNumberOfCells(), serial->GetNumberOfCells()) << filter->GetClassName();
      }
      else
      {
        EXPECT_EQ(piece->GetNumberOfCells() + piece->GetNumberOfPoints(), 0) << filter->GetClassName();
      }
    }
    EXPECT_EQ(messages.NumErrors, 0) << filter->GetClassName() << ": " << messages.Errors;
  }
}

// A piece that came without the ghost cells asked for is subdivided with its seams as
// boundaries: the filter warns (once per execution), and only then.
TEST(PiecesWithoutGhosts, WarnThatSeamsBecomeBoundaries)
{
  const PieceScheme scheme = PieceSchemes()[0];
  vtkSmartPointer<vtkPolyData> input = PieceTestInput(PieceTestCases(scheme.Triangles)[0]);
  PiecePipeline withGhosts(scheme, input, 2);
  withGhosts.Run(0, 2);
  EXPECT_EQ(withGhosts.FilterMessages.NumWarnings, 0) << withGhosts.FilterMessages.Warnings;
  PiecePipeline withoutGhosts(scheme, input, 2);
  withoutGhosts.Source.Extract->CreateGhostCellsOff();
  withoutGhosts.Run(0, 2);
  EXPECT_EQ(withoutGhosts.FilterMessages.NumWarnings, 1);
  EXPECT_NE(withoutGhosts.FilterMessages.Warnings.find("came without the ghost cells"), std::string::npos)
    << withoutGhosts.FilterMessages.Warnings;
}

// Asked for a ghost level of its output, a piece adds the children of the first layer of its
// ghost faces, marked DUPLICATECELL: without them the pieces are still the serial output, the
// marked faces are serial faces (of other pieces), and exactly the points of no own face are
// marked DUPLICATEPOINT.
TEST_P(Pieces, GhostLevelsAskedOfTheOutput)
{
  const PieceScheme scheme = PieceSchemes()[GetParam()];
  const PieceTestCase test = PieceTestCases(scheme.Triangles)[2]; // the creased torus
  vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
  int serialErrors = 0;
  vtkSmartPointer<vtkPolyData> serial = SubdividePiece(scheme, input, 2, 0, 1, serialErrors);
  const double tolerance = PieceTolerance(serial);
  const int numPieces = 3;
  std::vector<vtkSmartPointer<vtkPolyData>> own;
  std::vector<vtkPolyData*> raw;
  for (int p = 0; p < numPieces; ++p)
  {
    PiecePipeline pipeline(scheme, input, 2);
    pipeline.Filter->UpdatePiece(p, numPieces, 1);
    vtkPolyData* piece = pipeline.Filter->GetOutput();
    EXPECT_EQ(pipeline.FilterMessages.NumErrors, 0);
    vtkDataArray* cellMarks = piece->GetCellData()->GetArray("vtkGhostType");
    vtkDataArray* pointMarks = piece->GetPointData()->GetArray("vtkGhostType");
    ASSERT_NE(cellMarks, nullptr);
    ASSERT_NE(pointMarks, nullptr);
    own.push_back(CellsByGhostMark(piece, false));
    raw.push_back(own.back());
    vtkSmartPointer<vtkPolyData> ghosts = CellsByGhostMark(piece, true);
    EXPECT_GT(ghosts->GetNumberOfPolys(), 0) << "piece " << p;
    EXPECT_EQ(FacesAreAmong(serial, ghosts, tolerance, scheme.SameCellData), "") << "piece " << p;
    // Points: DUPLICATEPOINT exactly where no own face has a corner.
    std::vector<char> onOwnFace(static_cast<size_t>(piece->GetNumberOfPoints()), 0);
    vtkIdType n;
    const vtkIdType* pts;
    for (own.back()->GetPolys()->InitTraversal(); own.back()->GetPolys()->GetNextCell(n, pts);)
    {
      for (vtkIdType k = 0; k < n; ++k)
        onOwnFace[pts[k]] = 1;
    }
    for (vtkIdType q = 0; q < piece->GetNumberOfPoints(); ++q)
    {
      ASSERT_EQ(pointMarks->GetComponent(q, 0) != 0, !onOwnFace[q]) << "piece " << p << ", point " << q;
    }
  }
  EXPECT_EQ(ComparePieces(serial, raw, tolerance, scheme.SameCellData), "");
  vtkIdType lines = 0; // own crease lines: each in one piece only, those on seams too
  for (vtkPolyData* piece : raw)
    lines += piece->GetNumberOfLines();
  EXPECT_EQ(lines, serial->GetNumberOfLines()) << scheme.Name;
}

// Curves: each line is refined by itself, so pieces need no ghost cells; asked for one ghost
// level, a piece adds its ghost lines refined and marked.
namespace
{
// Polylines (open, closed, sharing end points) with a point-data array.
vtkSmartPointer<vtkPolyData> CurveTestInput()
{
  auto curves = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> payload;
  payload->SetName("Payload");
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIdTypeArray> cellIds;
  cellIds->SetName("TestCellId");
  vtkIdType shared = -1;
  for (int c = 0; c < 12; ++c)
  {
    std::vector<vtkIdType> ids;
    if (c % 2 == 0 && shared >= 0)
    {
      ids.push_back(shared); // starts where the previous curve ended
    }
    const int n = 4 + c % 5;
    for (int k = 0; k < n; ++k)
    {
      ids.push_back(points->InsertNextPoint(k, c + 0.3 * std::sin(k + c), 0.1 * k * k));
      payload->InsertNextValue(k * c);
    }
    if (c % 3 == 2)
    {
      ids.push_back(ids.front()); // closed
    }
    shared = ids.back();
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    cellIds->InsertNextValue(c);
  }
  curves->SetPoints(points);
  curves->SetLines(lines);
  curves->GetPointData()->AddArray(payload);
  curves->GetCellData()->AddArray(cellIds);
  return curves;
}

// The lines of `mesh` (without the ghost ones unless `withGhosts`) as sequences of corners
// with their "TestCellId", sorted by it.
std::vector<std::pair<double, Face>> Polylines(vtkPolyData* mesh, bool withGhosts)
{
  std::vector<std::pair<double, Face>> out;
  vtkDataArray* marks = mesh->GetCellData()->GetArray("vtkGhostType");
  vtkDataArray* ids = mesh->GetCellData()->GetArray("TestCellId");
  vtkIdType c = mesh->GetNumberOfVerts(), n;
  const vtkIdType* pts;
  for (mesh->GetLines()->InitTraversal(); mesh->GetLines()->GetNextCell(n, pts); ++c)
  {
    if (!withGhosts && marks && marks->GetComponent(c, 0) != 0)
    {
      continue;
    }
    Face line;
    for (vtkIdType k = 0; k < n; ++k)
    {
      line.push_back(CornerOf(mesh, pts[k]));
    }
    out.emplace_back(ids->GetComponent(c, 0), line);
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

bool SameLines(const std::vector<std::pair<double, Face>>& a, const std::vector<std::pair<double, Face>>& b)
{
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const auto& p, const auto& q) {
    return p.first == q.first && SameFace(p.second, q.second, 1e-12);
  });
}

TEST(CurvePieces, UnionOfPiecesIsTheSerialOutputAndGhostLinesAreMarked)
{
  vtkSmartPointer<vtkPolyData> input = CurveTestInput();
  for (int scheme : { vtkSubDCurveFilter::SCHEME_CHAIKIN, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE,
         vtkSubDCurveFilter::SCHEME_FOUR_POINT })
  {
    auto run = [&](int piece, int numPieces, int ghostLevels) {
      PieceSource source(input);
      vtkNew<vtkSubDCurveFilter> filter;
      filter->SetInputConnection(source.GetOutputPort());
      filter->SetScheme(scheme);
      filter->SetNumberOfSubdivisions(3);
      filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
      filter->UpdatePiece(piece, numPieces, ghostLevels);
      auto output = vtkSmartPointer<vtkPolyData>::New();
      output->DeepCopy(filter->GetOutput());
      return output;
    };
    const auto serial = Polylines(run(0, 1, 0), true);
    ASSERT_EQ(serial.size(), 12u);
    for (int ghostLevels : { 0, 1 })
    {
      std::vector<std::pair<double, Face>> together;
      size_t ghostLines = 0;
      for (int p = 0; p < 3; ++p)
      {
        vtkSmartPointer<vtkPolyData> piece = run(p, 3, ghostLevels);
        const auto own = Polylines(piece, false);
        together.insert(together.end(), own.begin(), own.end());
        ghostLines += Polylines(piece, true).size() - own.size();
        vtkDataArray* pointMarks = piece->GetPointData()->GetArray("vtkGhostType");
        EXPECT_TRUE(pointMarks != nullptr || ghostLevels == 0);
        for (vtkIdType q = 0; pointMarks && q < pointMarks->GetNumberOfTuples(); ++q)
        {
          const double mark = pointMarks->GetComponent(q, 0); // never an interpolated value
          EXPECT_TRUE(mark == 0 || mark == vtkDataSetAttributes::DUPLICATEPOINT) << mark;
        }
      }
      std::sort(together.begin(), together.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      EXPECT_TRUE(SameLines(serial, together)) << "scheme " << scheme << ", ghost levels " << ghostLevels;
      EXPECT_EQ(ghostLines > 0, ghostLevels > 0);
    }
  }
}
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Pieces, ::testing::Range(0, 7),
  [](const ::testing::TestParamInfo<int>& info) {
    std::string name = PieceSchemes()[info.param].Name;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  });
}
