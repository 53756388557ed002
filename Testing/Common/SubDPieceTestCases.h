// What the tests of subdivision in pieces (TestPieces, and TestPiecesMPI across ranks) run:
// every surface scheme, test meshes as vtkPolyData carrying what must survive the split into
// pieces (the input cell of each face, "TestCellId", which the children inherit, for
// SubDPieceComparison.h; global cell ids; a point-data array; optionally creases and a sharp
// vertex that cross the pieces), and a pipeline that cuts a piece and subdivides it.
#ifndef SubDPieceTestCases_h
#define SubDPieceTestCases_h

#include "SubDFilterTestSupport.h"

#include "vtkExtractPolyDataPiece.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"
#include "vtkTrivialProducer.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"

#include <functional>
#include <string>
#include <vector>

namespace subdtest
{
struct PieceScheme
{
  const char* Name;
  std::function<vtkSmartPointer<vtkSubDSurfaceFilter>()> Make;
  bool Triangles;
  // Doo-Sabin and midpoint pieces, numbering faces by their coordinates, may give a face made
  // from two faces the other one's cell data (vtkSubDPieces.h): compared without it.
  bool SameCellData = true;
};

template <typename T>
PieceScheme MakePieceScheme(const char* name, bool triangles, bool sameCellData = true)
{
  return { name, [] { return vtkSmartPointer<T>::New(); }, triangles, sameCellData };
}

inline std::vector<PieceScheme> PieceSchemes()
{
  return { MakePieceScheme<vtkSubDCatmullClarkFilter>("catmull-clark", false),
    MakePieceScheme<vtkSubDLoopFilter>("loop", true), MakePieceScheme<vtkSubDButterflyFilter>("butterfly", true),
    MakePieceScheme<vtkSubDLinearFilter>("linear", true), MakePieceScheme<vtkSubDSqrt3Filter>("sqrt3", true),
    MakePieceScheme<vtkSubDDooSabinFilter>("doo-sabin", false, false),
    MakePieceScheme<vtkSubDMidpointFilter>("midpoint", false, false) };
}

/// A mesh cut into the piece its consumer asks for (vtkExtractPolyDataPiece, with the ghost
/// levels asked of it).
struct PieceSource
{
  vtkNew<vtkTrivialProducer> Producer;
  vtkNew<vtkExtractPolyDataPiece> Extract;

  explicit PieceSource(vtkPolyData* input)
  {
    this->Producer->SetOutput(input);
    this->Extract->SetInputConnection(this->Producer->GetOutputPort());
  }
  vtkAlgorithmOutput* GetOutputPort() { return this->Extract->GetOutputPort(); }
};

/// input -> vtkExtractPolyDataPiece -> the scheme's filter (double output points: the piece
/// cutter stores float points, and double output keeps round-off apart from float rounding).
struct PiecePipeline
{
  PieceSource Source;
  vtkSmartPointer<vtkSubDSurfaceFilter> Filter;
  Messages FilterMessages;

  PiecePipeline(const PieceScheme& scheme, vtkPolyData* input, int levels)
    : Source(input)
    , Filter(scheme.Make())
  {
    this->Filter->SetInputConnection(this->Source.GetOutputPort());
    this->Filter->SetNumberOfSubdivisions(levels);
    this->Filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    this->FilterMessages.Watch(this->Filter);
  }

  /// A copy of the filter's output for piece `piece` of `numPieces`.
  vtkSmartPointer<vtkPolyData> Run(int piece, int numPieces)
  {
    this->Filter->UpdatePiece(piece, numPieces, 0);
    auto output = vtkSmartPointer<vtkPolyData>::New();
    output->DeepCopy(this->Filter->GetOutput());
    return output;
  }
};

/// Piece `piece` of `numPieces` (the whole mesh for 1) subdivided; adds the filter's errors
/// to `errors`.
inline vtkSmartPointer<vtkPolyData> SubdividePiece(
  const PieceScheme& scheme, vtkPolyData* input, int levels, int piece, int numPieces, int& errors)
{
  PiecePipeline pipeline(scheme, input, levels);
  vtkSmartPointer<vtkPolyData> output = pipeline.Run(piece, numPieces);
  errors += pipeline.FilterMessages.NumErrors;
  return output;
}

/// The comparison tolerance: 1e-12 of the mesh's size.
inline double PieceTolerance(vtkPolyData* mesh)
{
  return 1e-12 * std::max(1.0, mesh->GetLength());
}

struct PieceTestCase
{
  std::string Name;
  TestMesh Mesh;
  vtkIdType PointsPerRow; // grid points are numbered row by row
  bool Creases = false;
};

/// Closed and open, quads and triangles, with and without creases.
inline std::vector<PieceTestCase> PieceTestCases(bool triangles)
{
  const int n = 2; // pieces of several rows of cells, so that ghost layers do not cover them
  std::vector<PieceTestCase> cases{ { "torus", Grid(12 * n, 8 * n, true, true), 12 * n, false },
    { "open-grid", Grid(9 * n, 9 * n, false, false), 9 * n + 1, false },
    { "creased-torus", Grid(12 * n, 8 * n, true, true), 12 * n, true },
    { "creased-open-grid", Grid(9 * n, 9 * n, false, false), 9 * n + 1, true } };
  for (PieceTestCase& c : cases)
  {
    if (triangles)
    {
      c.Mesh = c.Mesh.Triangulated();
    }
  }
  return cases;
}

/// The test case as vtkPolyData. Creases: an infinitely sharp line along the vertices of one
/// mesh column and a semi-sharp one (2.5) along one row, so both cross every band of cells
/// that vtkExtractPolyDataPiece makes; a corner sharpness of 3 on one vertex.
inline vtkSmartPointer<vtkPolyData> PieceTestInput(const PieceTestCase& test)
{
  vtkSmartPointer<vtkPolyData> mesh = ToPolyData(test.Mesh);
  vtkNew<vtkDoubleArray> payload;
  payload->SetName("Payload");
  payload->SetNumberOfComponents(2);
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetPoint(p, x);
    payload->InsertNextTuple2(x[0] * x[1], x[2] + 0.5 * p);
  }
  mesh->GetPointData()->AddArray(payload);
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("Sharpness");
  if (test.Creases)
  {
    const vtkIdType perRow = test.PointsPerRow;
    const vtkIdType rows = mesh->GetNumberOfPoints() / perRow;
    vtkNew<vtkCellArray> lines;
    for (vtkIdType j = 0; j + 1 < rows; ++j)
    {
      lines->InsertNextCell({ j * perRow + 3, (j + 1) * perRow + 3 });
      sharpness->InsertNextValue(10.0f);
    }
    for (vtkIdType i = 0; i + 1 < perRow; ++i)
    {
      lines->InsertNextCell({ 4 * perRow + i, 4 * perRow + i + 1 });
      sharpness->InsertNextValue(2.5f);
    }
    mesh->SetLines(lines);
    vtkNew<vtkFloatArray> corner;
    corner->SetName("CornerSharpness");
    corner->SetNumberOfTuples(mesh->GetNumberOfPoints());
    corner->FillValue(0.0f);
    corner->SetValue(2 * perRow + 6, 3.0f);
    mesh->GetPointData()->AddArray(corner);
  }
  const vtkIdType numCells = mesh->GetNumberOfCells();
  vtkNew<vtkIdTypeArray> cellIds, globalIds;
  cellIds->SetName("TestCellId");
  globalIds->SetName("GlobalCellIds");
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    cellIds->InsertNextValue(c);
    globalIds->InsertNextValue(c);
    if (c < mesh->GetNumberOfLines())
    {
      continue;
    }
    sharpness->InsertNextValue(0.0f); // faces: the array is per cell
  }
  mesh->GetCellData()->AddArray(cellIds);
  mesh->GetCellData()->SetGlobalIds(globalIds);
  if (test.Creases)
  {
    mesh->GetCellData()->AddArray(sharpness);
  }
  return mesh;
}
}

#endif
