// subd-mpi: subdivision of a mesh split over MPI ranks, each rank one piece.
//
//   mpirun -np N subd-mpi [--scheme NAME] [--levels L] [--boundary RULE] [--limit]
//                         [--builtin CAGE | INPUT] OUTPUT.pvtp
//
// Every rank reads the input (or builds the built-in cage) and keeps its piece: a run of
// polygons in Z order of their centroids, so that pieces are compact patches of the surface
// (vtkExtractPolyDataPiece cuts runs of cell ids, and a file's cell order is often scattered),
// plus the layers of ghost cells the scheme needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels). It subdivides the piece, which outputs the
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
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkCellArray.h"
#include "vtkLogger.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSubDSurfaceFilter.h"
#include "vtkXMLPPolyDataWriter.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>
#include <thread>
#include <sys/resource.h>

namespace
{
const char* const Usage =
  "usage: mpirun -np N subd-mpi [--scheme NAME] [--levels L] [--boundary RULE] [--limit]\n"
  "                             [--threads T] [--builtin CAGE | INPUT] OUTPUT.pvtp\n"
  "  --scheme NAME     a surface scheme of `subd --help` (default catmull-clark)\n"
  "  --levels L        subdivision levels (default 2)\n"
  "  --boundary RULE   edge-only (default), edge-and-corner or none\n"
  "  --limit           move the output points to the limit surface\n"
  "  --threads T       threads per rank (default: the cores shared by the ranks on a node)\n"
  "  --builtin CAGE    subdivide a built-in cage instead of a file (default cube)\n"
  "Each rank writes its piece as OUTPUT_<rank>.vtp; rank 0 writes OUTPUT.pvtp naming them.\n";

struct Arguments
{
  std::string Scheme = "catmull-clark";
  subdapp::SchemeOptions Options;
  std::string Builtin = "cube";
  std::string Input, Output;
  int Threads = 0; // 0: the node's cores over its ranks
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
    // The value of option `a` as an integer in [lo, hi].
    auto integer = [&](const std::string& text, long lo, long hi, int& out) {
      char* end = nullptr;
      const long number = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || number < lo || number > hi)
      {
        error = a + " wants an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not '" + text + "'";
        return false;
      }
      out = static_cast<int>(number);
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
      if (!value(v) || !integer(v, 0, 30, args.Options.Levels))
        return false;
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
    else if (a == "--threads")
    {
      if (!value(v) || !integer(v, 1, 1024, args.Threads))
        return false;
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

// Threads for this rank: the node's cores shared among the ranks on it (Open MPI tells their
// number), so that ranks on one machine do not oversubscribe its cores.
int DefaultThreads()
{
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int ranksHere = local ? std::max(1, std::atoi(local)) : 1;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / ranksHere);
}

// Interleaves the bits of three 21-bit integers: the Z-order (Morton) key.
std::uint64_t MortonKey(const double p[3], const double lo[3], const double scale[3])
{
  std::uint64_t key = 0;
  std::uint32_t q[3];
  for (int k = 0; k < 3; ++k)
  {
    q[k] = static_cast<std::uint32_t>(std::min(2097151.0, std::max(0.0, (p[k] - lo[k]) * scale[k])));
  }
  for (int bit = 20; bit >= 0; --bit)
  {
    for (int k = 0; k < 3; ++k)
    {
      key = (key << 1) | ((q[k] >> bit) & 1u);
    }
  }
  return key;
}

// `mesh` with its polygons in Z order of their centroids (verts, lines and strips as they are,
// cell data following its cells) and each cell's id in `mesh` as the cell-data array
// `globalIdName`, so that pieces can tell faces apart the same way whatever the order.
// The cell-data array that carries the input's cell ids through the pieces.
const char* const GlobalIdName = "SubDGlobalCellIds";

vtkSmartPointer<vtkPolyData> OrderPolygonsSpatially(vtkPolyData* mesh, const char* globalIdName)
{
  double bounds[6];
  mesh->GetBounds(bounds);
  double lo[3], scale[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = bounds[2 * k];
    scale[k] = bounds[2 * k + 1] > bounds[2 * k] ? 2097151.0 / (bounds[2 * k + 1] - bounds[2 * k]) : 0.0;
  }
  const vtkIdType firstPoly = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  const vtkIdType numPolys = mesh->GetNumberOfPolys();
  std::vector<std::pair<std::uint64_t, vtkIdType>> order;
  order.reserve(static_cast<size_t>(numPolys));
  vtkIdType n;
  const vtkIdType* pts;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
  {
    double centroid[3] = { 0, 0, 0 }, p[3];
    for (vtkIdType k = 0; k < n; ++k)
    {
      mesh->GetPoint(pts[k], p);
      for (int c = 0; c < 3; ++c)
        centroid[c] += p[c] / n;
    }
    order.emplace_back(MortonKey(centroid, lo, scale), static_cast<vtkIdType>(order.size()));
  }
  std::stable_sort(order.begin(), order.end());
  vtkNew<vtkCellArray> sorted;
  vtkNew<vtkIdList> cell;
  auto ordered = vtkSmartPointer<vtkPolyData>::New();
  ordered->SetPoints(mesh->GetPoints());
  ordered->GetPointData()->ShallowCopy(mesh->GetPointData());
  ordered->SetVerts(mesh->GetVerts());
  ordered->SetLines(mesh->GetLines());
  for (const auto& entry : order)
  {
    polys->GetCellAtId(entry.second, cell);
    sorted->InsertNextCell(cell);
  }
  ordered->SetPolys(sorted);
  ordered->SetStrips(mesh->GetStrips());
  // Cell data in VTK's cell order: verts and lines, the polygons in their new order, strips.
  const vtkIdType numCells = mesh->GetNumberOfCells();
  vtkNew<vtkIdList> from;
  from->SetNumberOfIds(numCells);
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    const bool poly = c >= firstPoly && c < firstPoly + numPolys;
    from->SetId(c, poly ? firstPoly + order[c - firstPoly].second : c);
  }
  vtkNew<vtkIdList> to;
  to->SetNumberOfIds(numCells);
  std::iota(to->GetPointer(0), to->GetPointer(0) + numCells, 0);
  ordered->GetCellData()->CopyAllocate(mesh->GetCellData(), numCells);
  ordered->GetCellData()->CopyData(mesh->GetCellData(), from, to);
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(globalIdName);
  ids->SetNumberOfTuples(numCells);
  std::copy(from->GetPointer(0), from->GetPointer(0) + numCells, ids->GetPointer(0));
  ordered->GetCellData()->AddArray(ids);
  return ordered;
}

// The piece of `mesh` for this rank, with `ghostLevels` layers of ghost cells. The coordinates
// travel as point data and the global cell ids as a plain array, which vtkExtractPolyDataPiece
// copies exactly (it would store the points in single precision and drop the GlobalIds
// attribute); the piece gets them back as its points and its GlobalIds.
vtkSmartPointer<vtkPolyData> ExtractPiece(vtkPolyData* mesh, int rank, int numRanks, int ghostLevels)
{
  const char* const name = "SubDExactCoordinates";
  vtkSmartPointer<vtkPolyData> source = OrderPolygonsSpatially(mesh, GlobalIdName);
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
  piece->GetCellData()->SetGlobalIds(piece->GetCellData()->GetArray(GlobalIdName));
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
    return fail(error + " (see --help)", 2);
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

  const int threads = args.Threads > 0 ? args.Threads : DefaultThreads();
  if (threads == 1)
  {
    vtkSMPTools::SetBackend("Sequential"); // no thread pool at all (TBB would warn about one of 0)
  }
  vtkSMPTools::Initialize(threads);
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = entry->Make(args.Options);
  vtkSubDSurfaceFilter* filter = vtkSubDSurfaceFilter::SafeDownCast(algorithm);
  vtkSmartPointer<vtkPolyData> piece = ExtractPiece(mesh, rank, numRanks, filter->GetRequiredGhostLevels());
  mesh = nullptr; // only the piece is kept
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(piece);
  filter->UpdatePiece(rank, numRanks, 0);
  const std::string prefix = "subd-mpi: rank " + std::to_string(rank) + ": ";
  subdapp::PrintMessageLines(prefix, messages.Warnings, "warning");
  subdapp::PrintMessageLines(prefix, messages.Errors, "error");
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
  // The output as the serial one: without the ids the pieces agreed by.
  vtkNew<vtkPolyData> result;
  result->ShallowCopy(filter->GetOutput());
  result->GetCellData()->RemoveArray(GlobalIdName);
  writer->SetInputData(result);
  writer->SetFileName(args.Output.c_str());
  writer->SetNumberOfPieces(numRanks);
  writer->SetStartPiece(rank);
  writer->SetEndPiece(rank);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff(); // raw bytes: compressing and encoding cost more than writing
  writer->SetCompressorTypeToNone();
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
