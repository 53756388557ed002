// Inputs for the tests of subdivision in pieces: test meshes as vtkPolyData carrying what
// must survive the split into pieces: the input cell of each face ("TestCellId", which the
// children inherit, for SubDPieceComparison.h), global cell ids (the GlobalIds attribute),
// a point-data array, and optionally creases and a sharp vertex that cross the pieces.
#ifndef SubDPieceTestInputs_h
#define SubDPieceTestInputs_h

#include "SubDFilterTestSupport.h"

#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPointData.h"

#include <string>
#include <vector>

namespace subdtest
{
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
