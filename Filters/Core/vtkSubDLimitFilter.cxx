#include "vtkSubDLimitFilter.h"

#include "SubDLimitEvaluator.h"
#include "SubDMeshValidation.h"
#include "SubDScheme.h"
#include "vtkSubDCage.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDAdaptiveTessellation.h"
#include "vtkSubDLimitGeometry.h"
#include "vtkSubDMemoryBudget.h"
#include "vtkSubDOutOfMemory.h"
#include "vtkSubDPieces.h"
#include "vtkSubDPointDataInterpolation.h"
#include "vtkSubDSharpFeatures.h"
#include "vtkSubDSurfaceFilter.h"
#include "vtkSubDUniformTessellation.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
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
// The tessellation's cell data: each cell gets its input cell's ("FaceId" names it) and, from an
// adaptive or selective tessellation, its level ("RefineLevel"); in a piece with ghost faces,
// "vtkGhostType" marks the cells of ghost faces.
void AddCellData(vtkPolyData* input, const vtkSubDLimitSamples& samples, bool piece, vtkPolyData* output)
{
  vtkIdTypeArray* cellFace = samples.CellFace;
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
  if (!samples.CellLevels.empty())
  {
    vtkNew<vtkIntArray> levels;
    levels->SetName("RefineLevel");
    levels->SetNumberOfTuples(numCells);
    std::copy(samples.CellLevels.begin(), samples.CellLevels.end(), levels->GetPointer(0));
    outCD->AddArray(levels);
  }
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

// Samples at given (face, u, v) locations (point-data "FaceId", "FaceUV", optional
// "SubFace"), one vertex cell each. False, with `error`, for locations that name no polygon.
bool ReadLocations(vtkDataSet* locations, const vtkSubDCage& cage, vtkSubDLimitSamples& samples, std::string& error)
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

// A cage point-data array carried to the samples, evaluated in double with the limit weights
// and stored by the surface filters' rules (integers rounded and clamped, normals
// re-normalized).
struct CarriedArray
{
  vtkDataArray* Input;
  int Components;
  bool Normals;
  bool FaceVarying; ///< over the channel's vertices (cage.Seams.Arrays), not the cage's points
  std::vector<double> Cage, Samples;
};

std::vector<CarriedArray> CarriedArrays(vtkPolyData* input, const vtkSubDCage& cage, vtkIdType numSamples)
{
  std::vector<CarriedArray> carried;
  vtkPointData* inPD = input->GetPointData();
  const std::vector<int>& faceVarying = cage.Seams.Arrays;
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
      std::find(faceVarying.begin(), faceVarying.end(), a) != faceVarying.end(), {}, {} };
    // A face-varying array's values are those of the input points the channel's vertices are.
    const vtkIdType numValues =
      c.FaceVarying ? static_cast<vtkIdType>(cage.Channel.UserValue.size()) : array->GetNumberOfTuples();
    c.Cage.resize(static_cast<size_t>(numValues) * c.Components);
    for (vtkIdType i = 0; i < numValues; ++i)
    {
      array->GetTuple(c.FaceVarying ? cage.Channel.UserValue[i] : i, c.Cage.data() + i * c.Components);
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
std::string EvaluateSamples(const subd::LimitEvaluator& evaluator, const subd::LimitEvaluator* channel,
  const vtkSubDCage& cage, const vtkSubDLimitSamples& samples, int rows, double* xyz,
  vtkSubDLimitGeometry& geometry, std::vector<CarriedArray>& carried)
{
  const std::vector<vtkSubDFaceSamples>& grids = samples.Grids;
  std::mutex errorMutex;
  std::string firstError;
  vtkSMPTools::For(0, static_cast<vtkIdType>(grids.size()), [&](vtkIdType begin, vtkIdType end) {
    std::vector<subd::LimitStencil> stencils, channelStencils;
    for (vtkIdType g = begin; g < end; ++g)
    {
      const vtkSubDFaceSamples& grid = grids[g];
      std::string faceError;
      if (!evaluator.EvaluateFace(grid.Face, grid.Owned, stencils, faceError, rows) ||
        (channel && !channel->EvaluateFace(grid.Face, grid.Owned, channelStencils, faceError, 1)))
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
          const subd::LimitStencil& stencil = array.FaceVarying ? channelStencils[s] : stencils[s];
          stencil.Apply(stencil.Weights, subd::PatchValue, array.Cage.data(), array.Components,
            array.Samples.data() + id * array.Components);
        }
      }
    }
  });
  // The sides of a seam are one place: one position, one normal, the same vertex data.
  for (const std::pair<vtkIdType, vtkIdType>& same : samples.SamePlace)
  {
    std::copy(xyz + 3 * same.second, xyz + 3 * same.second + 3, xyz + 3 * same.first);
    geometry.Copy(same.first, same.second);
    for (CarriedArray& array : carried)
    {
      const size_t n = array.FaceVarying ? 0 : static_cast<size_t>(array.Components);
      std::copy_n(array.Samples.begin() + same.second * n, n, array.Samples.begin() + same.first * n);
    }
  }
  return firstError;
}


// The faces a piece outputs: its own, and the first `outputGhostLevels` layers of ghost faces;
// not the holes.
std::vector<subd::Index> OutputFaces(
  const vtkSubDCage& cage, const std::vector<std::uint8_t>& ghostLayer, int outputGhostLevels)
{
  std::vector<subd::Index> faces;
  for (subd::Index f = 0; f < cage.Level.Topology.GetNumFaces(); ++f)
  {
    if (!cage.Level.FaceIsHole[f] && (ghostLayer.empty() || ghostLayer[f] <= outputGhostLevels))
    {
      faces.push_back(f);
    }
  }
  return faces;
}

// The level each face asks for, from the input's cell-data array `name`. False, with the
// reason, when the array is missing.
bool ReadFaceLevels(vtkPolyData* input, const char* name, const vtkSubDCage& cage, std::vector<int>& levels,
  std::string& error)
{
  vtkDataArray* array = name ? input->GetCellData()->GetArray(name) : nullptr;
  if (!array)
  {
    error = std::string("Selective tessellation needs the cell-data array \"") + (name ? name : "") +
      "\" (the level each polygon asks for), which the input does not have";
    return false;
  }
  levels.assign(static_cast<size_t>(cage.Level.Topology.GetNumFaces()), 0);
  for (subd::Index f = 0; f < cage.Level.Topology.GetNumFaces(); ++f)
  {
    const double level = array->GetComponent(cage.FaceCell[f], 0);
    levels[f] = std::isfinite(level) ? static_cast<int>(std::max(0.0, std::min(level, 64.0))) : 0;
  }
  return true;
}

// "FaceId", "FaceUV", "SubFace": where each point of a tessellation was evaluated.
void AddLocations(const vtkSubDCage& cage, const vtkSubDLimitSamples& samples, vtkPointData* pd)
{
  vtkNew<vtkIdTypeArray> ids;
  vtkNew<vtkDoubleArray> uv;
  vtkNew<vtkIdTypeArray> sub;
  ids->SetName("FaceId");
  uv->SetName("FaceUV");
  sub->SetName("SubFace");
  uv->SetNumberOfComponents(2);
  ids->SetNumberOfTuples(samples.Count);
  uv->SetNumberOfTuples(samples.Count);
  sub->SetNumberOfTuples(samples.Count);
  for (const vtkSubDFaceSamples& grid : samples.Grids)
  {
    for (size_t s = 0; s < grid.Owned.size(); ++s)
    {
      const vtkIdType id = grid.OwnedIds[s];
      ids->SetValue(id, cage.FaceCell[grid.Face]);
      uv->SetTypedComponent(id, 0, grid.Owned[s].U);
      uv->SetTypedComponent(id, 1, grid.Owned[s].V);
      sub->SetValue(id, grid.Owned[s].SubFace);
    }
  }
  pd->AddArray(ids);
  pd->AddArray(uv);
  pd->AddArray(sub);
}
}

vtkSubDLimitFilter::vtkSubDLimitFilter()
  : MaximumMemory(vtkSubDDefaultMemoryBudget())
{
  this->SetNumberOfInputPorts(2);
  this->SetRefineLevelArrayName("RefineLevel");
}

vtkSubDLimitFilter::~vtkSubDLimitFilter()
{
  this->SetRefineLevelArrayName(nullptr);
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
  // An adaptive or selective face takes the points its neighbours' refinement puts on its
  // edges, and theirs in turn: no number of ghost layers makes a piece's tessellation its own.
  if (this->Tessellation != UNIFORM && !inputVector[1]->GetInformationObject(0))
  {
    vtkSubDRequestWholeInput(inputVector, 1);
    return 1;
  }
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
  // Adaptive and selective tessellations are made of the whole mesh, on the first piece.
  const bool wholeMesh = this->Tessellation != UNIFORM && !locations;
  if (wholeMesh && request.IsLaterPiece())
  {
    return 1;
  }
  const bool quads = this->Scheme == CATMULL_CLARK;
  vtkSubDCage cage;
  std::string error;
  if (!this->ReadCage(input, cage))
  {
    return 0;
  }
  const std::unique_ptr<subd::Scheme> scheme(
    quads ? static_cast<subd::Scheme*>(new subd::CatmullClarkScheme) : new subd::LoopScheme);
  // A piece tessellates its own faces, and the first OutputGhostLevels layers of ghost faces.
  if (request.OneOfMany && cage.FaceIsGhost.empty() && !locations && !wholeMesh)
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
  // Data that differ across welded points (texture coordinates at seams): their channel's limit.
  vtkSubDMakeCageChannel(cage, static_cast<subd::FaceVaryingInterpolation>(this->FaceVaryingInterpolation));
  std::unique_ptr<subd::LimitEvaluator> channel;
  if (cage.HasChannel())
  {
    channel.reset(new subd::LimitEvaluator(*scheme, cage.Channel.Values));
  }
  vtkSubDLimitSamples samples;
  samples.CellFace->SetName("FaceId");
  if (locations && !ReadLocations(locations, cage, samples, error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  if (!locations &&
    !this->Tessellate(input, cage, evaluator, OutputFaces(cage, ghostLayer, request.OutputGhostLevels), samples))
  {
    return 0;
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(samples.Count);
  double* xyz = static_cast<vtkDoubleArray*>(points->GetData())->GetPointer(0);
  vtkSubDLimitGeometry geometry(samples.Count, this->ComputeNormals, this->ComputeCurvature, this->ComputeDerivatives);
  std::vector<CarriedArray> carried = CarriedArrays(input, cage, samples.Count);
  // The stencil rows the arrays asked for need: curvature all, normals and derivatives the first.
  const int rows = this->ComputeCurvature ? subd::NumPatchDerivatives
    : (this->ComputeNormals || this->ComputeDerivatives ? 3 : 1);
  error = EvaluateSamples(evaluator, channel.get(), cage, samples, rows, xyz, geometry, carried);
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
    AddCellData(input, samples, !ghostLayer.empty(), output);
  }
  AddCarriedArrays(carried, samples.Count, output);
  if (this->ComputeLocations && !locations)
  {
    AddLocations(cage, samples, output->GetPointData());
  }
  geometry.AddTo(output->GetPointData(), this);
  return 1;
}

bool vtkSubDLimitFilter::ReadCage(vtkPolyData* input, vtkSubDCage& cage)
{
  const bool quads = this->Scheme == CATMULL_CLARK;
  std::string error, warning;
  const bool read = vtkSubDReadCage(input, quads ? vtkSubDCageFaces::Polygons : vtkSubDCageFaces::Triangulated,
    quads ? subd::RepeatedCorners::Keep : subd::RepeatedCorners::KeepInTriangles,
    static_cast<subd::BoundaryRule>(this->BoundaryRule), static_cast<subd::CreaseMethod>(this->CreaseMethod), cage,
    error, warning, this->WeldCoincidentPoints);
  if (!warning.empty())
  {
    vtkWarningMacro(<< vtkSubDSentence(warning));
  }
  if (!read)
  {
    vtkErrorMacro(<< error << ".");
  }
  return read;
}

bool vtkSubDLimitFilter::Tessellate(vtkPolyData* input, const vtkSubDCage& cage,
  const subd::LimitEvaluator& evaluator, const std::vector<subd::Index>& faces, vtkSubDLimitSamples& samples)
{
  const bool quads = this->Scheme == CATMULL_CLARK;
  if (this->Tessellation == UNIFORM)
  {
    vtkSubDTessellateUniform(cage, faces, quads, this->Resolution, samples);
    return true;
  }
  std::string error;
  vtkSubDAdaptiveSettings settings;
  if (this->Tessellation == ADAPTIVE)
  {
    if (!(this->Tolerance > 0.0) || !std::isfinite(this->Tolerance))
    {
      vtkErrorMacro(<< "Tolerance must be a positive number, not " << this->Tolerance << ".");
      return false;
    }
    // In the cage's units: a fraction of its bounding-box diagonal unless absolute.
    settings.Tolerance = this->Tolerance * (this->ToleranceIsAbsolute ? 1.0 : input->GetLength());
  }
  else if (!ReadFaceLevels(input, this->RefineLevelArrayName, cage, settings.FaceLevels, error))
  {
    vtkErrorMacro(<< error << ".");
    return false;
  }
  settings.MaximumLevel = this->MaximumLevel;
  // A cell becomes about three triangles with two points, their arrays and their bookkeeping.
  settings.MaximumCells = this->MaximumMemory * 1024.0 * 1024.0 / 400.0;
  vtkSubDAdaptiveResult result;
  if (!vtkSubDTessellateAdaptive(cage, evaluator, quads, faces, settings, samples, result, error))
  {
    vtkErrorMacro(<< vtkSubDSentence(error));
    return false;
  }
  if (result.NumTrianglesOffTolerance > 0)
  {
    vtkWarningMacro(<< result.NumTrianglesOffTolerance << " triangles are farther than the tolerance ("
                    << settings.Tolerance << " in the cage's units) from the limit surface at the deepest level "
                    << "allowed (MaximumLevel " << this->MaximumLevel << ").");
  }
  return true;
}

void vtkSubDLimitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << (this->Scheme == CATMULL_CLARK ? "Catmull-Clark" : "Loop") << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  static const char* const tessellations[] = { "Uniform", "Adaptive", "Selective" };
  os << indent << "Tessellation: " << tessellations[this->Tessellation] << "\n";
  os << indent << "Tolerance: " << this->Tolerance << (this->ToleranceIsAbsolute ? " (absolute)" : " (of the diagonal)")
     << "\n";
  os << indent << "MaximumLevel: " << this->MaximumLevel << "\n";
  os << indent << "RefineLevelArrayName: " << (this->RefineLevelArrayName ? this->RefineLevelArrayName : "(none)")
     << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << " MiB\n";
  os << indent << "BoundaryRule: " << this->BoundaryRule << "\n";
  os << indent << "CreaseMethod: " << this->CreaseMethod << "\n";
  os << indent << "WeldCoincidentPoints: " << (this->WeldCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "FaceVaryingInterpolation: "
     << vtkSubDSurfaceFilter::GetFaceVaryingInterpolationName(this->FaceVaryingInterpolation) << "\n";
  os << indent << "ComputeNormals: " << (this->ComputeNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeCurvature: " << (this->ComputeCurvature ? "On" : "Off") << "\n";
  os << indent << "ComputeDerivatives: " << (this->ComputeDerivatives ? "On" : "Off") << "\n";
  os << indent << "ComputeLocations: " << (this->ComputeLocations ? "On" : "Off") << "\n";
}
