// Subdivision in pieces across MPI ranks (run by ctest under mpirun -np 2 and -np 3): every
// rank subdivides its piece of each test mesh (vtkExtractPolyDataPiece with the ghost levels
// the filter asks for) with every surface scheme at 1..3 levels and sends the result to rank
// 0, which compares the pieces with the serial output (SubDPieceComparison.h): same faces,
// points and point data to 1e-12, the same crease lines. A single quad leaves ranks without a
// cell. Exit status 0 only if every case matches on every rank.
#include "SubDPieceComparison.h"
#include "SubDPieceTestCases.h"

#include "vtkMPIController.h"

#include <cstdio>
#include <string>

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  const int numRanks = controller->GetNumberOfProcesses();
  int failures = 0, cases = 0, emptyPieces = 0;
  int tag = 1000;
  for (const subdtest::PieceScheme& scheme : subdtest::PieceSchemes())
  {
    // The four meshes, and a single quad (two triangles), which leaves pieces without a cell.
    std::vector<subdtest::PieceTestCase> tests = subdtest::PieceTestCases(scheme.Triangles);
    const subdtest::TestMesh quad = subdtest::Grid(1, 1, false, false);
    tests.push_back({ "one-quad", scheme.Triangles ? quad.Triangulated() : quad, 2, false });
    for (const subdtest::PieceTestCase& test : tests)
    {
      vtkSmartPointer<vtkPolyData> input = subdtest::PieceTestInput(test);
      for (int levels = 1; levels <= 3; ++levels, ++tag)
      {
        int errors = 0;
        vtkSmartPointer<vtkPolyData> mine = subdtest::SubdividePiece(scheme, input, levels, rank, numRanks, errors);
        if (rank != 0)
        {
          controller->Send(mine, 0, tag);
          controller->Send(&errors, 1, 0, tag);
          continue;
        }
        std::vector<vtkSmartPointer<vtkPolyData>> pieces{ mine };
        std::vector<vtkPolyData*> raw{ mine };
        for (int r = 1; r < numRanks; ++r)
        {
          auto piece = vtkSmartPointer<vtkPolyData>::New();
          controller->Receive(piece, r, tag);
          int remoteErrors = 0;
          controller->Receive(&remoteErrors, 1, r, tag);
          errors += remoteErrors;
          emptyPieces += piece->GetNumberOfCells() == 0;
          pieces.push_back(piece);
          raw.push_back(piece);
        }
        int serialErrors = 0;
        vtkSmartPointer<vtkPolyData> serial = subdtest::SubdividePiece(scheme, input, levels, 0, 1, serialErrors);
        std::string why =
          subdtest::ComparePieces(serial, raw, subdtest::PieceTolerance(serial), scheme.SameCellData);
        if (errors + serialErrors > 0)
        {
          why += " (" + std::to_string(errors + serialErrors) + " filter errors)";
        }
        if (serial->GetNumberOfPolys() == 0)
        {
          why += " (empty serial output)";
        }
        ++cases;
        if (!why.empty())
        {
          ++failures;
          std::printf("FAIL %s %s, %d level(s), %d ranks: %s\n", scheme.Name, test.Name.c_str(), levels, numRanks,
            why.c_str());
        }
      }
    }
  }
  controller->Broadcast(&failures, 1, 0);
  if (rank == 0)
  {
    std::printf("%d of %d cases on %d ranks (%d empty pieces): the pieces' union is the serial output\n",
      cases - failures, cases, numRanks, emptyPieces);
  }
  controller->Finalize();
  return failures == 0 ? 0 : 1;
}
