// ComparePieceFiles serial.vtp pieces.pvtp: exit 0 when the pieces a .pvtp names (as subd-mpi
// writes them) are together the serial mesh (SubDPieceComparison.h: faces, points and point
// data to 1e-12 relative to its size, crease lines); else prints the first difference.
#include "SubDPieceComparison.h"

#include "vtkXMLPPolyDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <cstdio>

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::fprintf(stderr, "usage: ComparePieceFiles serial.vtp pieces.pvtp\n");
    return 2;
  }
  vtkNew<vtkXMLPolyDataReader> serialReader;
  serialReader->SetFileName(argv[1]);
  serialReader->Update();
  vtkPolyData* serial = serialReader->GetOutput();
  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(argv[2]);
  reader->UpdateInformation();
  const int numPieces = reader->GetNumberOfPieces();
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  std::vector<vtkPolyData*> raw;
  for (int p = 0; p < numPieces; ++p)
  {
    reader->UpdatePiece(p, numPieces, 0);
    pieces.push_back(vtkSmartPointer<vtkPolyData>::New());
    pieces.back()->DeepCopy(reader->GetOutput());
    raw.push_back(pieces.back());
  }
  if (serial->GetNumberOfPolys() == 0 || numPieces < 2)
  {
    std::fprintf(stderr, "ComparePieceFiles: %lld serial faces, %d pieces\n",
      static_cast<long long>(serial->GetNumberOfPolys()), numPieces);
    return 1;
  }
  const std::string why = subdtest::ComparePieces(serial, raw, 1e-12 * std::max(1.0, serial->GetLength()), false);
  if (!why.empty())
  {
    std::fprintf(stderr, "ComparePieceFiles: %s\n", why.c_str());
    return 1;
  }
  std::printf("%d pieces together are the serial mesh (%lld faces)\n", numPieces,
    static_cast<long long>(serial->GetNumberOfPolys()));
  return 0;
}
