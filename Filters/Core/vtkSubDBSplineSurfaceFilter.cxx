#include "vtkSubDBSplineSurfaceFilter.h"

#include "SubDBSplineSurface.h"
#include "SubDQuadGrid.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDMemoryBudget.h"
#include "vtkSubDOutOfMemory.h"
#include "vtkSubDPieces.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDBSplineSurfaceFilter);

namespace
{
// The point-data arrays that ride along with the coordinates: every numeric array but the
// parameters and VTK's bookkeeping (ghost and id arrays make no sense blended).
struct CarriedArrays
{
  std::vector<vtkDataArray*> Arrays;
  int Components = 3; // x y z, then each array's components

  CarriedArrays(vtkPointData* pointData, vtkIdType numPoints, vtkDataArray* skip)
  {
    for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = pointData->GetArray(a);
      if (!array || array == skip || !array->GetName() || vtkIdTypeArray::SafeDownCast(array) ||
        std::string(array->GetName()) == "vtkGhostType" || array->GetNumberOfTuples() != numPoints)
      {
        continue;
      }
      this->Arrays.push_back(array);
      this->Components += array->GetNumberOfComponents();
    }
  }

  // The values of point `id`: coordinates, then the arrays' components.
  void Gather(vtkPointSet* input, vtkIdType id, double* out) const
  {
    input->GetPoint(id, out);
    int k = 3;
    for (vtkDataArray* array : this->Arrays)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        out[k++] = array->GetComponent(id, c);
      }
    }
  }

  // Points and arrays of an n x m lattice of values (point (a, b) at a + b n), with its quads.
  void MakeLattice(vtkIdType n, vtkIdType m, const std::vector<double>& values, vtkPolyData* mesh) const
  {
    const vtkIdType count = n * m;
    const size_t K = static_cast<size_t>(this->Components);
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(count);
    for (vtkIdType p = 0; p < count; ++p)
    {
      coordinates->SetTypedTuple(p, &values[p * K]);
    }
    vtkNew<vtkPoints> points;
    points->SetData(coordinates);
    mesh->SetPoints(points);
    int k = 3;
    for (vtkDataArray* source : this->Arrays)
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(source->GetName());
      array->SetNumberOfComponents(source->GetNumberOfComponents());
      array->SetNumberOfTuples(count);
      for (vtkIdType p = 0; p < count; ++p)
      {
        for (int c = 0; c < source->GetNumberOfComponents(); ++c)
        {
          array->SetComponent(p, c, values[p * K + k + c]);
        }
      }
      k += source->GetNumberOfComponents();
      mesh->GetPointData()->AddArray(array);
    }
    vtkNew<vtkCellArray> quads;
    quads->AllocateExact((n - 1) * (m - 1), 4 * (n - 1) * (m - 1));
    for (vtkIdType b = 0; b + 1 < m; ++b)
    {
      for (vtkIdType a = 0; a + 1 < n; ++a)
      {
        const vtkIdType quad[4] = { a + b * n, a + 1 + b * n, a + 1 + (b + 1) * n, a + (b + 1) * n };
        quads->InsertNextCell(4, quad);
      }
    }
    mesh->SetPolys(quads);
  }
};

// The P x Q grid of a structured grid (one dimension 1) or of a quad-grid polydata.
bool ReadGrid(vtkPointSet* input, subd::QuadGrid& grid, std::string& error)
{
  if (auto* structured = vtkStructuredGrid::SafeDownCast(input))
  {
    int dims[3];
    structured->GetDimensions(dims);
    std::vector<int> sizes;
    for (int d : dims)
    {
      if (d > 1)
        sizes.push_back(d);
    }
    if (sizes.size() != 2)
    {
      error = "the structured grid has dimensions " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
        std::to_string(dims[2]) + "; a surface grid has exactly two dimensions above 1";
      return false;
    }
    grid.P = sizes[0];
    grid.Q = sizes[1];
    grid.Points.resize(static_cast<size_t>(grid.P) * grid.Q);
    for (size_t p = 0; p < grid.Points.size(); ++p)
    {
      grid.Points[p] = static_cast<subd::Index>(p); // VTK's order: the first dimension fastest
    }
    return true;
  }
  auto* polyData = vtkPolyData::SafeDownCast(input);
  if (!polyData)
  {
    error = std::string("a ") + input->GetClassName() + " is not a grid: give a vtkStructuredGrid or quads in a vtkPolyData";
    return false;
  }
  const vtkIdType badCell = vtkSubDFirstCellOutsidePoints(polyData);
  if (badCell >= 0)
  {
    error = "cell " + std::to_string(badCell) + " refers to a point id outside 0.." +
      std::to_string(polyData->GetNumberOfPoints() - 1);
    return false;
  }
  const vtkSubDInputFaces faces = vtkSubDGatherFaces(polyData);
  std::vector<subd::Index> offsets(static_cast<size_t>(faces.NumFaces) + 1), ids;
  for (vtkIdType f = 0; f < faces.NumFaces; ++f)
  {
    for (vtkIdType k = faces.Offsets[f]; k < faces.Offsets[f + 1]; ++k)
    {
      ids.push_back(static_cast<subd::Index>(faces.Connectivity[k]));
    }
    offsets[f + 1] = static_cast<subd::Index>(ids.size());
  }
  if (!subd::FindQuadGrid(static_cast<subd::Index>(polyData->GetNumberOfPoints()), offsets, ids, grid, error))
  {
    error = "the input is not a grid of quads: " + error;
    return false;
  }
  return true;
}

// The scattered points' (u, v) parameters: the named point-data array, else the texture
// coordinates, of 2 components or more and one tuple per point; null, with the reason, if
// there are none.
vtkDataArray* FindParameters(vtkPointSet* input, const char* name, std::string& error)
{
  vtkDataArray* parameters = name ? input->GetPointData()->GetArray(name) : nullptr;
  if (!parameters)
  {
    parameters = input->GetPointData()->GetTCoords();
  }
  if (!parameters || parameters->GetNumberOfComponents() < 2)
  {
    error = std::string("the input has no 2-component point-data array \"") + (name ? name : "") +
      "\" and no texture coordinates: scattered points need (u, v) parameters";
    return nullptr;
  }
  if (parameters->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    error = "the parameter array has " + std::to_string(parameters->GetNumberOfTuples()) + " tuples for " +
      std::to_string(input->GetNumberOfPoints()) + " points";
    return nullptr;
  }
  return parameters;
}

// Refuses, before anything large exists, a net and surface that would need more than half
// the physical memory: the fit's banded normal matrix (49 doubles per control point), the
// net and the evaluated surface. Returns the reason, or nothing.
std::string SizeGuard(subd::Index D, subd::Index E, size_t K, int samplesPerSpan)
{
  const double numSamples =
    (static_cast<double>(D - 3) * samplesPerSpan + 1) * (static_cast<double>(E - 3) * samplesPerSpan + 1);
  const double bytes = 8.0 * (static_cast<double>(D) * E * (49.0 + K) + numSamples * (K + 3.0));
  if (bytes <= vtkSubDDefaultMemoryBudget() * 1024.0 * 1024.0)
  {
    return std::string();
  }
  return "refusing: about " + std::to_string(static_cast<long long>(numSamples)) + " surface samples and a net of " +
    std::to_string(static_cast<long long>(D) * E) + " points need " +
    std::to_string(static_cast<long long>(bytes / (1024.0 * 1024.0))) +
    " MiB, above half the physical memory; lower SamplesPerSpan or NumberOfControlPoints";
}

// The surface of the D x E net `control`, samplesPerSpan samples per knot span, with unit
// normals from the exact derivatives.
void EvaluateSurface(const std::vector<double>& control, subd::Index D, subd::Index E, const CarriedArrays& carried,
  int samplesPerSpan, vtkPolyData* surface)
{
  const size_t K = static_cast<size_t>(carried.Components);
  const vtkIdType Ns = static_cast<vtkIdType>(D - 3) * samplesPerSpan + 1;
  const vtkIdType Nt = static_cast<vtkIdType>(E - 3) * samplesPerSpan + 1;
  std::vector<double> samples(static_cast<size_t>(Ns * Nt) * K);
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(Ns * Nt);
  std::vector<double> ds(K), dt(K);
  for (vtkIdType b = 0; b < Nt; ++b)
  {
    for (vtkIdType a = 0; a < Ns; ++a)
    {
      const vtkIdType p = a + b * Ns;
      subd::EvaluateBicubic(control, D, E, carried.Components, static_cast<double>(a) / samplesPerSpan,
        static_cast<double>(b) / samplesPerSpan, &samples[p * K], ds.data(), dt.data());
      double normal[3];
      vtkMath::Cross(ds.data(), dt.data(), normal);
      vtkMath::Normalize(normal);
      normals->SetTypedTuple(p, normal);
    }
  }
  carried.MakeLattice(Ns, Nt, samples, surface);
  surface->GetPointData()->SetNormals(normals);
}
}

vtkSubDBSplineSurfaceFilter::vtkSubDBSplineSurfaceFilter()
{
  this->SetNumberOfOutputPorts(2);
  this->SetParameterArrayName("UV");
}

vtkSubDBSplineSurfaceFilter::~vtkSubDBSplineSurfaceFilter()
{
  this->SetParameterArrayName(nullptr);
}

void vtkSubDBSplineSurfaceFilter::SetNumberOfControlPoints(int u, int v)
{
  u = std::clamp(u, 4, 4096);
  v = std::clamp(v, 4, 4096);
  if (u != this->NumberOfControlPoints[0] || v != this->NumberOfControlPoints[1])
  {
    this->NumberOfControlPoints[0] = u;
    this->NumberOfControlPoints[1] = v;
    this->Modified();
  }
}

int vtkSubDBSplineSurfaceFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkSubDBSplineSurfaceFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkSubDRequestWholeInput(inputVector, this->GetNumberOfInputPorts());
  return 1;
}

int vtkSubDBSplineSurfaceFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkSubDRunCatchingOutOfMemory(
    this, vtkPolyData::GetData(outputVector, 0), [&]() { return this->Execute(request, inputVector, outputVector); },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

int vtkSubDBSplineSurfaceFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* net = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  net->Initialize();
  surface->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  this->RmsError = this->MaxError = 0.0;
  if (vtkSubDPieceRequest(outputVector->GetInformationObject(0)).IsLaterPiece())
  {
    return 1; // piece 0 holds the whole result
  }
  auto fail = [&](const std::string& why) {
    vtkErrorMacro(<< vtkSubDSentence(why));
    net->Initialize();
    surface->Initialize();
    this->SetErrorCode(vtkErrorCode::UserError);
    return 0;
  };
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return fail("the input has no points");
  }
  const vtkIdType badPoint = vtkSubDFirstNonFinitePoint(input->GetPoints());
  if (badPoint >= 0)
  {
    return fail("point " + std::to_string(badPoint) + " has a non-finite coordinate");
  }

  std::string error;
  vtkDataArray* parameters = nullptr;
  if (this->Mode == MODE_APPROXIMATE_SCATTERED && !(parameters = FindParameters(input, this->ParameterArrayName, error)))
  {
    return fail(error);
  }
  const CarriedArrays carried(input->GetPointData(), input->GetNumberOfPoints(), parameters);
  const size_t K = static_cast<size_t>(carried.Components);
  // The net's size: the grid's plus 2 (interpolation), or as asked (fit).
  subd::QuadGrid grid;
  if (this->Mode == MODE_INTERPOLATE_GRID && !ReadGrid(input, grid, error))
  {
    return fail(error);
  }
  const subd::Index D = this->Mode == MODE_INTERPOLATE_GRID ? grid.P + 2 : this->NumberOfControlPoints[0];
  const subd::Index E = this->Mode == MODE_INTERPOLATE_GRID ? grid.Q + 2 : this->NumberOfControlPoints[1];
  error = SizeGuard(D, E, K, this->SamplesPerSpan);
  if (!error.empty())
  {
    return fail(error);
  }
  std::vector<double> control;
  if (this->Mode == MODE_INTERPOLATE_GRID)
  {
    std::vector<double> data(grid.Points.size() * K);
    for (size_t p = 0; p < grid.Points.size(); ++p)
    {
      carried.Gather(input, grid.Points[p], &data[p * K]);
    }
    subd::InterpolateGrid(grid.P, grid.Q, data, carried.Components, control);
  }
  else
  {
    const vtkIdType n = input->GetNumberOfPoints();
    std::vector<double> uv(static_cast<size_t>(n) * 2), values(static_cast<size_t>(n) * K);
    for (vtkIdType p = 0; p < n; ++p)
    {
      uv[2 * p] = parameters->GetComponent(p, 0);
      uv[2 * p + 1] = parameters->GetComponent(p, 1);
      carried.Gather(input, p, &values[p * K]);
    }
    subd::BSplineFitReport report;
    if (!subd::FitBicubic(D, E, uv, values, carried.Components, this->ShapeWeight, control, report, error))
    {
      return fail(error);
    }
    this->RmsError = report.RmsError;
    this->MaxError = report.MaxError;
  }
  this->UpdateProgress(0.5);

  carried.MakeLattice(D, E, control, net);

  EvaluateSurface(control, D, E, carried, this->SamplesPerSpan, surface);
  return 1;
}

void vtkSubDBSplineSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == MODE_INTERPOLATE_GRID ? "interpolate grid" : "approximate scattered")
     << "\n";
  os << indent << "NumberOfControlPoints: " << this->NumberOfControlPoints[0] << " x "
     << this->NumberOfControlPoints[1] << "\n";
  os << indent << "ParameterArrayName: " << (this->ParameterArrayName ? this->ParameterArrayName : "(none)") << "\n";
  os << indent << "ShapeWeight: " << this->ShapeWeight << "\n";
  os << indent << "SamplesPerSpan: " << this->SamplesPerSpan << "\n";
  os << indent << "RmsError: " << this->RmsError << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
}
