#include "vtkSubDSurfaceFilter.h"
#include "vtkSubDMemoryBudget.h"
#include "vtkSubDOutOfMemory.h"

#include "SubDLimitEvaluator.h"
#include "SubDMeshValidation.h"
#include "SubDMemoryEstimate.h"
#include "SubDRefiner.h"
#include "SubDRegularPatch.h"
#include "SubDScheme.h"
#include "SubDSmoothGrandchild.h"
#include "vtkSubDAdoptedArray.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDLimitGeometry.h"
#include "vtkSubDPieces.h"
#include "vtkSubDPointDataInterpolation.h"
#include "vtkSubDSeams.h"
#include "vtkSubDSharpFeatures.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <sstream>
#include <vector>

namespace
{
// The field data array recording how many steps of a depth-dependent scheme made a mesh.
const char* const DepthArrayName = "SubDDepth";

// The input's recorded depth: a single non-negative integer value, else 0.
int ReadInputDepth(vtkPolyData* input)
{
  vtkDataArray* depth = input->GetFieldData() ? input->GetFieldData()->GetArray(DepthArrayName) : nullptr;
  if (!depth || depth->GetNumberOfTuples() != 1 || depth->GetNumberOfComponents() != 1)
  {
    return 0;
  }
  const double value = depth->GetComponent(0, 0);
  return value >= 0 && value < 1e6 && value == std::floor(value) ? static_cast<int>(value) : 0;
}

// The rank of each kept face in an order every piece shares, for deciding which piece owns a
// crease line on a seam. Doo-Sabin's and midpoint's faces are in that order already
// (vtkSubDOrderFacesAlikeInEveryPiece): their rank is their index.
std::vector<subd::Index> RankFacesAlikeInEveryPiece(vtkPolyData* input, const subd::FaceScreening& screened,
  const subd::LevelArray<vtkIdType>& faceCells, bool facesInPieceOrder)
{
  if (!facesInPieceOrder)
  {
    return vtkSubDFaceRanksAlikeInEveryPiece(input, screened, faceCells);
  }
  std::vector<subd::Index> rank(faceCells.size());
  std::iota(rank.begin(), rank.end(), 0);
  return rank;
}
}

// What an execution leaves for the next one: the screened input connectivity it refined,
// the stencils, and how finest points map to output points.
class vtkSubDSurfaceFilter::vtkInternals
{
public:
  bool Valid = false;
  vtkMTimeType FilterMTime = 0;
  vtkIdType NumInputPoints = 0;
  subd::IndexArray Offsets, Vertices;
  subd::IndexArray KeptFaces;
  std::vector<std::uint8_t> FaceIsGhost; // per kept face; empty unless the input is a piece with ghosts
  // With ghosts: per kept face, 0 if the piece's own, else its ghost layer (vtkSubDGhostLayers);
  // the children of faces up to layer OutputGhostLevels are output, those beyond 0 as ghosts.
  std::vector<std::uint8_t> FaceGhostLayer;
  // Per finest edge, 1 where its crease line is a copy another piece outputs (vtkSubDPieces.h).
  std::vector<std::uint8_t> SeamLineCopies;
  int OutputGhostLevels = 0;
  vtkSubDSharpFeatures Features;
  std::vector<subd::Index> UnmatchedSegments; // crease segments that are not surface edges
  subd::Hierarchy Hierarchy;
  std::unique_ptr<subd::Scheme> Scheme; // the scheme the hierarchy was built with
  vtkSubDSeams Seams;                   // the welded input's seams, and their channel
  vtkSubDSeamChannel SeamChannel;
  // Schemes LimitEvaluator cannot evaluate: two tangent rows per finest point (normals only).
  subd::StencilTable LimitTangents;
  int InputDepth = 0;        // the input's "SubDDepth" (0 without it)
  bool WritesDepth = false;  // the scheme depends on the depth: the output records it
  // Which finest faces and points are output. In the common case (no holes, no isolated
  // input points) all are, and no maps are stored.
  bool CompactPoints = false;
  subd::Index NumFinestFaces = 0; // kept: the finest faces are handed to the output
  bool AllFacesEmitted = true;                // else EmittedFaces lists them (holes, ghosts)
  std::vector<subd::Index> EmittedFaces;      // when holes exist: finest faces that are not holes
  std::vector<vtkIdType> OutputPointOfFinest; // when compacting: -1 where a finest point is unused
  std::vector<vtkIdType> FinestPointOfOutput;
  vtkSmartPointer<vtkCellArray> OutputFaces; // made once per topology, shared by the outputs
  // The last output's coordinates. Once that output is released (the pipeline does so
  // before executing again) and if nothing else holds them, re-applied stencils overwrite
  // them instead of faulting in a new array.
  vtkSmartPointer<vtkDataArray> LastCoords;
  subd::EvaluationScratch<double> Scratch; // the intermediate levels' values, reused likewise
  vtkDataArray* TakeRecyclableCoords()
  {
    vtkDataArray* last = this->LastCoords;
    return last && last->GetReferenceCount() == 1 ? last : nullptr;
  }

  vtkIdType GetNumberOfOutputFaces() const
  {
    return this->AllFacesEmitted ? this->NumFinestFaces : static_cast<vtkIdType>(this->EmittedFaces.size());
  }
  subd::Index FinestFace(vtkIdType outputFace) const
  {
    return this->AllFacesEmitted ? static_cast<subd::Index>(outputFace) : this->EmittedFaces[outputFace];
  }
  vtkIdType OutputPoint(subd::Index finestPoint) const
  {
    return this->CompactPoints ? this->OutputPointOfFinest[finestPoint] : finestPoint;
  }
  void SelectOutput(bool someBaseVertexUnused, bool splitAtSeams);
  void AddGhostArrays(vtkPolyData* output, vtkIdType numLines, const std::vector<std::uint8_t>& lineIsCopy) const;
};

// When ghost levels were asked of the output: "vtkGhostType" for its cells (children of ghost
// faces, crease lines with an end on no own face and the copies of other pieces' lines on the
// seams, `lineIsCopy`, are DUPLICATECELL) and its points (those on no own face are
// DUPLICATEPOINT).
void vtkSubDSurfaceFilter::vtkInternals::AddGhostArrays(
  vtkPolyData* output, vtkIdType numLines, const std::vector<std::uint8_t>& lineIsCopy) const
{
  if (this->OutputGhostLevels == 0 || this->FaceGhostLayer.empty())
  {
    return;
  }
  const subd::Level& finest = this->Hierarchy.Finest;
  const vtkIdType numOut = this->GetNumberOfOutputFaces();
  vtkNew<vtkUnsignedCharArray> cellGhosts;
  cellGhosts->SetName(vtkDataSetAttributes::GhostArrayName());
  cellGhosts->SetNumberOfTuples(numLines + numOut);
  // Lines first count as ghosts, so that the points are marked by the faces alone.
  std::fill_n(cellGhosts->GetPointer(0), numLines, vtkDataSetAttributes::DUPLICATECELL);
  for (vtkIdType c = 0; c < numOut; ++c)
  {
    const bool ghost = this->FaceGhostLayer[finest.GetFaceOrigin(this->FinestFace(c))] > 0;
    cellGhosts->SetValue(numLines + c, ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
  }
  output->GetCellData()->AddArray(cellGhosts);
  vtkSubDMarkGhostPoints(output);
  // Passed-through segments (their own copies of points) are the piece's own.
  vtkDataArray* pointGhosts = output->GetPointData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  const vtkIdType numFinestOutput =
    this->CompactPoints ? static_cast<vtkIdType>(this->FinestPointOfOutput.size()) : finest.Topology.GetNumVertices();
  for (vtkIdType p = numFinestOutput; p < output->GetNumberOfPoints(); ++p)
  {
    pointGhosts->SetComponent(p, 0, 0);
  }
  vtkIdType c = 0, n;
  const vtkIdType* ends;
  vtkCellArray* lines = output->GetLines();
  for (lines->InitTraversal(); c < numLines && lines->GetNextCell(n, ends); ++c)
  {
    const bool ghost = pointGhosts->GetComponent(ends[0], 0) != 0 || pointGhosts->GetComponent(ends[n - 1], 0) != 0 ||
      (static_cast<size_t>(c) < lineIsCopy.size() && lineIsCopy[c]);
    cellGhosts->SetValue(c, ghost ? vtkDataSetAttributes::DUPLICATECELL : 0);
  }
}

// Which finest faces and points are output: all of them, except faces in holes, children of
// ghost faces beyond the ghost levels asked for (another piece outputs them) and the points
// no output face uses; `splitAtSeams`: a point per value of the seams' channel instead
// (vtkSubDSelectSplitOutput).
void vtkSubDSurfaceFilter::vtkInternals::SelectOutput(bool someBaseVertexUnused, bool splitAtSeams)
{
  const subd::Level& finest = this->Hierarchy.Finest;
  this->EmittedFaces.clear();
  this->OutputPointOfFinest.clear();
  this->FinestPointOfOutput.clear();
  this->NumFinestFaces = this->Hierarchy.GetNumFinestFaces();
  this->AllFacesEmitted = !finest.HasHoles() && this->FaceGhostLayer.empty();
  this->CompactPoints = someBaseVertexUnused || !this->AllFacesEmitted || splitAtSeams;
  if (!this->CompactPoints)
  {
    return;
  }
  const subd::Index numFinestFaces = finest.Topology.GetNumFaces();
  for (subd::Index f = 0; f < numFinestFaces && !this->AllFacesEmitted; ++f)
  {
    if (!finest.IsFaceHole(f) &&
      (this->FaceGhostLayer.empty() || this->FaceGhostLayer[finest.GetFaceOrigin(f)] <= this->OutputGhostLevels))
    {
      this->EmittedFaces.push_back(f);
    }
  }
  if (splitAtSeams)
  {
    vtkSubDSelectSplitOutput(finest.Topology, this->AllFacesEmitted ? nullptr : &this->EmittedFaces,
      this->SeamChannel, this->FinestPointOfOutput, this->OutputPointOfFinest);
    return;
  }
  const subd::Index numFinestPoints = finest.Topology.GetNumVertices();
  this->OutputPointOfFinest.assign(static_cast<size_t>(numFinestPoints), -1);
  for (vtkIdType c = 0; c < this->GetNumberOfOutputFaces(); ++c)
  {
    for (subd::Index v : finest.Topology.GetFaceVertices(this->FinestFace(c)))
    {
      this->OutputPointOfFinest[v] = 0;
    }
  }
  for (subd::Index v = 0; v < numFinestPoints; ++v)
  {
    if (this->OutputPointOfFinest[v] == 0)
    {
      this->OutputPointOfFinest[v] = static_cast<vtkIdType>(this->FinestPointOfOutput.size());
      this->FinestPointOfOutput.push_back(v);
    }
  }
}

vtkSubDSurfaceFilter::vtkSubDSurfaceFilter()
  : MaximumMemory(vtkSubDDefaultMemoryBudget())
  , Internals(new vtkInternals)
{
  const vtkSubDFeatureArrayNames defaults;
  this->SetSharpnessArrayName(defaults.Sharpness.c_str());
  this->SetCornerSharpnessArrayName(defaults.CornerSharpness.c_str());
  this->SetHoleArrayName(defaults.Hole.c_str());
}

vtkSubDSurfaceFilter::~vtkSubDSurfaceFilter()
{
  delete this->Internals;
  this->SetSharpnessArrayName(nullptr);
  this->SetCornerSharpnessArrayName(nullptr);
  this->SetHoleArrayName(nullptr);
}

vtkSubDFeatureArrayNames vtkSubDSurfaceFilter::GetFeatureArrayNames() const
{
  auto name = [](const char* n) { return std::string(n ? n : ""); };
  return { name(this->SharpnessArrayName), name(this->CornerSharpnessArrayName), name(this->HoleArrayName) };
}

const char* vtkSubDSurfaceFilter::GetBoundaryRuleAsString()
{
  return subd::ToString(static_cast<subd::BoundaryRule>(this->BoundaryRule));
}

const char* vtkSubDSurfaceFilter::GetFaceVaryingInterpolationName(int mode)
{
  return subd::ToString(static_cast<subd::FaceVaryingInterpolation>(std::max(0, std::min(5, mode))));
}

int vtkSubDSurfaceFilter::FaceVaryingInterpolationFromName(const char* name)
{
  for (int mode = FVAR_LINEAR_NONE; name && mode <= FVAR_LINEAR_ALL; ++mode)
  {
    if (std::strcmp(name, GetFaceVaryingInterpolationName(mode)) == 0)
    {
      return mode;
    }
  }
  return -1;
}

const char* vtkSubDSurfaceFilter::GetCreaseMethodAsString()
{
  return subd::ToString(static_cast<subd::CreaseMethod>(this->CreaseMethod));
}

int vtkSubDSurfaceFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkSubDRunCatchingOutOfMemory(this, vtkPolyData::GetData(outputVector),
    [&]() { return this->Execute(request, inputVector, outputVector); },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

int vtkSubDSurfaceFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkSubDRequestPieceWithGhosts(inputVector[0]->GetInformationObject(0), outputVector->GetInformationObject(0),
    this->GetRequiredGhostLevels());
  return 1;
}

// The input's polygons as the kernel reads them, with what the refinement and the output need
// to know about them: each kept face's input cell, the ghost faces of a piece, the sharp
// features.
struct vtkSubDSurfaceFilter::vtkInputMesh
{
  vtkIdType NumPoints = 0;
  vtkIdType NumPolys = 0;
  vtkSubDInputFaces Faces;
  subd::FaceScreening Screened;
  subd::LevelArray<vtkIdType> FaceCells;  // per kept face, its input cell
  std::vector<std::uint8_t> FaceIsGhost; // per kept face; empty unless a piece with ghosts
  vtkSubDSharpFeatures Features;
  vtkSubDSeams Seams; // where welded points differ in their data (WeldCoincidentPoints)
  int Depth = 0; // the input's "SubDDepth"
};

int vtkSubDSurfaceFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  // One of several pieces may hold no polygon at all: nothing to output, nothing wrong.
  const vtkSubDPieceRequest request(outputVector->GetInformationObject(0));
  if (request.IsEmptyPiece(input))
  {
    return 1;
  }
  vtkInputMesh mesh;
  Status status = this->ReadInputMesh(input, request, mesh) ? Status::Done : Status::Failed;
  const bool reuse = status == Status::Done && this->CanReuseRefinement(mesh, request.OutputGhostLevels);
  if (status == Status::Done && !reuse)
  {
    status = this->BuildRefinement(input, mesh, request.OutputGhostLevels);
  }
  else if (reuse)
  {
    // Applied again: worth the memory of the level the first application did without.
    subd::BuildLevelBetween(*this->Internals->Scheme, this->Internals->Hierarchy);
  }
  if (status == Status::Done)
  {
    this->UpdateProgress(0.5);
    status = this->WriteOutput(input, mesh, reuse, output);
  }
  if (status != Status::Done)
  {
    // An abort (AbortExecute set by an observer) is not an error: empty output, success.
    output->Initialize();
    if (status == Status::Failed)
    {
      this->SetErrorCode(vtkErrorCode::UserError);
    }
    return status == Status::Aborted ? 1 : 0;
  }
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkSubDSurfaceFilter::ReadInputPoints(vtkPolyData* input)
{
  const vtkIdType numPoints = (input && input->GetPoints()) ? input->GetNumberOfPoints() : 0;
  if (numPoints == 0)
  {
    vtkErrorMacro("Input has no points: nothing to subdivide.");
    return false;
  }
  if (numPoints >= static_cast<vtkIdType>(std::numeric_limits<subd::Index>::max() / 8))
  {
    vtkErrorMacro("Input has " << numPoints << " points; at most "
                               << std::numeric_limits<subd::Index>::max() / 8 << " are supported.");
    return false;
  }
  const vtkIdType badPoint = vtkSubDFirstNonFinitePoint(input->GetPoints());
  if (badPoint >= 0)
  {
    double p[3];
    input->GetPoint(badPoint, p);
    vtkErrorMacro("Point " << badPoint << " has a non-finite coordinate (" << p[0] << ", " << p[1]
                           << ", " << p[2] << "); NaN or infinite coordinates cannot be subdivided.");
    return false;
  }
  return true;
}

bool vtkSubDSurfaceFilter::ScreenInputFaces(vtkPolyData* input, vtkInputMesh& mesh)
{
  mesh.Faces = vtkSubDGatherFaces(input);
  const vtkSubDInputFaces& faces = mesh.Faces;
  if (faces.NumFaces == 0)
  {
    vtkErrorMacro("Input has no polygons (it has " << input->GetNumberOfVerts() << " verts, "
                                                 << input->GetNumberOfLines()
                                                 << " lines): a surface scheme needs faces.");
    return false;
  }
  if (faces.Offsets[faces.NumFaces] >= std::numeric_limits<subd::Index>::max() / 8)
  {
    vtkErrorMacro("Input has " << faces.Offsets[faces.NumFaces] << " face corners; too many.");
    return false;
  }
  const subd::RepeatedCorners repeated = this->CollapseRepeatedCorners || !this->KeepsRepeatedCorners()
    ? subd::RepeatedCorners::Collapse
    : this->RequiresTriangles() ? subd::RepeatedCorners::KeepInTriangles : subd::RepeatedCorners::Keep;
  std::string error, warning;
  if (!vtkSubDScreenFaces(faces, mesh.NumPoints, mesh.NumPolys, repeated, mesh.Screened, error, warning))
  {
    vtkErrorMacro(<< vtkSubDSentence(error));
    return false;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< vtkSubDSentence(warning));
  }
  const subd::FaceScreening& screened = mesh.Screened;
  if (this->RequiresTriangles())
  {
    const subd::Index split = vtkSubDTriangulateFaces(mesh.Screened, input->GetPoints());
    if (split > 0)
    {
      vtkWarningMacro(<< vtkSubDSplitPolygonsWarning(split) << ".");
    }
  }
  if (this->WeldCoincidentPoints)
  {
    subd::Index dropped = 0;
    mesh.Seams = vtkSubDWeldCoincidentPoints(input, mesh.Screened, !this->RefinesFaceVaryingData(), dropped);
    // Arrays the output does not carry on (corner sharpness is decayed per vertex, ghost
    // flags are the input's, normals replaced by the limit's) need no channel.
    vtkPointData* inPD = input->GetPointData();
    vtkDataArray* cornerSharpness = vtkSubDNamedArray(inPD, this->GetFeatureArrayNames().CornerSharpness);
    std::vector<int>& arrays = mesh.Seams.Arrays;
    arrays.erase(std::remove_if(arrays.begin(), arrays.end(), [&](int a) {
      return inPD->GetArray(a) == cornerSharpness || inPD->GetArray(a) == input->GetPointGhostArray() ||
        this->IsReplacedByLimitNormals(inPD, a);
    }), arrays.end());
    if (arrays.empty())
    {
      mesh.Seams.ValueOfCorner.clear();
    }
    if (dropped > 0)
    {
      vtkWarningMacro(<< "Ignored " << dropped << " polygon(s) whose points coincide once welded (a point at two "
                      << "corners that were distinct points); WeldCoincidentPoints off keeps them.");
    }
  }
  if (screened.KeptFaces.empty())
  {
    vtkErrorMacro("No usable polygon remains after removing degenerate ones.");
    return false;
  }
  return true;
}

bool vtkSubDSurfaceFilter::ReadInputMesh(vtkPolyData* input, const vtkSubDPieceRequest& request, vtkInputMesh& mesh)
{
  if (!this->ReadInputPoints(input))
  {
    return false;
  }
  mesh.NumPoints = input->GetNumberOfPoints();
  mesh.NumPolys = input->GetNumberOfPolys();
  if (!this->ScreenInputFaces(input, mesh))
  {
    return false;
  }
  const subd::IndexArray& kept = mesh.Screened.KeptFaces;
  mesh.FaceCells.resize(kept.size()); // every entry written below
  vtkSubDPointDataInterpolation::SMPFor(0, static_cast<subd::Index>(kept.size()), [&](subd::Index begin, subd::Index end) {
    for (subd::Index f = begin; f < end; ++f)
    {
      mesh.FaceCells[f] = mesh.Faces.CellIdOf(kept[f], mesh.NumPolys);
    }
  });
  // A piece with ghost faces (vtkSubDPieces.h).
  mesh.FaceIsGhost = vtkSubDGhostFaces(input, mesh.FaceCells);
  if (!mesh.FaceIsGhost.empty() && this->MakesFacesFromSeveralFaces())
  {
    vtkSubDOrderFacesAlikeInEveryPiece(input, mesh.Screened, mesh.FaceCells);
    mesh.FaceIsGhost = vtkSubDGhostFaces(input, mesh.FaceCells);
  }
  if (request.OneOfMany && mesh.FaceIsGhost.empty() && this->GetRequiredGhostLevels() > 0)
  {
    vtkWarningMacro(<< vtkSubDMissingGhostsWarning(request.Piece, this->GetRequiredGhostLevels()));
  }
  std::string featureError;
  if (!mesh.Features.Read(input, mesh.FaceCells, featureError, this->GetFeatureArrayNames()))
  {
    vtkErrorMacro(<< featureError);
    return false;
  }
  const std::vector<subd::Index>& weldedTo = mesh.Seams.WeldedTo;
  for (subd::Index& p : mesh.Features.SegmentPoints) // crease lines name welded points as the faces do
  {
    p = p >= 0 && static_cast<size_t>(p) < weldedTo.size() ? weldedTo[p] : p;
  }
  mesh.Depth = ReadInputDepth(input);
  return true;
}

bool vtkSubDSurfaceFilter::CanReuseRefinement(const vtkInputMesh& mesh, int outputGhostLevels)
{
  const vtkInternals& cache = *this->Internals;
  return cache.Valid && cache.FilterMTime == this->GetMTime() && cache.InputDepth == mesh.Depth &&
    cache.NumInputPoints == mesh.NumPoints && cache.Offsets == mesh.Screened.Offsets &&
    cache.Vertices == mesh.Screened.Vertices && cache.FaceIsGhost == mesh.FaceIsGhost &&
    cache.OutputGhostLevels == outputGhostLevels && cache.Features == mesh.Features && cache.Seams == mesh.Seams &&
    !this->AutomaticCreases;
}

bool vtkSubDSurfaceFilter::FitsTheMemoryBudget(
  const subd::Scheme& scheme, const subd::MeshTopology& topology, vtkPointData* inPD, bool fullFinest)
{
  // Predict the finest level and the peak memory before allocating anything.
  const subd::MeshCounts baseCounts{ static_cast<double>(topology.GetNumFaces()),
    static_cast<double>(topology.GetNumEdges()), static_cast<double>(topology.GetNumVertices()),
    static_cast<double>(topology.GetNumFaceCorners()),
    static_cast<double>(topology.GetNumBoundaryEdges() + topology.GetNumNonManifoldEdges()) };
  subd::MeshCounts counts = baseCounts;
  for (int l = 0; l < this->NumberOfSubdivisions; ++l)
  {
    counts = scheme.PredictChildCounts(counts);
  }
  const double indexLimit = 2147483647.0; // the kernel's and the output's 32-bit indices
  if (std::max({ counts.Corners, counts.Vertices, counts.Edges }) > indexLimit)
  {
    vtkErrorMacro("Refusing " << this->NumberOfSubdivisions << " subdivision level(s): the output "
                              << "would have about " << counts.Faces << " faces and " << counts.Vertices
                              << " points, more corners or points than 32-bit indices can number (2^31 - 1).");
    return false;
  }
  subd::RefinementRequest request;
  request.Base = baseCounts;
  request.Levels = this->NumberOfSubdivisions;
  request.Finest = fullFinest ? subd::ChildTopology::Full : subd::ChildTopology::FacesOnly;
  request.Rows = subd::LevelRows::Written;
  int maxComponents = 3;
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = inPD->GetArray(a))
    {
      request.OutputBytesPerPoint += array->GetNumberOfComponents() * array->GetDataTypeSize();
      maxComponents = std::max(maxComponents, array->GetNumberOfComponents());
    }
  }
  request.ScratchBytesPerPoint = 8.0 * maxComponents; // one array at a time, in double
  const double MiB = 1024.0 * 1024.0;
  const double bytes = subd::EstimatePeakBytes(scheme, request);
  if (bytes > this->MaximumMemory * MiB)
  {
    vtkErrorMacro("Refusing " << this->NumberOfSubdivisions << " subdivision level(s): the output "
                              << "would have about " << counts.Faces << " faces and " << counts.Vertices
                              << " points and need about " << bytes / MiB << " MiB, more than MaximumMemory ("
                              << this->MaximumMemory << " MiB).");
    return false;
  }
  return true;
}

void vtkSubDSurfaceFilter::ReadBaseTags(
  vtkPolyData* input, const vtkInputMesh& mesh, const subd::MeshTopology& topology, subd::BaseTags& tags)
{
  vtkInternals& cache = *this->Internals;
  const vtkSubDSharpFeatures& features = mesh.Features;
  tags = features.ToBaseTags(topology, input->GetPoints(),
    this->AutomaticCreases ? this->FeatureAngle : 0.0, static_cast<subd::CreaseMethod>(this->CreaseMethod),
    cache.UnmatchedSegments);
  // Ghost line cells are passed through by the piece that owns them.
  std::vector<subd::Index>& unmatched = cache.UnmatchedSegments;
  unmatched.erase(std::remove_if(unmatched.begin(), unmatched.end(),
                    [&](subd::Index segment) { return vtkSubDIsGhostCell(input, features.SegmentCell[segment]); }),
    unmatched.end());
  if (!unmatched.empty())
  {
    const subd::Index first = unmatched[0];
    vtkWarningMacro(<< unmatched.size() << " crease line segment(s) are not edges of "
                    << "the surface and are passed through unchanged; the first is ("
                    << features.SegmentPoints[2 * first] << ", " << features.SegmentPoints[2 * first + 1]
                    << ") in line cell " << features.SegmentCell[first] << ".");
  }
}

bool vtkSubDSurfaceFilter::AddLimitTables()
{
  vtkInternals& cache = *this->Internals;
  const subd::Scheme& scheme = *cache.Scheme;
  const subd::Level& finest = cache.Hierarchy.Finest;
  if (this->ProjectToLimit)
  {
    // The limit masks read the finest points: one more stencil table after the levels,
    // so that points and point data are projected alike, and cached alike.
    subd::StencilTable limit;
    std::string limitError;
    if (!scheme.BuildLimitStencils(finest, limit, limitError))
    {
      vtkErrorMacro(<< "ProjectToLimit: " << limitError << ".");
      return false;
    }
    cache.Hierarchy.Stencils.push_back(std::move(limit));
  }
  std::string evaluationError;
  cache.LimitTangents = subd::StencilTable();
  const bool limitGeometry = this->ComputeLimitNormals || this->ComputeCurvature;
  if (!limitGeometry || subd::LimitEvaluator(scheme, finest).IsValid(evaluationError))
  {
    return true;
  }
  // Without exact derivatives, normals can still come from tangent masks; curvature not.
  // Catmull-Clark and Loop report the evaluator's reason (e.g. a vertex of too high a
  // valence), the other schemes why their tangent masks do not apply.
  std::string tangentError;
  if (!this->ComputeCurvature && scheme.BuildLimitTangentStencils(finest, cache.LimitTangents, tangentError))
  {
    return true;
  }
  const std::string name = scheme.GetName();
  const bool exactScheme = name == "catmull-clark" || name == "loop";
  vtkErrorMacro(<< (this->ComputeCurvature ? "ComputeCurvature" : "ComputeLimitNormals") << ": "
                << (exactScheme || tangentError.empty() ? evaluationError : tangentError) << ".");
  return false;
}

vtkSubDSurfaceFilter::Status vtkSubDSurfaceFilter::BuildRefinement(vtkPolyData* input, vtkInputMesh& mesh, int outputGhostLevels)
{
  vtkInternals& cache = *this->Internals;
  cache.Valid = false;
  cache.OutputFaces = nullptr;
  cache.LastCoords = nullptr;
  cache.Scratch = subd::EvaluationScratch<double>();
  const subd::FaceScreening& screened = mesh.Screened;
  // Screened faces have at least three corners: three per face on average is three each.
  const bool allTriangles = screened.Vertices.size() == 3 * (screened.Offsets.size() - 1);
  cache.Scheme.reset(this->NewScheme(allTriangles));
  cache.Scheme->SetParallelFor(&vtkSubDPointDataInterpolation::SMPFor);
  const subd::Scheme& scheme = *cache.Scheme;
  const bool sharpFeatures = mesh.Features.Any() || this->AutomaticCreases;
  const bool limitGeometry = this->ComputeLimitNormals || this->ComputeCurvature;
  // The finest level keeps its full topology where something reads it: crease lines out,
  // limit positions and limit geometry.
  const subd::ChildTopology finest = !sharpFeatures && !this->ProjectToLimit && !limitGeometry
    ? subd::ChildTopology::FacesOnly
    : subd::ChildTopology::Full;
  subd::MeshTopology topology = subd::MeshTopology::Build(static_cast<subd::Index>(mesh.NumPoints),
    subd::CopyOnThreads(screened.Offsets.begin(), screened.Offsets.end(), &vtkSubDPointDataInterpolation::SMPFor),
    subd::CopyOnThreads(screened.Vertices.begin(), screened.Vertices.end(), &vtkSubDPointDataInterpolation::SMPFor),
    &vtkSubDPointDataInterpolation::SMPFor);
  const std::string nonManifold = vtkSubDNonManifoldWarning(topology, mesh.FaceIsGhost);
  if (!nonManifold.empty())
  {
    vtkWarningMacro(<< nonManifold << ".");
  }
  cache.FaceGhostLayer = mesh.FaceIsGhost.empty() ? std::vector<std::uint8_t>()
                                                  : vtkSubDGhostLayers(topology, mesh.FaceIsGhost, outputGhostLevels);
  // A piece's crease lines on its seams are also in the neighbouring piece: one must own each.
  const std::vector<subd::Index> faceRank = mesh.FaceIsGhost.empty() || !sharpFeatures
    ? std::vector<subd::Index>()
    : RankFacesAlikeInEveryPiece(input, mesh.Screened, mesh.FaceCells, this->MakesFacesFromSeveralFaces());
  bool someBaseVertexUnused = false;
  for (subd::Index v = 0; v < topology.GetNumVertices() && !someBaseVertexUnused; ++v)
  {
    someBaseVertexUnused = topology.GetVertexFaces(v).empty();
  }
  if (!this->FitsTheMemoryBudget(scheme, topology, input->GetPointData(), finest == subd::ChildTopology::Full))
  {
    return Status::Failed;
  }
  subd::BaseTags tags;
  this->ReadBaseTags(input, mesh, topology, tags);
  subd::Level base = subd::MakeBaseLevel(
    std::move(topology), tags, scheme.EffectiveBoundaryRule(static_cast<subd::BoundaryRule>(this->BoundaryRule)));
  cache.WritesDepth = scheme.DependsOnDepth();
  base.Depth = cache.WritesDepth ? mesh.Depth : 0;
  std::string seamError;
  if (mesh.Seams.Any() &&
    !vtkSubDRefineSeams(scheme, base, mesh.Seams, static_cast<subd::FaceVaryingInterpolation>(this->FaceVaryingInterpolation),
      this->NumberOfSubdivisions, this->ProjectToLimit, cache.SeamChannel, seamError))
  {
    vtkErrorMacro(<< "ProjectToLimit (face-varying data): " << seamError << ".");
    return Status::Failed;
  }
  auto progress = [this](double fraction) {
    this->UpdateProgress(0.5 * fraction);
    return !this->GetAbortExecute();
  };
  if (!subd::Refine(scheme, std::move(base), this->NumberOfSubdivisions, cache.Hierarchy, progress, finest,
        subd::LevelRows::Written))
  {
    return Status::Aborted;
  }
  if (!this->AddLimitTables())
  {
    return Status::Failed;
  }
  ++this->NumberOfStencilBuilds;
  cache.SeamLineCopies = faceRank.empty() ? std::vector<std::uint8_t>()
                                          : vtkSubDSeamLineCopies(cache.Hierarchy.Finest, cache.FaceGhostLayer, faceRank);
  cache.FaceIsGhost = std::move(mesh.FaceIsGhost);
  cache.OutputGhostLevels = outputGhostLevels;
  cache.SelectOutput(someBaseVertexUnused, mesh.Seams.Any());
  cache.NumInputPoints = mesh.NumPoints;
  cache.InputDepth = mesh.Depth;
  cache.Offsets = std::move(mesh.Screened.Offsets);
  cache.Vertices = std::move(mesh.Screened.Vertices);
  cache.KeptFaces = std::move(mesh.Screened.KeptFaces);
  cache.Features = std::move(mesh.Features);
  cache.Seams = std::move(mesh.Seams);
  cache.FilterMTime = this->GetMTime();
  cache.Valid = true;
  return Status::Done;
}

vtkSubDSurfaceFilter::Status vtkSubDSurfaceFilter::WriteOutput(
  vtkPolyData* input, const vtkInputMesh& mesh, bool reuse, vtkPolyData* output)
{
  vtkInternals& cache = *this->Internals;
  // Only re-applications keep the scratch levels (the intermediate levels' values) for the
  // next update: the first update of a topology, which may be the only one, frees its own
  // before the output faces are made.
  subd::EvaluationScratch<double> updateScratch;
  vtkSubDPointDataInterpolation interpolation(cache.Hierarchy, vtkSubDPointDataInterpolation::SMPFor,
    cache.CompactPoints ? &cache.FinestPointOfOutput : nullptr, reuse ? &cache.Scratch : &updateScratch);
  const Status points = this->WritePoints(input, interpolation, output);
  if (points != Status::Done)
  {
    return points;
  }
  std::vector<std::pair<vtkDataArray*, vtkDataArray*>> interpolated;
  if (!this->InterpolatePointData(input, interpolation, output, interpolated))
  {
    return Status::Aborted;
  }

  // Sharp features out: decayed corner sharpness, crease lines (before the faces in VTK's
  // cell order) and the line segments passed through.
  vtkSubDOutputPointMap pointMap{ [&cache](subd::Index v) { return cache.OutputPoint(v); },
    [&cache](vtkIdType o) {
      return cache.CompactPoints ? cache.FinestPointOfOutput[o] : static_cast<subd::Index>(o);
    } };
  vtkSubDSeamLines seams{ cache.SeamLineCopies, cache.OutputGhostLevels > 0, {} };
  const std::vector<float> lineSharpness = vtkSubDWriteSharpFeatures(cache.Features, cache.UnmatchedSegments,
    cache.Hierarchy.Finest, pointMap, input, interpolated, output, cache.SeamLineCopies.empty() ? nullptr : &seams);

  // Faces, straight into offsets/connectivity; they depend on the topology only: re-applied
  // stencils reuse them.
  if (!cache.OutputFaces)
  {
    updateScratch = subd::EvaluationScratch<double>();
    cache.OutputFaces = this->MakeOutputFaces();
  }
  output->SetPolys(cache.OutputFaces);
  this->AddCellData(input, mesh, lineSharpness, output);
  if (cache.WritesDepth)
  {
    // How many steps made the output, so that a later refinement continues them.
    vtkNew<vtkIntArray> depth;
    depth->SetName(DepthArrayName);
    depth->InsertNextValue(cache.Hierarchy.Finest.Depth);
    output->GetFieldData()->AddArray(depth);
  }
  cache.AddGhostArrays(output, static_cast<vtkIdType>(lineSharpness.size()), seams.LineIsCopy);
  if (cache.Seams.Any() &&
    !vtkSubDAddFaceVaryingArrays(input, cache.Seams, cache.SeamChannel, this->EvaluationProgress(input, 0), output))
  {
    return Status::Aborted;
  }
  return Status::Done;
}

vtkSubDSurfaceFilter::Status vtkSubDSurfaceFilter::WritePoints(
  vtkPolyData* input, vtkSubDPointDataInterpolation& interpolation, vtkPolyData* output)
{
  vtkInternals& cache = *this->Internals;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  // Double input points are read where they are; others are converted once.
  vtkSmartPointer<vtkDoubleArray> basePoints = vtkDoubleArray::FastDownCast(input->GetPoints()->GetData());
  if (!basePoints || basePoints->GetNumberOfComponents() != 3)
  {
    basePoints = vtkSmartPointer<vtkDoubleArray>::New();
    basePoints->SetNumberOfComponents(3);
    basePoints->SetNumberOfTuples(numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      input->GetPoint(i, basePoints->GetPointer(3 * i));
    }
  }
  int precision = this->OutputPointsPrecision;
  if (precision == DEFAULT_PRECISION)
  {
    precision = input->GetPoints()->GetDataType() == VTK_DOUBLE ? DOUBLE_PRECISION : SINGLE_PRECISION;
  }
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(precision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  vtkSmartPointer<vtkDataArray> outCoords = interpolation.Interpolate(
    basePoints, outPoints->GetDataType(), false, this->EvaluationProgress(input, 0), cache.TakeRecyclableCoords());
  if (!outCoords)
  {
    return Status::Aborted;
  }
  cache.LastCoords = outCoords;
  outPoints->SetData(outCoords);
  output->SetPoints(outPoints);
  if ((this->ComputeLimitNormals || this->ComputeCurvature) &&
    !this->AddLimitGeometry(basePoints->GetPointer(0), output->GetPointData()))
  {
    return Status::Failed;
  }
  return Status::Done;
}

std::function<bool(double)> vtkSubDSurfaceFilter::EvaluationProgress(vtkPolyData* input, int step)
{
  const int numArrays = input->GetPointData()->GetNumberOfArrays();
  return [this, numArrays, step](double fraction) {
    this->UpdateProgress(0.5 + 0.5 * (step + fraction) / (numArrays + 1));
    return !this->GetAbortExecute();
  };
}

bool vtkSubDSurfaceFilter::IsReplacedByLimitNormals(vtkPointData* inPD, int a) const
{
  vtkDataArray* array = inPD->GetArray(a);
  return this->ComputeLimitNormals && array &&
    (inPD->IsArrayAnAttribute(a) == vtkDataSetAttributes::NORMALS ||
      (array->GetName() && std::string(array->GetName()) == "Normals"));
}

bool vtkSubDSurfaceFilter::InterpolatePointData(vtkPolyData* input, vtkSubDPointDataInterpolation& interpolation,
  vtkPolyData* output, std::vector<std::pair<vtkDataArray*, vtkDataArray*>>& interpolated)
{
  const vtkInternals& cache = *this->Internals;
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  for (int a = 0; a < inPD->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* abstractArray = inPD->GetAbstractArray(a);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstractArray);
    if (!array)
    {
      vtkWarningMacro(<< "Point-data array '" << (abstractArray->GetName() ? abstractArray->GetName() : "")
                      << "' is not numeric and cannot be interpolated; it is not passed on.");
      continue;
    }
    // Corner sharpness is not interpolated: it is decayed on the vertices it belongs to
    // (vtkSubDWriteSharpFeatures); the ghost flags of the input's piece mean nothing for the
    // output's points.
    if (array == vtkSubDNamedArray(inPD, cache.Features.Names.CornerSharpness) || array == input->GetPointGhostArray())
    {
      continue;
    }
    if (array->GetNumberOfTuples() != input->GetNumberOfPoints())
    {
      vtkWarningMacro(<< "Point-data array '" << (array->GetName() ? array->GetName() : "")
                      << "' has " << array->GetNumberOfTuples() << " tuples for " << input->GetNumberOfPoints()
                      << " points; it is not passed on.");
      continue;
    }
    if (this->IsReplacedByLimitNormals(inPD, a) ||
      std::find(cache.Seams.Arrays.begin(), cache.Seams.Arrays.end(), a) != cache.Seams.Arrays.end())
    {
      continue; // replaced by the limit normals, or face-varying (vtkSubDAddFaceVaryingArrays)
    }
    const int attribute = inPD->IsArrayAnAttribute(a);
    vtkSmartPointer<vtkDataArray> out = interpolation.Interpolate(
      array, array->GetDataType(), attribute == vtkDataSetAttributes::NORMALS, this->EvaluationProgress(input, a + 1));
    if (!out)
    {
      return false;
    }
    outPD->AddArray(out);
    interpolated.emplace_back(array, out);
    if (attribute >= 0)
    {
      outPD->SetActiveAttribute(outPD->GetNumberOfArrays() - 1, attribute);
    }
  }
  return true;
}

void vtkSubDSurfaceFilter::AddCellData(
  vtkPolyData* input, const vtkInputMesh& mesh, const std::vector<float>& lineSharpness, vtkPolyData* output)
{
  const vtkInternals& cache = *this->Internals;
  const vtkIdType numLines = static_cast<vtkIdType>(lineSharpness.size());
  const vtkIdType numOut = cache.GetNumberOfOutputFaces();
  // Each face inherits its input cell's; lines get zeros, and their sharpness.
  if (input->GetCellData()->GetNumberOfArrays() == 0 && !this->GenerateParentCellIds && numLines == 0)
  {
    return;
  }
  vtkNew<vtkIdList> sourceCells, targetCells;
  sourceCells->SetNumberOfIds(numOut);
  targetCells->SetNumberOfIds(numOut);
  const subd::Level& finest = cache.Hierarchy.Finest;
  for (vtkIdType c = 0; c < numOut; ++c)
  {
    const subd::Index baseFace = finest.GetFaceOrigin(cache.FinestFace(c));
    sourceCells->SetId(c, mesh.Faces.CellIdOf(cache.KeptFaces[baseFace], mesh.NumPolys));
    targetCells->SetId(c, numLines + c);
  }
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, numLines + numOut);
  for (vtkIdType c = 0; c < numLines; ++c)
  {
    outCD->NullData(c);
  }
  outCD->CopyData(inCD, sourceCells, targetCells);
  outCD->RemoveArray(vtkDataSetAttributes::GhostArrayName()); // the input's, not the output's
  if (numLines > 0)
  {
    vtkNew<vtkFloatArray> sharpness;
    const std::string& sharpnessName =
      cache.Features.Names.Sharpness.empty() ? vtkSubDFeatureArrayNames().Sharpness : cache.Features.Names.Sharpness;
    sharpness->SetName(sharpnessName.c_str());
    sharpness->SetNumberOfTuples(numLines + numOut);
    std::copy(lineSharpness.begin(), lineSharpness.end(), sharpness->GetPointer(0));
    vtkDataArray* inputSharpness = inCD->GetArray(sharpnessName.c_str());
    for (vtkIdType c = 0; c < numOut; ++c)
    {
      sharpness->SetValue(numLines + c,
        inputSharpness ? static_cast<float>(inputSharpness->GetComponent(sourceCells->GetId(c), 0)) : 0.0f);
    }
    outCD->RemoveArray(sharpnessName.c_str());
    outCD->AddArray(sharpness);
  }
  if (this->GenerateParentCellIds)
  {
    vtkNew<vtkIdTypeArray> parents;
    parents->SetName("ParentCellId");
    parents->SetNumberOfTuples(numLines + numOut);
    std::fill_n(parents->GetPointer(0), numLines, -1);
    std::copy(sourceCells->GetPointer(0), sourceCells->GetPointer(0) + numOut, parents->GetPointer(numLines));
    outCD->AddArray(parents);
  }
}

bool vtkSubDSurfaceFilter::AddLimitGeometry(const double* basePoints, vtkPointData* outPD)
{
  const vtkInternals& cache = *this->Internals;
  const subd::Hierarchy& hierarchy = cache.Hierarchy;
  const subd::Level& finest = hierarchy.Finest;
  const subd::MeshTopology& topo = finest.Topology;
  // The finest control points (without the limit projection, if any).
  const int levelTables = this->NumberOfSubdivisions;
  std::vector<double> control(static_cast<size_t>(hierarchy.GetNumFinestPoints()) * 3);
  hierarchy.Evaluate(basePoints, 3, control.data(), vtkSubDPointDataInterpolation::SMPFor, nullptr, levelTables);

  const vtkIdType numOut =
    cache.CompactPoints ? static_cast<vtkIdType>(cache.FinestPointOfOutput.size()) : topo.GetNumVertices();
  if (cache.LimitTangents.GetNumRows() > 0)
  {
    this->AddTangentMaskNormals(control, numOut, outPD);
    return true;
  }
  const subd::LimitEvaluator evaluator(*cache.Scheme, finest);
  const bool quads = std::string(cache.Scheme->GetName()) == "catmull-clark";
  vtkSubDLimitGeometry geometry(numOut, this->ComputeLimitNormals, this->ComputeCurvature, false);
  std::mutex errorMutex;
  std::string firstError;
  vtkSMPTools::For(0, numOut, 256, [&](vtkIdType begin, vtkIdType end) {
    std::vector<subd::LimitStencil> stencils;
    std::vector<subd::SurfaceGeometry> sides;
    std::vector<subd::Index> seen;
    for (vtkIdType o = begin; o < end; ++o)
    {
      const subd::Index v = cache.CompactPoints ? cache.FinestPointOfOutput[o] : static_cast<subd::Index>(o);
      const subd::IndexSpan faces = topo.GetVertexFaces(v);
      const subd::IndexSpan corners = topo.GetVertexFaceCorners(v);
      sides.clear();
      seen.clear();
      double d[6][3] = {}, c[6][3];
      // One evaluation per side of the creases through v: one in all when no sharp,
      // boundary or non-manifold edge splits its fan.
      const subd::IndexSpan edges = topo.GetVertexEdges(v);
      const bool oneSide = std::all_of(edges.begin(), edges.end(),
        [&finest](subd::Index e) { return subd::IsSmoothInteriorEdge(finest, e); });
      for (subd::Index i = 0; i < faces.size(); ++i)
      {
        const subd::Index f = faces[i];
        if (finest.IsFaceHole(f) || std::find(seen.begin(), seen.end(), f) != seen.end())
        {
          continue;
        }
        if (oneSide)
        {
          seen.assign(faces.begin(), faces.end());
        }
        else
        {
          const std::vector<subd::Index> sector = subd::SectorFaces(finest, f, corners[i]);
          seen.insert(seen.end(), sector.begin(), sector.end());
        }
        std::string error;
        if (!evaluator.EvaluateFace(
              f, { subd::LimitEvaluator::CornerSample(topo.GetFaceSize(f), corners[i], quads) }, stencils, error))
        {
          std::lock_guard<std::mutex> lock(errorMutex);
          firstError = firstError.empty() ? error : firstError;
          return;
        }
        double di[6][3];
        vtkSubDLimitGeometry::Apply(stencils[0], control.data(), di, c);
        sides.push_back(subd::ComputeSurfaceGeometry(di, c));
        if (sides.size() == 1)
        {
          std::copy(&di[0][0], &di[0][0] + 18, &d[0][0]);
        }
      }
      geometry.SetMean(o, sides, d);
    }
  });
  if (!firstError.empty())
  {
    vtkErrorMacro(<< "Limit geometry: " << firstError << ".");
    return false;
  }
  geometry.AddTo(outPD, this);
  return true;
}

void vtkSubDSurfaceFilter::AddTangentMaskNormals(
  const std::vector<double>& control, vtkIdType numOut, vtkPointData* outPD)
{
  const vtkInternals& cache = *this->Internals;
  vtkSubDLimitGeometry geometry(numOut, true, false, false);
  vtkSMPTools::For(0, numOut, 1024, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType o = begin; o < end; ++o)
    {
      const subd::Index v = cache.CompactPoints ? cache.FinestPointOfOutput[o] : static_cast<subd::Index>(o);
      double d[6][3] = {}; // PatchDerivative order: the tangents stand for Du and Dv
      for (int t = 0; t < 2; ++t)
      {
        const subd::IndexSpan sources = cache.LimitTangents.GetSources(2 * v + t);
        const double* weights = cache.LimitTangents.GetWeights(2 * v + t);
        for (subd::Index k = 0; k < sources.size(); ++k)
        {
          for (int c = 0; c < 3; ++c)
          {
            d[1 + t][c] += weights[k] * control[3 * static_cast<size_t>(sources[k]) + c];
          }
        }
      }
      geometry.Set(o, d, d);
    }
  });
  geometry.AddTo(outPD, this);
}

// The output faces in 32-bit offsets/connectivity arrays: the kernel's own index width
// (the size guard refuses outputs beyond it), half the memory of vtkIdType's. When every
// finest face and point is output and nothing else reads the finest faces (a faces-only
// level), the kernel's arrays become the output's.
vtkSmartPointer<vtkCellArray> vtkSubDSurfaceFilter::MakeOutputFaces()
{
  vtkInternals& cache = *this->Internals;
  vtkNew<vtkCellArray> polys;
  subd::IndexArray kernelOffsets, kernelVertices;
  if (!cache.CompactPoints &&
    subd::MeshTopology::MoveFacesOut(std::move(cache.Hierarchy.Finest.Topology), kernelOffsets, kernelVertices))
  {
    polys->SetData(vtkSubDAdoptVector(std::move(kernelOffsets)), vtkSubDAdoptVector(std::move(kernelVertices)));
    return polys;
  }
  // Split at seams, the corners are the channel's values (its faces are the finest faces).
  const bool split = cache.Seams.Any();
  const subd::MeshTopology& topo = split ? cache.SeamChannel.Hierarchy.Finest.Topology : cache.Hierarchy.Finest.Topology;
  const std::vector<vtkIdType>& valueOutput = cache.SeamChannel.OutputPointOfValue;
  auto outputPoint = [&](subd::Index v) {
    return !split ? cache.OutputPoint(v) : valueOutput.empty() ? v : valueOutput[v];
  };
  const vtkIdType numOut = cache.GetNumberOfOutputFaces();
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfTuples(numOut + 1);
  vtkTypeInt32* off = offsets->GetPointer(0);
  off[0] = 0;
  for (vtkIdType c = 0; c < numOut; ++c)
  {
    off[c + 1] = off[c] + topo.GetFaceSize(cache.FinestFace(c));
  }
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfTuples(off[numOut]);
  vtkTypeInt32* conn = connectivity->GetPointer(0);
  vtkSMPTools::For(0, numOut, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      vtkTypeInt32* out = conn + off[c];
      for (subd::Index v : topo.GetFaceVertices(cache.FinestFace(c)))
      {
        *out++ = static_cast<vtkTypeInt32>(outputPoint(v));
      }
    }
  });
  polys->SetData(offsets, connectivity);
  return polys;
}

void vtkSubDSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
  os << indent << "BoundaryRule: " << this->GetBoundaryRuleAsString() << "\n";
  os << indent << "CreaseMethod: " << this->GetCreaseMethodAsString() << "\n";
  os << indent << "AutomaticCreases: " << (this->AutomaticCreases ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "CollapseRepeatedCorners: " << (this->CollapseRepeatedCorners ? "On" : "Off") << "\n";
  os << indent << "WeldCoincidentPoints: " << (this->WeldCoincidentPoints ? "On" : "Off") << "\n";
  os << indent << "FaceVaryingInterpolation: " << GetFaceVaryingInterpolationName(this->FaceVaryingInterpolation)
     << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "ProjectToLimit: " << (this->ProjectToLimit ? "On" : "Off") << "\n";
  os << indent << "ComputeLimitNormals: " << (this->ComputeLimitNormals ? "On" : "Off") << "\n";
  os << indent << "ComputeCurvature: " << (this->ComputeCurvature ? "On" : "Off") << "\n";
  os << indent << "GenerateParentCellIds: " << (this->GenerateParentCellIds ? "On" : "Off") << "\n";
  auto name = [](const char* n) { return n ? n : "(none)"; };
  os << indent << "SharpnessArrayName: " << name(this->SharpnessArrayName) << "\n";
  os << indent << "CornerSharpnessArrayName: " << name(this->CornerSharpnessArrayName) << "\n";
  os << indent << "HoleArrayName: " << name(this->HoleArrayName) << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << " MiB\n";
  os << indent << "NumberOfStencilBuilds: " << this->NumberOfStencilBuilds << "\n";
}
