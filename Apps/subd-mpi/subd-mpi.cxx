// subd-mpi: subdivision of a mesh split over MPI ranks, each rank one piece.
//
//   mpirun -np N subd-mpi [--scheme NAME] [--levels L] [--boundary RULE] [--limit]
//                         [--builtin CAGE | INPUT] OUTPUT.pvtp
//
// Every rank reads the input (or builds the built-in cage) and keeps its piece: a band of
// cells by id (vtkExtractPolyDataPiece) plus the layers of ghost cells the scheme needs
// (vtkSubDSurfaceFilter::GetRequiredGhostLevels). It subdivides the piece, which outputs the
// children of its own cells only, and writes them as OUTPUT_<rank>.vtp beside OUTPUT.pvtp,
// which rank 0 writes and which names every piece: ParaView or vtkXMLPPolyDataReader read
// them as one mesh, equal to the serial `subd` output. Rank 0 prints a summary.
//
// Memory: each rank holds the whole input while cutting out its piece, then only its piece
// and its output (see Documentation in README, "MPI"): the subdivided levels, which are what
// grows, are split across ranks.
#include "SubDBuiltinCages.h"
#include "SubDMeshIO.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExtractPolyDataPiece.h"
#include "vtkLogger.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSubDSurfaceFilter.h"
#include "vtkXMLPPolyDataWriter.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>

namespace
{
const char* const Usage =
  "usage: mpirun -np N subd-mpi [--scheme NAME] [--levels L] [--boundary RULE] [--limit]\n"
  "                             [--builtin CAGE | INPUT] OUTPUT.pvtp\n"
  "  --scheme NAME     a surface scheme of `subd --help` (default catmull-clark)\n"
  "  --levels L        subdivision levels (default 2)\n"
  "  --boundary RULE   edge-only (default), edge-and-corner or none\n"
  "  --limit           move the output points to the limit surface\n"
  "  --builtin CAGE    subdivide a built-in cage instead of a file (default cube)\n"
  "Each rank writes its piece as OUTPUT_<rank>.vtp; rank 0 writes OUTPUT.pvtp naming them.\n";

struct Arguments
{
  std::string Scheme = "catmull-clark";
  subdapp::SchemeOptions Options;
  std::string Builtin = "cube";
  std::string Input, Output;
  bool Help = false;
};

bool Parse(int argc, char* argv[], Arguments& args, std::string& error)
{
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (i + 1 >= argc)
      {
        error = a + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help")
    {
      args.Help = true;
    }
    else if (a == "--scheme")
    {
      if (!value(args.Scheme))
        return false;
    }
    else if (a == "--builtin")
    {
      if (!value(args.Builtin))
        return false;
    }
    else if (a == "--levels")
    {
      if (!value(v))
        return false;
      char* end = nullptr;
      const long levels = std::strtol(v.c_str(), &end, 10);
      if (*end != '\0' || levels < 0 || levels > 30)
      {
        error = "--levels wants an integer from 0 to 30, not '" + v + "'";
        return false;
      }
      args.Options.Levels = static_cast<int>(levels);
    }
    else if (a == "--boundary")
    {
      if (!value(v))
        return false;
      const char* rules[] = { "none", "edge-only", "edge-and-corner" };
      int rule = -1;
      for (int r = 0; r < 3; ++r)
        rule = v == rules[r] ? r : rule;
      if (rule < 0)
      {
        error = "--boundary wants none, edge-only or edge-and-corner, not '" + v + "'";
        return false;
      }
      args.Options.BoundaryRule = rule;
    }
    else if (a == "--limit")
    {
      args.Options.ProjectToLimit = true;
    }
    else if (!a.empty() && a[0] == '-')
    {
      error = "unknown option " + a;
      return false;
    }
    else
    {
      positional.push_back(a);
    }
  }
  if (args.Help)
  {
    return true;
  }
  if (positional.empty() || positional.size() > 2)
  {
    error = "give the output file (and optionally an input file before it)";
    return false;
  }
  args.Output = positional.back();
  args.Input = positional.size() == 2 ? positional[0] : "";
  if (subdapp::LowerExtension(args.Output) != ".pvtp")
  {
    error = "the output must be a .pvtp file (one piece per rank), not '" + args.Output + "'";
    return false;
  }
  return true;
}

// Prints each line of `lines` as "subd-mpi: rank R: <kind>: <line>".
void PrintMessages(int rank, const std::string& lines, const char* kind)
{
  std::istringstream in(lines);
  std::string line;
  while (std::getline(in, line))
  {
    if (!line.empty())
    {
      std::cerr << "subd-mpi: rank " << rank << ": " << kind << ": " << line << "\n";
    }
  }
}

// The piece of `mesh` for this rank, with `ghostLevels` layers of ghost cells. The coordinates
// travel as point data, which vtkExtractPolyDataPiece copies exactly (it would store the points
// themselves in single precision).
vtkSmartPointer<vtkPolyData> ExtractPiece(vtkPolyData* mesh, int rank, int numRanks, int ghostLevels)
{
  const char* const name = "SubDExactCoordinates";
  vtkNew<vtkPolyData> source;
  source->ShallowCopy(mesh);
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetName(name);
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(mesh->GetNumberOfPoints());
  for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
  {
    mesh->GetPoint(p, coordinates->GetPointer(3 * p));
  }
  source->GetPointData()->AddArray(coordinates);
  vtkNew<vtkExtractPolyDataPiece> extract;
  extract->SetInputData(source);
  extract->UpdatePiece(rank, numRanks, ghostLevels);
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  piece->ShallowCopy(extract->GetOutput());
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints() ? mesh->GetPoints()->GetDataType() : VTK_DOUBLE);
  vtkDataArray* exact = piece->GetPointData()->GetArray(name);
  points->SetNumberOfPoints(piece->GetNumberOfPoints());
  for (vtkIdType p = 0; exact && p < piece->GetNumberOfPoints(); ++p)
  {
    points->SetPoint(p, exact->GetTuple3(p));
  }
  piece->SetPoints(points);
  piece->GetPointData()->RemoveArray(name);
  return piece;
}
}

int main(int argc, char* argv[])
{
  vtkNew<subdapp::QuietOutputWindow> outputWindow;
  vtkOutputWindow::SetInstance(outputWindow);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // messages come through outputWindow
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  const int rank = controller->GetLocalProcessId();
  const int numRanks = controller->GetNumberOfProcesses();
  // Every rank decides alike (same arguments, same input), so all return the same status.
  auto finish = [&](int status) {
    controller->Finalize();
    return status;
  };
  auto fail = [&](const std::string& message, int status) {
    if (rank == 0)
    {
      std::cerr << "subd-mpi: " << message << "\n";
    }
    return finish(status);
  };

  Arguments args;
  std::string error;
  if (!Parse(argc, argv, args, error))
  {
    return fail(error + "\n" + Usage, 2);
  }
  if (args.Help)
  {
    if (rank == 0)
      std::cout << Usage;
    return finish(0);
  }
  const subdapp::SchemeEntry* entry = subdapp::FindScheme(args.Scheme);
  if (!entry || entry->Curve)
  {
    return fail("'" + args.Scheme + "' is not a surface scheme (see subd --help)", 2);
  }
  vtkSmartPointer<vtkPolyData> mesh =
    args.Input.empty() ? subdapp::MakeBuiltinCage(args.Builtin) : subdapp::ReadMesh(args.Input, error);
  if (!mesh)
  {
    return fail(args.Input.empty() ? "no built-in cage named '" + args.Builtin + "'" : error, 1);
  }

  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = entry->Make(args.Options);
  vtkSubDSurfaceFilter* filter = vtkSubDSurfaceFilter::SafeDownCast(algorithm);
  vtkSmartPointer<vtkPolyData> piece = ExtractPiece(mesh, rank, numRanks, filter->GetRequiredGhostLevels());
  mesh = nullptr; // only the piece is kept
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(piece);
  filter->UpdatePiece(rank, numRanks, 0);
  PrintMessages(rank, messages.Warnings, "warning");
  PrintMessages(rank, messages.Errors, "error");
  int failed = filter->GetErrorCode() != 0 || !messages.Errors.empty() ? 1 : 0;
  int anyFailed = 0;
  controller->AllReduce(&failed, &anyFailed, 1, vtkCommunicator::MAX_OP);
  if (anyFailed)
  {
    std::cerr << "subd-mpi: rank " << rank << ": " << (failed ? "subdivision failed" : "stopping") << "\n";
    return finish(1);
  }

  const double subdivideSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  vtkNew<vtkXMLPPolyDataWriter> writer;
  writer->SetController(controller);
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetFileName(args.Output.c_str());
  writer->SetNumberOfPieces(numRanks);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetDataModeToAppended();
  failed = writer->Write() == 1 ? 0 : 1;
  controller->AllReduce(&failed, &anyFailed, 1, vtkCommunicator::MAX_OP);
  if (anyFailed)
  {
    return fail("cannot write " + args.Output, 1);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  long long counts[3] = { filter->GetOutput()->GetNumberOfPolys(), filter->GetOutput()->GetNumberOfPoints(),
    piece->GetNumberOfPolys() };
  long long totals[3] = { 0, 0, 0 };
  controller->Reduce(counts, totals, 3, vtkCommunicator::SUM_OP, 0);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  // Slowest rank's times, largest rank's peak memory (MiB).
  const double mine[3] = { subdivideSeconds, seconds, usage.ru_maxrss / 1024.0 };
  double worst[3] = { 0, 0, 0 };
  controller->Reduce(mine, worst, 3, vtkCommunicator::MAX_OP, 0);
  if (rank == 0)
  {
    std::printf("%s: %s, %d level(s) on %d ranks: %lld faces (%lld points, seams counted in each piece); "
                "pieces held %lld input faces with ghosts; piece and subdivision %.3f s, with writing %.3f s "
                "(slowest rank); peak memory %.1f MiB (largest rank)\n",
      args.Output.c_str(), entry->Name.c_str(), args.Options.Levels, numRanks, totals[0], totals[1], totals[2],
      worst[0], worst[1], worst[2]);
  }
  return finish(0);
}
