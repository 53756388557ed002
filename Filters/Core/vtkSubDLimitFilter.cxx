#include "vtkSubDLimitFilter.h"

#include "SubDLimitEvaluator.h"
#include "SubDMeshValidation.h"
#include "SubDScheme.h"
#include "vtkSubDCage.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDLimitGeometry.h"
#include "vtkSubDOutOfMemory.h"
#include "vtkSubDPieces.h"
#include "vtkSubDPointDataInterpolation.h"
#include "vtkSubDSharpFeatures.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <unordered_map>

vtkStandardNewMacro(vtkSubDLimitFilter);

namespace
{
// A point of the tessellation: a cage vertex, a point on a cage edge (t segments from its
// first vertex), on a segment inside a polygon, or inside a face.
using SampleKey = std::array<vtkIdType, 4>;

struct FaceGrid
{
  subd::Index Face;
  std::vector<subd::FaceSample> Owned; ///< samples this face evaluates
  std::vector<vtkIdType> OwnedIds;     ///< their output points
};

// The tessellation's cell data: each cell gets its input cell's ("FaceId" names it), and in a
// piece with ghost faces, "vtkGhostType" marks the cells of ghost faces.
void AddCellData(vtkPolyData* input, vtkIdTypeArray* cellFace, bool piece, vtkPolyData* output)
{
  const vtkIdType numCells = cellFace->GetNumberOfTuples();
  vtkNew<vtkIdList> sources, targets;
  sources->SetNumberOfIds(numCells);
  targets->SetNumberOfIds(numCells);
  for (vtkIdType c = 0; c < numCells; ++c)
  {
    sources->SetId(c, cellFace->GetValue(c));
    targets->SetId(c, c);
  }
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(input->GetCellData(), numCells);
  outCD->CopyData(input->GetCellData(), sources, targets);
  outCD->RemoveArray(vtkDataSetAttributes::GhostArrayName()); // the input's, remade below
  outCD->AddArray(cellFace);
  if (piece)
  {
    vtkUnsignedCharArray* inputMarks = input->GetCellGhostArray(); // looked up once, not per cell
    vtkNew<vtkUnsignedCharArray> ghosts;
    ghosts->SetName(vtkDataSetAttributes::GhostArrayName());
    ghosts->SetNumberOfTuples(numCells);
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      ghosts->SetValue(c, inputMarks->GetValue(cellFace->GetValue(c)) & vtkDataSetAttributes::DUPLICATECELL);
    }
    outCD->AddArray(ghosts);
    vtkSubDMarkGhostPoints(output);
  }
}

// The samples of the output, grouped by the face that owns (evaluates) each, and the output
// cells with their input cells ("FaceId").
struct Samples
{
  std::vector<FaceGrid> Grids;
  vtkIdType Count = 0;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkIdTypeArray> CellFace;
};

// Samples at given (face, u, v) locations (point-data "FaceId", "FaceUV", optional
// "SubFace"), one vertex cell each. False, with `error`, for locations that name no polygon.
bool ReadLocations(vtkDataSet* locations, const vtkSubDCage& cage, Samples& samples, std::string& error)
{
  vtkDataArray* ids = locations->GetPointData()->GetArray("FaceId");
  vtkDataArray* uv = locations->GetPointData()->GetArray("FaceUV");
  vtkDataArray* sub = locations->GetPointData()->GetArray("SubFace");
  if (!ids || !uv || uv->GetNumberOfComponents() != 2)
  {
    error = "The locations need point-data arrays \"FaceId\" and \"FaceUV\" (2 components)";
    return false;
  }
  samples.Count = locations->GetNumberOfPoints();
  std::map<subd::Index, size_t> gridOf;
  for (vtkIdType i = 0; i < samples.Count; ++i)
  {
    const double cell = ids->GetComponent(i, 0);
    auto known = cell == std::floor(cell) ? cage.FaceOfCell.find(static_cast<vtkIdType>(cell)) : cage.FaceOfCell.end();
    if (known == cage.FaceOfCell.end())
    {
      std::ostringstream message;
      message << "Location " << i << " names cell " << cell << ", which is not a polygon of the input";
      error = message.str();
      return false;
    }
    const subd::Index face = known->second;
    auto found = gridOf.emplace(face, samples.Grids.size());
    if (found.second)
    {
      samples.Grids.push_back({ face, {}, {} });
    }
    subd::FaceSample s;
    s.U = uv->GetComponent(i, 0);
    s.V = uv->GetComponent(i, 1);
    s.SubFace = sub ? static_cast<subd::Index>(sub->GetComponent(i, 0)) : 0;
    samples.Grids[found.first->second].Owned.push_back(s);
    samples.Grids[found.first->second].OwnedIds.push_back(i);
    samples.Cells->InsertNextCell(1, &i);
  }
  return true;
}

// A watertight tessellation of the cage's faces at resolution R: triangles split into R^2
// triangles, quads into R x R quads, other polygons into one (R/2) x (R/2) grid of quads per
// corner. A point shared by faces (on a cage vertex or edge) is made once, owned by the first
// face that meets it.
class Tessellation
{
public:
  Tessellation(const vtkSubDCage& cage, int resolution, Samples& samples)
    : Cage(cage)
    , Topo(cage.Level.Topology)
    , R(resolution)
    , Out(samples)
  {
  }
  void AddTriangle(subd::Index f);
  void AddPolygon(subd::Index f);

private:
  enum Kind
  {
    Vertex,
    Edge,
    Inside,
    Spoke,
    Centre
  };
  // The key of the point `t` segments (of R along the edge) from corner k toward the next
  // corner along edge k of face f.
  SampleKey EdgeKey(subd::Index f, subd::Index k, int t) const
  {
    const subd::IndexSpan fv = this->Topo.GetFaceVertices(f);
    const subd::Index e = this->Topo.GetFaceEdges(f)[k];
    if (t == 0)
      return { Vertex, fv[k], 0, 0 };
    if (t == this->R)
      return { Vertex, fv[(k + 1) % fv.size()], 0, 0 };
    const bool forward = this->Topo.GetEdgeVertices(e)[0] == fv[k];
    return { Edge, e, forward ? t : this->R - t, 0 };
  }
  // The output point of `key`, made (and owned by `grid`) if new.
  vtkIdType Point(FaceGrid& grid, const SampleKey& key, double u, double v, subd::Index subFace)
  {
    auto found = this->IdOf.emplace(key, this->Out.Count);
    if (found.second)
    {
      subd::FaceSample s;
      s.U = u;
      s.V = v;
      s.SubFace = subFace;
      grid.Owned.push_back(s);
      grid.OwnedIds.push_back(this->Out.Count++);
    }
    return found.first->second;
  }
  void AddCell(subd::Index f, vtkIdType size, const vtkIdType* ids)
  {
    this->Out.Cells->InsertNextCell(size, ids);
    this->Out.CellFace->InsertNextValue(this->Cage.FaceCell[f]);
  }
  void AddCornerGrid(FaceGrid& grid, subd::Index k);

  const vtkSubDCage& Cage;
  const subd::MeshTopology& Topo;
  const int R;
  Samples& Out;
  std::map<SampleKey, vtkIdType> IdOf;
};

void Tessellation::AddTriangle(subd::Index f)
{
  // (i, j) with i + j <= R: corners (0,0), (R,0), (0,R).
  FaceGrid grid{ f, {}, {} };
  const int R = this->R;
  auto index = [R](int i, int j) { return static_cast<size_t>(j * (R + 1) + i); };
  std::vector<vtkIdType> ids(static_cast<size_t>((R + 1) * (R + 1)), -1);
  for (int j = 0; j <= R; ++j)
  {
    for (int i = 0; i + j <= R; ++i)
    {
      SampleKey key{ Inside, f, i, j };
      if (j == 0)
        key = this->EdgeKey(f, 0, i);
      else if (i + j == R)
        key = this->EdgeKey(f, 1, j);
      else if (i == 0)
        key = this->EdgeKey(f, 2, R - j);
      ids[index(i, j)] = this->Point(grid, key, static_cast<double>(i) / R, static_cast<double>(j) / R, 0);
    }
  }
  for (int j = 0; j < R; ++j)
  {
    for (int i = 0; i + j < R; ++i)
    {
      const vtkIdType up[3] = { ids[index(i, j)], ids[index(i + 1, j)], ids[index(i, j + 1)] };
      this->AddCell(f, 3, up);
      if (i + j + 1 < R)
      {
        const vtkIdType down[3] = { ids[index(i + 1, j)], ids[index(i + 1, j + 1)], ids[index(i, j + 1)] };
        this->AddCell(f, 3, down);
      }
    }
  }
  this->Out.Grids.push_back(std::move(grid));
}

void Tessellation::AddPolygon(subd::Index f)
{
  FaceGrid grid{ f, {}, {} };
  const bool quad = this->Topo.GetFaceSize(f) == 4;
  for (subd::Index k = 0; k < (quad ? 1 : this->Topo.GetFaceSize(f)); ++k)
  {
    this->AddCornerGrid(grid, k);
  }
  this->Out.Grids.push_back(std::move(grid));
}

// Quads: one R x R grid (k = 0); other polygons: per corner k an S x S grid, S = R/2, with
// (0,0) at corner k, (S,0) at the middle of edge k, (S,S) at the centre.
void Tessellation::AddCornerGrid(FaceGrid& grid, subd::Index k)
{
  const subd::Index f = grid.Face;
  const subd::Index n = this->Topo.GetFaceSize(f);
  const bool whole = n == 4;
  const int S = whole ? this->R : this->R / 2;
  std::vector<vtkIdType> ids(static_cast<size_t>((S + 1) * (S + 1)));
  for (int j = 0; j <= S; ++j)
  {
    for (int i = 0; i <= S; ++i)
    {
      SampleKey key{ Inside, f, k * (S + 1) * (S + 1) + j * (S + 1) + i, 0 };
      if (whole)
      {
        if (j == 0)
          key = this->EdgeKey(f, 0, i);
        else if (i == S)
          key = this->EdgeKey(f, 1, j);
        else if (j == S)
          key = this->EdgeKey(f, 2, S - i);
        else if (i == 0)
          key = this->EdgeKey(f, 3, S - j);
      }
      else if (i == S && j == S)
        key = { Centre, f, 0, 0 };
      else if (j == 0)
        key = this->EdgeKey(f, k, i);
      else if (i == 0)
        key = this->EdgeKey(f, (k + n - 1) % n, this->R - j);
      else if (i == S)
        key = { Spoke, f, k, j };
      else if (j == S)
        key = { Spoke, f, (k + n - 1) % n, i };
      ids[static_cast<size_t>(j * (S + 1) + i)] =
        this->Point(grid, key, static_cast<double>(i) / S, static_cast<double>(j) / S, k);
    }
  }
  auto id = [&](int a, int b) { return ids[static_cast<size_t>(b * (S + 1) + a)]; };
  for (int j = 0; j < S; ++j)
  {
    for (int i = 0; i < S; ++i)
    {
      const vtkIdType quad[4] = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) };
      this->AddCell(f, 4, quad);
    }
  }
}

// A cage point-data array carried to the samples, evaluated in double with the limit weights
// and stored by the surface filters' rules (integers rounded and clamped, normals
// re-normalized).
struct CarriedArray
{
  vtkDataArray* Input;
  int Components;
  bool Normals;
  std::vector<double> Cage, Samples;
};

std::vector<CarriedArray> CarriedArrays(vtkPolyData* input, vtkIdType numSamples)
{
  std::vector<CarriedArray> carried;
  vtkPointData* inPD = input->GetPointData();
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inPD->GetArray(a);
    if (!array || array->GetNumberOfTuples() != input->GetNumberOfPoints() ||
      (array->GetName() && std::string(array->GetName()) == "CornerSharpness") ||
      array == input->GetPointGhostArray()) // the input piece's marks: remade for the output
    {
      continue;
    }
    CarriedArray c{ array, array->GetNumberOfComponents(), inPD->IsArrayAnAttribute(a) == vtkDataSetAttributes::NORMALS,
      {}, {} };
    c.Cage.resize(static_cast<size_t>(array->GetNumberOfTuples()) * c.Components);
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
    {
      array->GetTuple(i, c.Cage.data() + i * c.Components);
    }
    c.Samples.resize(static_cast<size_t>(numSamples) * c.Components);
    carried.push_back(std::move(c));
  }
  return carried;
}

void AddCarriedArrays(const std::vector<CarriedArray>& carried, vtkIdType numSamples, vtkPolyData* output)
{
  for (const CarriedArray& c : carried)
  {
    vtkSmartPointer<vtkDataArray> out =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(c.Input->GetDataType()));
    out->SetName(c.Input->GetName());
    out->SetNumberOfComponents(c.Components);
    out->SetNumberOfTuples(numSamples);
    vtkSubDPointDataInterpolation::Store(c.Samples.data(), c.Components, nullptr, numSamples, c.Normals, out);
    output->GetPointData()->AddArray(out);
  }
}

// Evaluates every sample, face by face in parallel: its position into `xyz`, its derivatives
// into `geometry`, the carried arrays. Returns the first face's error, if any.
std::string EvaluateSamples(const subd::LimitEvaluator& evaluator, const vtkSubDCage& cage,
  const std::vector<FaceGrid>& grids, double* xyz, vtkSubDLimitGeometry& geometry, std::vector<CarriedArray>& carried)
{
  std::mutex errorMutex;
  std::string firstError;
  vtkSMPTools::For(0, static_cast<vtkIdType>(grids.size()), [&](vtkIdType begin, vtkIdType end) {
    std::vector<subd::LimitStencil> stencils;
    for (vtkIdType g = begin; g < end; ++g)
    {
      const FaceGrid& grid = grids[g];
      std::string faceError;
      if (!evaluator.EvaluateFace(grid.Face, grid.Owned, stencils, faceError))
      {
        std::lock_guard<std::mutex> lock(errorMutex);
        firstError = firstError.empty() ? "cell " + std::to_string(cage.FaceCell[grid.Face]) + ": " + faceError
                                        : firstError;
        return;
      }
      for (size_t s = 0; s < stencils.size(); ++s)
      {
        const vtkIdType id = grid.OwnedIds[s];
        double d[6][3], c[6][3];
        vtkSubDLimitGeometry::Apply(stencils[s], cage.Points.data(), d, c);
        std::copy(d[0], d[0] + 3, xyz + 3 * id);
        geometry.Set(id, d, c);
        for (CarriedArray& array : carried)
        {
          stencils[s].Apply(stencils[s].Weights, subd::PatchValue, array.Cage.data(), array.Components,
            array.Samples.data() + id * array.Components);
        }
      }
    }
  });
  return firstError;
}

// Tessellates the faces a piece outputs: its own, and the first `outputGhostLevels` layers of
// ghost faces; triangles for Loop, quads for Catmull-Clark.
void TessellateFaces(const vtkSubDCage& cage, const std::vector<std::uint8_t>& ghostLayer, int outputGhostLevels,
  bool quads, int resolution, Samples& samples)
{
  const subd::MeshTopology& topo = cage.Level.Topology;
  bool polygons = false;
  for (subd::Index f = 0; f < topo.GetNumFaces() && quads; ++f)
  {
    polygons = polygons || topo.GetFaceSize(f) != 4;
  }
  // Other polygons than quads take a grid per corner of half the resolution: an even one.
  Tessellation tessellation(cage, polygons ? 2 * ((resolution + 1) / 2) : resolution, samples);
  for (subd::Index f = 0; f < topo.GetNumFaces(); ++f)
  {
    if (cage.Level.FaceIsHole[f] || (!ghostLayer.empty() && ghostLayer[f] > outputGhostLevels))
    {
      continue;
    }
    if (quads)
    {
      tessellation.AddPolygon(f);
    }
    else
    {
      tessellation.AddTriangle(f);
    }
  }
}
}

vtkSubDLimitFilter::vtkSubDLimitFilter()
{
  this->SetNumberOfInputPorts(2);
}

int vtkSubDLimitFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkSubDLimitFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkSubDRequestPieceWithGhosts(inputVector[0]->GetInformationObject(0), outInfo, 1);
  if (vtkInformation* locationsInfo = inputVector[1]->GetInformationObject(0))
  {
    // The same piece of the locations, without ghosts: each location is evaluated once.
    vtkSubDRequestPieceWithGhosts(locationsInfo, outInfo, 0);
    locationsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

int vtkSubDLimitFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkSubDRunCatchingOutOfMemory(this, vtkPolyData::GetData(outputVector),
    [&]() { return this->Execute(request, inputVector, outputVector); },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

int vtkSubDLimitFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkDataSet* locations = vtkDataSet::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  // One of several pieces may hold no polygon at all: nothing to output, nothing wrong.
  const vtkSubDPieceRequest request(outputVector->GetInformationObject(0));
  if (request.IsEmptyPiece(input))
  {
    return 1;
  }
  const bool quads = this->Scheme == CATMULL_CLARK;
  vtkSubDCage cage;
  std::string error, warning;
  const bool read = vtkSubDReadCage(input, !quads,
    quads ? subd::RepeatedCorners::Keep : subd::RepeatedCorners::KeepInTriangles,
    static_cast<subd::BoundaryRule>(this->BoundaryRule),
    static_cast<subd::CreaseMethod>(this->CreaseMethod), cage, error, warning);
  if (!warning.empty())
  {
    vtkWarningMacro(<< vtkSubDSentence(warning));
  }
  if (!read)
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  std::unique_ptr<subd::Scheme> scheme;
  if (quads)
  {
    scheme.reset(new subd::CatmullClarkScheme);
  }
  else
  {
    scheme.reset(new subd::LoopScheme);
  }
  // A piece tessellates its own faces, and the first OutputGhostLevels layers of ghost faces.
  if (request.OneOfMany && cage.FaceIsGhost.empty() && !locations)
  {
    vtkWarningMacro(<< vtkSubDMissingGhostsWarning(request.Piece, 1));
  }
  const std::vector<std::uint8_t> ghostLayer = cage.FaceIsGhost.empty()
    ? std::vector<std::uint8_t>()
    : vtkSubDGhostLayers(cage.Level.Topology, cage.FaceIsGhost, request.OutputGhostLevels);
  const subd::LimitEvaluator evaluator(*scheme, cage.Level);
  if (!evaluator.IsValid(error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  Samples samples;
  samples.CellFace->SetName("FaceId");
  if (locations && !ReadLocations(locations, cage, samples, error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  if (!locations)
  {
    TessellateFaces(cage, ghostLayer, request.OutputGhostLevels, quads, this->Resolution, samples);
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(samples.Count);
  double* xyz = static_cast<vtkDoubleArray*>(points->GetData())->GetPointer(0);
  vtkSubDLimitGeometry geometry(samples.Count, this->ComputeNormals, this->ComputeCurvature, this->ComputeDerivatives);
  std::vector<CarriedArray> carried = CarriedArrays(input, samples.Count);
  error = EvaluateSamples(evaluator, cage, samples.Grids, xyz, geometry, carried);
  if (!error.empty())
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  output->SetPoints(points);
  if (locations)
  {
    output->SetVerts(samples.Cells);
    output->GetPointData()->PassData(locations->GetPointData());
  }
  else
  {
    output->SetPolys(samples.Cells);
    AddCellData(input, samples.CellFace, !ghostLayer.empty(), output);
  }
  AddCarriedArrays(carried, samples.Count, output);
  geometry.AddTo(output->GetPointData(), this);
  return 1;
}

void vtkSubDLimitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << (this->Scheme == CATMULL_CLARK ? "Catmull-Clark" : "Loop") << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "BoundaryRule: " << this->BoundaryRule << "\n";
  os << indent << "CreaseMethod: " << this->CreaseMethod << "\n";
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeCurvature: " << (this->ComputeCurvature ? "On" : "Off") << "\n";
  os << indent << "ComputeDerivatives: " << (this->ComputeDerivatives ? "On" : "Off") << "\n";
}
