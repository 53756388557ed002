// Subdivision in pieces across MPI ranks (run by ctest under mpirun -np 2 and -np 3): every
// rank subdivides its piece of each test mesh (vtkExtractPolyDataPiece with the ghost levels
// the filter asks for) with every surface scheme at 1..3 levels and sends the result to rank
// 0, which compares the pieces with the serial output (SubDPieceComparison.h): same faces,
// points and point data to 1e-12, the same crease lines. Exit status 0 only if every case
// matches on every rank.
#include "SubDPieceComparison.h"
#include "SubDPieceTestInputs.h"

#include "vtkExtractPolyDataPiece.h"
#include "vtkMPIController.h"
#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"
#include "vtkTrivialProducer.h"

#include <cstdio>
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
  bool SameCellData; // see TestPieces.cxx
};

template <typename T>
SchemeCase Scheme(const char* name, bool triangles, bool sameCellData = true)
{
  return { name, [] { return vtkSmartPointer<T>::New(); }, triangles, sameCellData };
}

vtkSmartPointer<vtkPolyData> Subdivide(
  const SchemeCase& scheme, vtkPolyData* input, int levels, int piece, int numPieces, int& errors)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(input);
  vtkNew<vtkExtractPolyDataPiece> extract;
  extract->SetInputConnection(producer->GetOutputPort());
  vtkSmartPointer<vtkSubDSurfaceFilter> filter = scheme.Make();
  filter->SetInputConnection(extract->GetOutputPort());
  filter->SetNumberOfSubdivisions(levels);
  filter->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  Messages messages;
  messages.Watch(filter);
  filter->UpdatePiece(piece, numPieces, 0);
  errors += messages.NumErrors;
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}
}

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  const int rank = controller->GetLocalProcessId();
  const int numRanks = controller->GetNumberOfProcesses();
  const std::vector<SchemeCase> schemes{ Scheme<vtkSubDCatmullClarkFilter>("catmull-clark", false),
    Scheme<vtkSubDLoopFilter>("loop", true), Scheme<vtkSubDButterflyFilter>("butterfly", true),
    Scheme<vtkSubDLinearFilter>("linear", true), Scheme<vtkSubDSqrt3Filter>("sqrt3", true),
    Scheme<vtkSubDDooSabinFilter>("doo-sabin", false, false),
    Scheme<vtkSubDMidpointFilter>("midpoint", false, false) };
  int failures = 0, cases = 0;
  int tag = 1000;
  for (const SchemeCase& scheme : schemes)
  {
    for (const PieceTestCase& test : PieceTestCases(scheme.Triangles))
    {
      vtkSmartPointer<vtkPolyData> input = PieceTestInput(test);
      for (int levels = 1; levels <= 3; ++levels, ++tag)
      {
        int errors = 0;
        vtkSmartPointer<vtkPolyData> mine = Subdivide(scheme, input, levels, rank, numRanks, errors);
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
          pieces.push_back(piece);
          raw.push_back(piece);
        }
        int serialErrors = 0;
        vtkSmartPointer<vtkPolyData> serial = Subdivide(scheme, input, levels, 0, 1, serialErrors);
        std::string why = ComparePieces(serial, raw, 1e-12 * std::max(1.0, serial->GetLength()), scheme.SameCellData);
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
    std::printf("%d of %d cases on %d ranks: the pieces' union is the serial output\n", cases - failures, cases,
      numRanks);
  }
  controller->Finalize();
  return failures == 0 ? 0 : 1;
}
