// Subdivision in pieces, in one process: every surface filter, asked for each of N pieces of a
// mesh split by vtkExtractPolyDataPiece (with the ghost levels the filter requests), must
// give pieces whose union is the serial output (SubDPieceComparison.h). The MPI tests
// (Testing/Parallel) do the same across processes.
#include "SubDPieceComparison.h"
#include "SubDPieceTestInputs.h"

#include "vtkExtractPolyDataPiece.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"
#include "vtkTrivialProducer.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace
{
using namespace subdtest;

struct SchemeCase
{
  const char* Name;
  std::function<vtkSmartPointer<vtkSubDSurfaceFilter>()> Make;
  bool Triangles;
  // Doo-Sabin and midpoint pieces, numbering faces by their coordinates, may give a face made
  // from two faces the other one's cell data (vtkSubDPieces.h): compared without it.
  bool SameCellData = true;
};

template <typename T>
SchemeCase Scheme(const char* name, bool triangles, bool sameCellData = true)
{
  return { name, [] { return vtkSmartPointer<T>::New(); }, triangles, sameCellData };
}

std::vector<SchemeCase> Schemes()
{
  return { Scheme<vtkSubDCatmullClarkFilter>("catmull-clark", false), Scheme<vtkSubDLoopFilter>("loop", true),
    Scheme<vtkSubDButterflyFilter>("butterfly", true), Scheme<vtkSubDLinearFilter>("linear", true),
    Scheme<vtkSubDSqrt3Filter>("sqrt3", true), Scheme<vtkSubDDooSabinFilter>("doo-sabin", false, false),
    Scheme<vtkSubDMidpointFilter>("midpoint", false, false) };
}

// The filter's output for piece `piece` of `numPieces` (the whole mesh for 1 piece), with
// `ghostLevels` ghost levels instead of the filter's own request when >= 0.
vtkSmartPointer<vtkPolyData> RunPiece(const SchemeCase& scheme, vtkPolyData* input, int levels, int piece,
  int numPieces, Messages& messages)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(input);
  vtkNew<vtkExtractPolyDataPiece> extract;
  extract->SetInputConnection(producer->GetOutputPort());
  vtkSmartPointer<vtkSubDSurfaceFilter> filter = scheme.Make();
  filter->SetInputConnection(extract->GetOutputPort());
  filter->SetNumberOfSubdivisions(levels);
  // vtkExtractPolyDataPiece makes float points; double output keeps round-off apart from the
  // float rounding of the result.
  filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  messages.Watch(filter);
  filter->UpdatePiece(piece, numPieces, 0);
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}

double Tolerance(vtkPolyData* mesh)
{
  return 1e-12 * std::max(1.0, mesh->GetLength());
}

class Pieces : public ::testing::TestWithParam<int>
{
};

TEST_P(Pieces, UnionOfPiecesIsTheSerialOutput)
{
  const SchemeCase scheme = Schemes()[GetParam()];
  for (const PieceTestCase& test : PieceTestCases(scheme.Triangles))
  {
    vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
    for (int levels = 1; levels <= 3; ++levels)
    {
      Messages serialMessages;
      vtkSmartPointer<vtkPolyData> serial = RunPiece(scheme, input, levels, 0, 1, serialMessages);
      ASSERT_GT(serial->GetNumberOfPolys(), 0) << serialMessages.Errors;
      for (int numPieces : { 2, 3, 5 })
      {
        std::vector<vtkSmartPointer<vtkPolyData>> pieces;
        std::vector<vtkPolyData*> raw;
        Messages messages;
        vtkIdType total = 0;
        for (int p = 0; p < numPieces; ++p)
        {
          pieces.push_back(RunPiece(scheme, input, levels, p, numPieces, messages));
          raw.push_back(pieces.back());
          total += pieces.back()->GetNumberOfPolys();
          EXPECT_EQ(pieces.back()->GetCellData()->GetArray("vtkGhostType"), nullptr);
          EXPECT_EQ(pieces.back()->GetPointData()->GetArray("vtkGhostType"), nullptr);
        }
        const std::string where = std::string(scheme.Name) + " " + test.Name + ", " + std::to_string(levels) +
          " level(s), " + std::to_string(numPieces) + " pieces";
        EXPECT_EQ(messages.NumErrors, 0) << where << ": " << messages.Errors;
        EXPECT_EQ(total, serial->GetNumberOfPolys()) << where;
        EXPECT_EQ(ComparePieces(serial, raw, Tolerance(serial), scheme.SameCellData), "") << where;
      }
    }
  }
}

// More pieces than cells: some pieces are empty (no error, empty output), and one filter
// asked for every piece in turn (re-executing on each new piece) still gives the serial union.
TEST_P(Pieces, EmptyPiecesAndOneFilterForAllPieces)
{
  const SchemeCase scheme = Schemes()[GetParam()];
  PieceTestCase test{ "cube", scheme.Triangles ? Cube().Triangulated() : Cube(), 4, false };
  vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
  Messages serialMessages;
  vtkSmartPointer<vtkPolyData> serial = RunPiece(scheme, input, 2, 0, 1, serialMessages);
  const int numPieces = 2 * static_cast<int>(input->GetNumberOfCells());
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(input);
  vtkNew<vtkExtractPolyDataPiece> extract;
  extract->SetInputConnection(producer->GetOutputPort());
  vtkSmartPointer<vtkSubDSurfaceFilter> filter = scheme.Make();
  filter->SetInputConnection(extract->GetOutputPort());
  filter->SetNumberOfSubdivisions(2);
  filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  Messages messages;
  messages.Watch(filter);
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  std::vector<vtkPolyData*> raw;
  int empty = 0;
  for (int p = 0; p < numPieces; ++p)
  {
    filter->UpdatePiece(p, numPieces, 0);
    pieces.push_back(vtkSmartPointer<vtkPolyData>::New());
    pieces.back()->DeepCopy(filter->GetOutput());
    raw.push_back(pieces.back());
    empty += pieces.back()->GetNumberOfCells() == 0;
  }
  EXPECT_GT(empty, 0);
  EXPECT_EQ(messages.NumErrors, 0) << messages.Errors;
  EXPECT_EQ(ComparePieces(serial, raw, Tolerance(serial), scheme.SameCellData), "");
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Pieces, ::testing::Range(0, 7),
  [](const ::testing::TestParamInfo<int>& info) {
    std::string name = Schemes()[info.param].Name;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
  });
}
