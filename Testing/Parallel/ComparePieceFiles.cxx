// ComparePieceFiles serial.vtp pieces.pvtp: exit 0 when the pieces a .pvtp names (as subd-mpi
// or ParaView writes them) are together the serial mesh (SubDPieceComparison.h: faces, points
// and point data to 1e-12 relative to its size, crease lines), not counting ghost cells, which
// must be serial faces too, and every piece must own faces; else prints the first difference.
#include "SubDPieceComparison.h"

#include "vtkPointData.h"
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
  const double tolerance = 1e-12 * std::max(1.0, serial->GetLength());
  vtkNew<vtkXMLPPolyDataReader> reader;
  reader->SetFileName(argv[2]);
  reader->UpdateInformation();
  const int numPieces = reader->GetNumberOfPieces();
  std::vector<vtkSmartPointer<vtkPolyData>> pieces, ghosts;
  std::vector<vtkPolyData*> raw;
  for (int p = 0; p < numPieces; ++p)
  {
    reader->UpdatePiece(p, numPieces, 0);
    // Ghost cells (a writer asked for ghost levels, as ParaView's parallel runs do) are copies
    // of other pieces' cells: the comparison is of the rest, and they must be serial faces.
    // Point arrays a pipeline added on the way (ParaView's vtkOriginalPointIds) are not compared.
    vtkPolyData* piece = reader->GetOutput();
    for (int a = piece->GetPointData()->GetNumberOfArrays() - 1; a >= 0; --a)
    {
      const char* name = piece->GetPointData()->GetArrayName(a);
      if (name && !serial->GetPointData()->HasArray(name) && std::string(name) != "vtkGhostType")
      {
        piece->GetPointData()->RemoveArray(a);
      }
    }
    pieces.push_back(subdtest::CellsByGhostMark(piece, false));
    ghosts.push_back(subdtest::CellsByGhostMark(piece, true));
    raw.push_back(pieces.back());
    // A piece without faces of its own would leave the seams untested.
    if (pieces.back()->GetNumberOfPolys() == 0)
    {
      std::fprintf(stderr, "ComparePieceFiles: piece %d has no faces of its own\n", p);
      return 1;
    }
  }
  if (serial->GetNumberOfPolys() == 0 || numPieces < 2)
  {
    std::fprintf(stderr, "ComparePieceFiles: %lld serial faces, %d pieces\n",
      static_cast<long long>(serial->GetNumberOfPolys()), numPieces);
    return 1;
  }
  vtkIdType lines = 0; // each crease line in one piece only, those on seams too
  for (vtkPolyData* piece : raw)
  {
    lines += piece->GetNumberOfLines();
  }
  if (lines != serial->GetNumberOfLines())
  {
    std::fprintf(stderr, "ComparePieceFiles: the pieces own %lld crease lines, serially %lld\n",
      static_cast<long long>(lines), static_cast<long long>(serial->GetNumberOfLines()));
    return 1;
  }
  const std::string why = subdtest::ComparePieces(serial, raw, tolerance, false);
  if (!why.empty())
  {
    std::fprintf(stderr, "ComparePieceFiles: %s\n", why.c_str());
    return 1;
  }
  for (int p = 0; p < numPieces; ++p)
  {
    const std::string wrong = subdtest::FacesAreAmong(serial, ghosts[p], tolerance, false);
    if (!wrong.empty())
    {
      std::fprintf(stderr, "ComparePieceFiles: the pieces' own cells are the serial mesh, but piece %d's ghost "
                           "cells are not serial cells: %s\n", p, wrong.c_str());
      return 1;
    }
  }
  std::printf("%d pieces together are the serial mesh (%lld faces)\n", numPieces,
    static_cast<long long>(serial->GetNumberOfPolys()));
  return 0;
}
