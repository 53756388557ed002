// subd-mpi: subdivision of a mesh split over MPI ranks, each rank one piece.
//
//   mpirun -np N subd-mpi [INPUT] [subd's surface options] [--threads T] [--output FILE.pvtp]
//
// The command line is subd's (SubDCommandLine, Program::SubdMpi): the surface options under the
// same names and defaults, creases from the input as subd reads them, --threads of its own;
// subd's pictures, curve options and --interpolate are refused by name.
//
// Every rank reads the input (or builds the built-in cage) and keeps its piece: a run of
// polygons in Z order of their centroids, so that pieces are compact patches of the surface
// (vtkExtractPolyDataPiece cuts runs of cell ids, and a file's cell order is often scattered),
// plus the layers of ghost cells the scheme needs (vtkSubDSurfaceFilter::GetRequiredGhostLevels).
// It subdivides the piece, which outputs the children of its own cells only, and writes them
// as FILE_<rank>.vtp beside FILE.pvtp, which rank 0 writes and which names every piece:
// ParaView or vtkXMLPPolyDataReader read them as one mesh, equal to the serial `subd` output
// for the same options. Rank 0 prints a summary.
//
// Memory: each rank holds the whole input while cutting out its piece, then only its piece
// and its output (see docs/pieces-and-mpi.md): the subdivided levels, which are what grows,
// are split across ranks.
#include "SubDBuiltinCages.h"
#include "SubDCommandLine.h"
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
#include "vtkVersion.h"
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

// The cell-data array that carries the input's cell ids through the pieces.
const char* const GlobalIdName = "SubDGlobalCellIds";

// `mesh` with its polygons in Z order of their centroids (verts, lines and strips as they are,
// cell data following its cells) and each cell's id in `mesh` as the cell-data array
// `globalIdName`, so that pieces can tell faces apart the same way whatever the order.
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

// The ranks of this run. Every rank decides alike (the same arguments, the same input), so
// all end with the same status.
struct Ranks
{
  vtkMPIController* Controller;
  int Rank;
  int Count;

  int Finish(int status)
  {
    this->Controller->Finalize();
    return status;
  }
  int Fail(const std::string& message, int status)
  {
    if (this->Rank == 0)
    {
      std::cerr << "subd-mpi: " << message << "\n";
    }
    return this->Finish(status);
  }
  /// Whether any rank failed; every rank must ask.
  bool AnyFailed(bool failed)
  {
    int mine = failed ? 1 : 0, any = 0;
    this->Controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
    return any != 0;
  }
};

// This rank's piece of `mesh` (released once the piece is cut out) subdivided with the scheme
// and options of `cmd`: the children of the piece's own cells, as the serial output holds
// them, or nullptr when any rank failed (its messages printed). `pieceFaces`: the input faces
// the piece held, ghost cells included.
vtkSmartPointer<vtkPolyData> SubdividePiece(
  const subdapp::CommandLine& cmd, vtkSmartPointer<vtkPolyData>& mesh, Ranks& ranks, long long& pieceFaces)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> algorithm = subdapp::FindScheme(cmd.Scheme)->Make(cmd.Options);
  vtkSubDSurfaceFilter* filter = vtkSubDSurfaceFilter::SafeDownCast(algorithm); // a surface scheme
  // At level 0 the filter asks for no ghost cells, but its limit points, normals and curvature
  // read the stencils of one level, and a crease line needs the faces on both of its sides: the
  // layers one level needs.
  filter->SetNumberOfSubdivisions(std::max(1, cmd.Options.Levels));
  const int ghostLevels = filter->GetRequiredGhostLevels();
  filter->SetNumberOfSubdivisions(cmd.Options.Levels);
  vtkSmartPointer<vtkPolyData> piece = ExtractPiece(mesh, ranks.Rank, ranks.Count, ghostLevels);
  mesh = nullptr; // only the piece is kept
  pieceFaces = piece->GetNumberOfPolys();
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(piece);
  filter->UpdatePiece(ranks.Rank, ranks.Count, 0);
  const std::string prefix = "subd-mpi: rank " + std::to_string(ranks.Rank) + ": ";
  subdapp::PrintMessageLines(prefix, messages.Warnings, "warning");
  subdapp::PrintMessageLines(prefix, messages.Errors, "error");
  const bool failed = filter->GetErrorCode() != 0 || !messages.Errors.empty();
  if (ranks.AnyFailed(failed))
  {
    std::cerr << prefix << (failed ? "subdivision failed" : "stopping") << "\n";
    return nullptr;
  }
  // The output as the serial one: without the ids the pieces agreed by.
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(filter->GetOutput());
  result->GetCellData()->RemoveArray(GlobalIdName);
  return result;
}

// Writes this rank's piece of the output as a .vtp (raw appended arrays as subd writes them,
// or zlib-compressed) and, on rank 0, the .pvtp `path` naming every piece. Every rank must
// call it; false when any rank failed (its messages printed).
bool WritePieces(vtkPolyData* result, const std::string& path, bool compress, Ranks& ranks)
{
  vtkNew<vtkXMLPPolyDataWriter> writer;
  subdapp::MessageCollector messages;
  messages.Watch(writer);
  writer->SetController(ranks.Controller);
  writer->SetInputData(result);
  writer->SetFileName(path.c_str());
  writer->SetNumberOfPieces(ranks.Count);
  writer->SetStartPiece(ranks.Rank);
  writer->SetEndPiece(ranks.Rank);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff(); // raw bytes: encoding costs more than writing
  if (compress)
  {
    writer->SetCompressorTypeToZLib();
  }
  else
  {
    writer->SetCompressorTypeToNone();
  }
  const bool failed = writer->Write() != 1 || !messages.Errors.empty();
  subdapp::PrintMessageLines("subd-mpi: rank " + std::to_string(ranks.Rank) + ": ", messages.Errors, "error");
  return !ranks.AnyFailed(failed);
}

// Rank 0's summary line (unless --quiet): the faces and points of all pieces, the slowest
// rank's times (`seconds`: piece and subdivision, then with writing), the largest rank's peak
// memory. Every rank must call it.
void PrintSummary(const subdapp::CommandLine& cmd, const std::string& path, vtkPolyData* result,
  long long pieceFaces, const double seconds[2], Ranks& ranks)
{
  if (cmd.Quiet)
  {
    return;
  }
  long long counts[3] = { result->GetNumberOfPolys(), result->GetNumberOfPoints(), pieceFaces };
  long long totals[3] = { 0, 0, 0 };
  ranks.Controller->Reduce(counts, totals, 3, vtkCommunicator::SUM_OP, 0);
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double mine[3] = { seconds[0], seconds[1], usage.ru_maxrss / 1024.0 };
  double worst[3] = { 0, 0, 0 };
  ranks.Controller->Reduce(mine, worst, 3, vtkCommunicator::MAX_OP, 0);
  if (ranks.Rank == 0)
  {
    std::printf("%s: %s, %d level(s) on %d ranks: %lld faces (%lld points, seams counted in each piece); "
                "pieces held %lld input faces with ghosts; piece and subdivision %.3f s, with writing %.3f s "
                "(slowest rank); peak memory %.1f MiB (largest rank)\n",
      path.c_str(), cmd.Scheme.c_str(), cmd.Options.Levels, ranks.Count, totals[0], totals[1], totals[2], worst[0],
      worst[1], worst[2]);
  }
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
  Ranks ranks{ controller, controller->GetLocalProcessId(), controller->GetNumberOfProcesses() };

  subdapp::CommandLine cmd;
  std::string error;
  if (!subdapp::ParseCommandLine(argc, argv, cmd, error, subdapp::Program::SubdMpi))
  {
    return ranks.Fail(error, 2);
  }
  for (const std::string& warning : cmd.Warnings)
  {
    if (ranks.Rank == 0)
    {
      std::cerr << "subd-mpi: warning: " << warning << "\n";
    }
  }
  if (cmd.Help || cmd.Version)
  {
    if (ranks.Rank == 0)
    {
      std::cout << (cmd.Help ? subdapp::UsageText(subdapp::Program::SubdMpi)
                             : std::string("subd-mpi " SUBD_VERSION " (VTK ") + vtkVersion::GetVTKVersion() + ")\n");
    }
    return ranks.Finish(0);
  }
  vtkSmartPointer<vtkPolyData> mesh =
    cmd.Input.empty() ? subdapp::MakeBuiltinCage(cmd.Builtin) : subdapp::ReadMesh(cmd.Input, error);
  if (ranks.AnyFailed(!mesh))
  {
    return ranks.Fail(error.empty() ? "a rank could not read " + cmd.Input : error, 1);
  }
  const std::string output = cmd.Output.empty() ? subdapp::DefaultOutputPath(cmd) : cmd.Output;

  const int threads = cmd.Threads > 0 ? cmd.Threads : DefaultThreads();
  if (threads == 1)
  {
    vtkSMPTools::SetBackend("Sequential"); // no thread pool at all (TBB would warn about one of 0)
  }
  vtkSMPTools::Initialize(threads);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start]() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  long long pieceFaces = 0;
  vtkSmartPointer<vtkPolyData> result = SubdividePiece(cmd, mesh, ranks, pieceFaces);
  if (!result)
  {
    return ranks.Finish(1);
  }
  double seconds[2] = { elapsed(), 0.0 };
  if (!WritePieces(result, output, cmd.Compress, ranks))
  {
    return ranks.Fail("cannot write " + output, 1);
  }
  seconds[1] = elapsed();
  PrintSummary(cmd, output, result, pieceFaces, seconds, ranks);
  return ranks.Finish(0);
}
