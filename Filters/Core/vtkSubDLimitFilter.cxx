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
  const int outputGhostLevels = request.OutputGhostLevels;
  const bool quads = this->Scheme == CATMULL_CLARK;
  vtkSubDCage cage;
  std::string error, warning;
  const bool read = vtkSubDReadCage(input, !quads, static_cast<subd::BoundaryRule>(this->BoundaryRule),
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
  const subd::Level& level = cage.Level;
  const subd::MeshTopology& topo = level.Topology;
  // A piece tessellates its own faces, and the first outputGhostLevels layers of ghost faces.
  if (request.OneOfMany && cage.FaceIsGhost.empty() && !locations)
  {
    vtkWarningMacro(<< vtkSubDMissingGhostsWarning(request.Piece, 1));
  }
  const std::vector<std::uint8_t> ghostLayer =
    cage.FaceIsGhost.empty() ? std::vector<std::uint8_t>() : vtkSubDGhostLayers(topo, cage.FaceIsGhost, outputGhostLevels);
  const subd::LimitEvaluator evaluator(*scheme, level);
  std::string evaluatorError;
  if (!evaluator.IsValid(evaluatorError))
  {
    vtkErrorMacro(<< evaluatorError << ".");
    return 0;
  }

  // The samples, grouped by face: each evaluated once, by the face that owns it.
  std::vector<FaceGrid> grids;
  vtkIdType numSamples = 0;
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdTypeArray> cellFace;
  cellFace->SetName("FaceId");
  if (locations)
  {
    vtkDataArray* ids = locations->GetPointData()->GetArray("FaceId");
    vtkDataArray* uv = locations->GetPointData()->GetArray("FaceUV");
    vtkDataArray* sub = locations->GetPointData()->GetArray("SubFace");
    if (!ids || !uv || uv->GetNumberOfComponents() != 2)
    {
      vtkErrorMacro("The locations need point-data arrays \"FaceId\" and \"FaceUV\" (2 components).");
      return 0;
    }
    numSamples = locations->GetNumberOfPoints();
    std::map<subd::Index, size_t> gridOf;
    for (vtkIdType i = 0; i < numSamples; ++i)
    {
      const double cell = ids->GetComponent(i, 0);
      auto known = cell == std::floor(cell) ? cage.FaceOfCell.find(static_cast<vtkIdType>(cell)) : cage.FaceOfCell.end();
      if (known == cage.FaceOfCell.end())
      {
        vtkErrorMacro("Location " << i << " names cell " << cell << ", which is not a polygon of the input.");
        return 0;
      }
      const subd::Index face = known->second;
      auto found = gridOf.emplace(face, grids.size());
      if (found.second)
      {
        grids.push_back({ face, {}, {} });
      }
      subd::FaceSample s;
      s.U = uv->GetComponent(i, 0);
      s.V = uv->GetComponent(i, 1);
      s.SubFace = sub ? static_cast<subd::Index>(sub->GetComponent(i, 0)) : 0;
      grids[found.first->second].Owned.push_back(s);
      grids[found.first->second].OwnedIds.push_back(i);
      cells->InsertNextCell(1, &i);
    }
  }
  else
  {
    bool polygons = false;
    for (subd::Index f = 0; f < topo.GetNumFaces() && quads; ++f)
    {
      polygons = polygons || topo.GetFaceSize(f) != 4;
    }
    const int R = polygons ? 2 * ((this->Resolution + 1) / 2) : this->Resolution;
    std::map<SampleKey, vtkIdType> idOf;
    enum { Vertex, Edge, Inside, Spoke, Centre };
    // The key of the point `t` segments (of R along the edge) from corner c toward the next
    // corner along edge k of face f.
    auto edgeKey = [&](subd::Index f, subd::Index k, int t) -> SampleKey {
      const subd::IndexSpan fv = topo.GetFaceVertices(f);
      const subd::Index e = topo.GetFaceEdges(f)[k];
      if (t == 0)
        return { Vertex, fv[k], 0, 0 };
      if (t == R)
        return { Vertex, fv[(k + 1) % fv.size()], 0, 0 };
      const bool forward = topo.GetEdgeVertices(e)[0] == fv[k];
      return { Edge, e, forward ? t : R - t, 0 };
    };
    for (subd::Index f = 0; f < topo.GetNumFaces(); ++f)
    {
      if (level.FaceIsHole[f] || (!ghostLayer.empty() && ghostLayer[f] > outputGhostLevels))
      {
        continue;
      }
      FaceGrid grid{ f, {}, {} };
      const subd::Index n = topo.GetFaceSize(f);
      auto point = [&](const SampleKey& key, const subd::FaceSample& s) {
        auto found = idOf.emplace(key, numSamples);
        if (found.second)
        {
          grid.Owned.push_back(s);
          grid.OwnedIds.push_back(numSamples++);
        }
        return found.first->second;
      };
      if (!quads)
      {
        // (i, j) with i + j <= R: corners (0,0), (R,0), (0,R).
        std::vector<vtkIdType> ids;
        auto index = [R](int i, int j) { return static_cast<size_t>(j * (R + 1) + i); };
        ids.assign(static_cast<size_t>((R + 1) * (R + 1)), -1);
        for (int j = 0; j <= R; ++j)
        {
          for (int i = 0; i + j <= R; ++i)
          {
            SampleKey key{ Inside, f, i, j };
            if (j == 0)
              key = edgeKey(f, 0, i);
            else if (i + j == R)
              key = edgeKey(f, 1, j);
            else if (i == 0)
              key = edgeKey(f, 2, R - j);
            subd::FaceSample s;
            s.U = static_cast<double>(i) / R;
            s.V = static_cast<double>(j) / R;
            ids[index(i, j)] = point(key, s);
          }
        }
        for (int j = 0; j < R; ++j)
        {
          for (int i = 0; i + j < R; ++i)
          {
            const vtkIdType up[3] = { ids[index(i, j)], ids[index(i + 1, j)], ids[index(i, j + 1)] };
            cells->InsertNextCell(3, up);
            cellFace->InsertNextValue(cage.FaceCell[f]);
            if (i + j + 1 < R)
            {
              const vtkIdType down[3] = { ids[index(i + 1, j)], ids[index(i + 1, j + 1)], ids[index(i, j + 1)] };
              cells->InsertNextCell(3, down);
              cellFace->InsertNextValue(cage.FaceCell[f]);
            }
          }
        }
      }
      else
      {
        // Quads: one R x R grid; other polygons: per corner k an S x S grid, S = R/2, with
        // (0,0) at corner k, (S,0) at the middle of edge k, (S,S) at the centre.
        const bool whole = n == 4;
        const int S = whole ? R : R / 2;
        for (subd::Index k = 0; k < (whole ? 1 : n); ++k)
        {
          std::vector<vtkIdType> ids(static_cast<size_t>((S + 1) * (S + 1)));
          for (int j = 0; j <= S; ++j)
          {
            for (int i = 0; i <= S; ++i)
            {
              SampleKey key{ Inside, f, k * (S + 1) * (S + 1) + j * (S + 1) + i, 0 };
              if (whole)
              {
                if (j == 0)
                  key = edgeKey(f, 0, i);
                else if (i == S)
                  key = edgeKey(f, 1, j);
                else if (j == S)
                  key = edgeKey(f, 2, S - i);
                else if (i == 0)
                  key = edgeKey(f, 3, S - j);
              }
              else if (i == S && j == S)
                key = { Centre, f, 0, 0 };
              else if (j == 0)
                key = edgeKey(f, k, i);
              else if (i == 0)
                key = edgeKey(f, (k + n - 1) % n, R - j);
              else if (i == S)
                key = { Spoke, f, k, j };
              else if (j == S)
                key = { Spoke, f, (k + n - 1) % n, i };
              subd::FaceSample s;
              s.U = static_cast<double>(i) / S;
              s.V = static_cast<double>(j) / S;
              s.SubFace = k;
              ids[static_cast<size_t>(j * (S + 1) + i)] = point(key, s);
            }
          }
          for (int j = 0; j < S; ++j)
          {
            for (int i = 0; i < S; ++i)
            {
              auto id = [&](int a, int b) { return ids[static_cast<size_t>(b * (S + 1) + a)]; };
              const vtkIdType quad[4] = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) };
              cells->InsertNextCell(4, quad);
              cellFace->InsertNextValue(cage.FaceCell[f]);
            }
          }
        }
      }
      grids.push_back(std::move(grid));
    }
  }

  // Evaluate, face by face in parallel.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numSamples);
  double* xyz = static_cast<vtkDoubleArray*>(points->GetData())->GetPointer(0);
  vtkSubDLimitGeometry geometry(numSamples, this->ComputeNormals, this->ComputeCurvature, this->ComputeDerivatives);
  // The cage's point data, in double, evaluated with the limit weights and stored by the
  // surface filters' rules (integers rounded and clamped, normals re-normalized).
  vtkPointData* inPD = input->GetPointData();
  struct CarriedArray
  {
    vtkDataArray* Input;
    int Components;
    bool Normals;
    std::vector<double> Cage, Samples;
  };
  std::vector<CarriedArray> carried;
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
        for (CarriedArray& c : carried)
        {
          stencils[s].Apply(stencils[s].Weights, subd::PatchValue, c.Cage.data(), c.Components,
            c.Samples.data() + id * c.Components);
        }
      }
    }
  });
  if (!firstError.empty())
  {
    vtkErrorMacro(<< firstError << ".");
    output->Initialize();
    return 0;
  }
  output->SetPoints(points);
  if (locations)
  {
    output->SetVerts(cells);
    output->GetPointData()->PassData(locations->GetPointData());
  }
  else
  {
    output->SetPolys(cells);
    AddCellData(input, cellFace, !ghostLayer.empty(), output);
  }
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
