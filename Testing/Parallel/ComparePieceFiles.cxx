// ComparePieceFiles serial.vtp pieces.pvtp [options]: exit 0 when the pieces a .pvtp names (as
// subd-mpi or ParaView writes them) are together the serial mesh (SubDPieceComparison.h: faces,
// points and point data to 1e-12 relative to its size, crease lines), not counting ghost cells,
// which must be serial faces too, and every piece must own faces; else prints the first
// difference. Point arrays a pipeline added on the way (ParaView's vtkOriginalPointIds) are
// not compared. Options:
//   --same-arrays        every piece must hold exactly the serial point-data arrays (names and
//                        components; vtkGhostType aside)
//   --presence-only A,B  these arrays must be in every piece, their values are not compared:
//                        the limit geometry where it is not defined alike in a piece (a cone
//                        point's normal, curvature at or next to an extraordinary vertex, which
//                        the filter takes from whichever of its faces comes first, principal
//                        directions at nearly umbilic points)
//   --tolerance R        R instead of 1e-12 (curvature, a second derivative, amplifies the
//                        round-off of the points' sums, which differ between piece and whole)
#include "SubDPieceComparison.h"

#include "vtkPointData.h"
#include "vtkXMLPPolyDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>

namespace
{
struct Options
{
  bool SameArrays = false;
  std::set<std::string> PresenceOnly;
  double Tolerance = 1e-12;
};

std::set<std::string> SplitNames(const std::string& text)
{
  std::set<std::string> names;
  std::istringstream in(text);
  for (std::string name; std::getline(in, name, ',');)
  {
    names.insert(name);
  }
  return names;
}

bool ParseOptions(int argc, char* argv[], Options& options)
{
  for (int i = 3; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--same-arrays")
    {
      options.SameArrays = true;
    }
    else if (arg == "--presence-only" && i + 1 < argc)
    {
      options.PresenceOnly = SplitNames(argv[++i]);
    }
    else if (arg == "--tolerance" && i + 1 < argc)
    {
      char* end = nullptr;
      options.Tolerance = std::strtod(argv[++i], &end);
      if (*end != '\0' || !(options.Tolerance > 0.0))
      {
        return false;
      }
    }
    else
    {
      return false;
    }
  }
  return true;
}

// "" when `piece` holds the point-data arrays `options` asks of it (see the top), else what
// is missing or extra.
std::string CheckArrays(vtkPolyData* serial, vtkPolyData* piece, const Options& options)
{
  vtkPointData* expected = serial->GetPointData();
  vtkPointData* got = piece->GetPointData();
  for (int a = 0; a < expected->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = expected->GetArray(a);
    vtkDataArray* same = array ? got->GetArray(array->GetName()) : nullptr;
    if (array && (!same || same->GetNumberOfComponents() != array->GetNumberOfComponents()))
    {
      return std::string("no point-data array \"") + array->GetName() + "\" of " +
        std::to_string(array->GetNumberOfComponents()) + " components";
    }
  }
  for (const std::string& name : options.PresenceOnly)
  {
    if (!expected->GetArray(name.c_str()))
    {
      return "the serial mesh has no point-data array \"" + name + "\"";
    }
  }
  for (int a = 0; options.SameArrays && a < got->GetNumberOfArrays(); ++a)
  {
    const char* name = got->GetArrayName(a);
    if (name && !expected->HasArray(name) && std::string(name) != "vtkGhostType")
    {
      return std::string("point-data array \"") + name + "\", which the serial mesh does not have";
    }
  }
  return "";
}

// Drops the point arrays not compared: those the serial mesh lacks (unless kept for
// --same-arrays, already checked) and the --presence-only ones.
void DropUncompared(vtkPolyData* mesh, vtkPolyData* serial, const Options& options)
{
  vtkPointData* pd = mesh->GetPointData();
  for (int a = pd->GetNumberOfArrays() - 1; a >= 0; --a)
  {
    const char* name = pd->GetArrayName(a);
    if (name && ((!serial->GetPointData()->HasArray(name) && std::string(name) != "vtkGhostType") ||
                  options.PresenceOnly.count(name)))
    {
      pd->RemoveArray(a);
    }
  }
}
}

int main(int argc, char* argv[])
{
  Options options;
  if (argc < 3 || !ParseOptions(argc, argv, options))
  {
    std::fprintf(stderr, "usage: ComparePieceFiles serial.vtp pieces.pvtp [--same-arrays] [--presence-only A,B,...] "
                         "[--tolerance R]\n");
    return 2;
  }
  vtkNew<vtkXMLPolyDataReader> serialReader;
  serialReader->SetFileName(argv[1]);
  serialReader->Update();
  vtkSmartPointer<vtkPolyData> serial = vtkSmartPointer<vtkPolyData>::New();
  serial->DeepCopy(serialReader->GetOutput());
  const double tolerance = options.Tolerance * std::max(1.0, serial->GetLength());
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
    vtkPolyData* piece = reader->GetOutput();
    const std::string wrongArrays = CheckArrays(serial, piece, options);
    if (!wrongArrays.empty())
    {
      std::fprintf(stderr, "ComparePieceFiles: piece %d: %s\n", p, wrongArrays.c_str());
      return 1;
    }
    DropUncompared(piece, serial, options);
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
  DropUncompared(serial, serial, options);
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
  std::string compared;
  for (int a = 0; a < serial->GetPointData()->GetNumberOfArrays(); ++a)
  {
    compared += std::string(compared.empty() ? "" : ", ") + serial->GetPointData()->GetArrayName(a);
  }
  std::printf("%d pieces together are the serial mesh (%lld faces; point data compared: %s)\n", numPieces,
    static_cast<long long>(serial->GetNumberOfPolys()), compared.empty() ? "none" : compared.c_str());
  return 0;
}
