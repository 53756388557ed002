#include "vtkSubDCurveFilter.h"
#include "vtkSubDMemoryBudget.h"
#include "vtkSubDOutOfMemory.h"

#include "SubDCurveLimit.h"
#include "SubDCurveRefiner.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDInputLines.h"
#include "vtkSubDPieces.h"
#include "vtkSubDPointDataInterpolation.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDCurveFilter);

namespace
{
// Unit tangents per output curve point: the tangent rows are one per piece entry; a point in
// several pieces (a corner) gets the normalized mean of its unit tangents.
vtkSmartPointer<vtkDoubleArray> UnitTangents(const subd::StencilTable& rows, const subd::CurvePieces& pieces,
  const std::vector<double>& points, vtkIdType numPoints, vtkIdType shift)
{
  std::vector<double> raw(static_cast<size_t>(rows.GetNumRows()) * 3);
  rows.Apply(points.data(), raw.data(), 3);
  auto tangents = vtkSmartPointer<vtkDoubleArray>::New();
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(3);
  tangents->SetNumberOfTuples(shift + numPoints);
  tangents->FillValue(0.0);
  double* out = tangents->GetPointer(0) + 3 * shift;
  for (size_t r = 0; r < pieces.Points.size(); ++r)
  {
    const double* t = raw.data() + 3 * r;
    const double norm = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
    if (norm > 0.0)
    {
      double* o = out + 3 * static_cast<size_t>(pieces.Points[r]);
      for (int c = 0; c < 3; ++c)
      {
        o[c] += t[c] / norm;
      }
    }
  }
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    double* o = out + 3 * i;
    const double norm = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
    for (int c = 0; c < 3 && norm > 0.0; ++c)
    {
      o[c] /= norm;
    }
  }
  return tangents;
}

// One output polyline per kept input line: its pieces joined at their shared end points.
// A one-point line becomes a vertex cell (VTK's cell links refuse one-point lines; this is
// what vtkCleanPolyData does with them too), appended to `verts`.
void OutputCells(const subd::CurvePieces& pieces, const std::vector<subd::Index>& firstPiece, vtkIdType shift,
  vtkCellArray* lines, vtkCellArray* verts, std::vector<bool>& isVertex)
{
  std::vector<vtkIdType> ids;
  isVertex.assign(firstPiece.size() - 1, false);
  for (size_t line = 0; line + 1 < firstPiece.size(); ++line)
  {
    ids.clear();
    for (subd::Index p = firstPiece[line]; p < firstPiece[line + 1]; ++p)
    {
      const subd::IndexSpan piece = pieces.GetPiece(p);
      for (subd::Index k = ids.empty() ? 0 : 1; k < piece.size(); ++k)
      {
        ids.push_back(shift + piece[k]);
      }
      if (pieces.IsClosed(p))
      {
        ids.push_back(shift + piece[0]);
      }
    }
    isVertex[line] = ids.size() == 1;
    (isVertex[line] ? verts : lines)->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
}

// `curve` (values of the curve points) after `shift` tuples of `input` (the points that
// other cells use), in one array of the input's type.
vtkSmartPointer<vtkDataArray> Concatenate(vtkDataArray* input, vtkDataArray* curve, vtkIdType shift)
{
  if (shift == 0)
  {
    return curve;
  }
  vtkSmartPointer<vtkDataArray> out = vtkSmartPointer<vtkDataArray>::Take(curve->NewInstance());
  out->SetName(curve->GetName());
  out->SetNumberOfComponents(curve->GetNumberOfComponents());
  out->SetNumberOfTuples(shift + curve->GetNumberOfTuples());
  out->InsertTuples(0, shift, 0, input);
  out->InsertTuples(shift, curve->GetNumberOfTuples(), 0, curve);
  return out;
}

// The output's cells in VTK's order (verts, lines, polys, strips), each with its input cell's
// data: the input's verts, then the refined curves (single points as verts), then its
// polygons and strips, passed through.
void WriteCells(vtkPolyData* input, const std::vector<vtkIdType>& lineCells, const subd::CurvePieces& finest,
  const std::vector<subd::Index>& firstPiece, vtkIdType shift, vtkPolyData* output)
{
  vtkNew<vtkCellArray> outVerts, outLines;
  outVerts->DeepCopy(input->GetVerts());
  std::vector<bool> isVertex;
  OutputCells(finest, firstPiece, shift, outLines, outVerts, isVertex);
  const vtkIdType numVerts = input->GetNumberOfVerts(), numInputLines = input->GetNumberOfLines();
  const vtkIdType numOtherCells = input->GetNumberOfPolys() + input->GetNumberOfStrips();
  vtkNew<vtkIdList> sources;
  for (vtkIdType c = 0; c < numVerts; ++c)
  {
    sources->InsertNextId(c);
  }
  for (bool vertices : { true, false })
  {
    for (size_t line = 0; line < lineCells.size(); ++line)
    {
      if (isVertex[line] == vertices)
      {
        sources->InsertNextId(lineCells[line]);
      }
    }
  }
  for (vtkIdType c = 0; c < numOtherCells; ++c)
  {
    sources->InsertNextId(numVerts + numInputLines + c);
  }
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, sources->GetNumberOfIds());
  for (vtkIdType c = 0; c < sources->GetNumberOfIds(); ++c)
  {
    outCD->CopyData(inCD, sources->GetId(c), c);
  }
  if (vtkUnsignedCharArray* inputMarks = input->GetCellGhostArray())
  {
    // A piece's ghost cells stay ghosts (CopyData leaves the ghost array out).
    vtkNew<vtkUnsignedCharArray> marks;
    marks->SetName(vtkDataSetAttributes::GhostArrayName());
    marks->SetNumberOfTuples(sources->GetNumberOfIds());
    for (vtkIdType c = 0; c < sources->GetNumberOfIds(); ++c)
    {
      marks->SetValue(c, inputMarks->GetValue(sources->GetId(c)));
    }
    outCD->RemoveArray(vtkDataSetAttributes::GhostArrayName());
    outCD->AddArray(marks);
  }
  if (outVerts->GetNumberOfCells() > 0)
  {
    output->SetVerts(outVerts);
  }
  output->SetLines(outLines);
  if (input->GetNumberOfPolys() > 0)
  {
    output->SetPolys(input->GetPolys());
  }
  if (input->GetNumberOfStrips() > 0)
  {
    output->SetStrips(input->GetStrips());
  }
  vtkSubDMarkGhostPoints(output); // a piece's ghost lines (asked for downstream) keep their mark
}
}

vtkSubDCurveFilter::vtkSubDCurveFilter()
  : MaximumMemory(vtkSubDDefaultMemoryBudget())
{
}
vtkSubDCurveFilter::~vtkSubDCurveFilter() = default;

const char* vtkSubDCurveFilter::GetSchemeAsString()
{
  return subd::ToString(static_cast<subd::CurveScheme>(this->Scheme));
}

int vtkSubDCurveFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkSubDRunCatchingOutOfMemory(this, vtkPolyData::GetData(outputVector),
    [&]() { return this->Execute(request, inputVector, outputVector); },
    [this](unsigned long code) { this->SetErrorCode(code); });
}

int vtkSubDCurveFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->SetErrorCode(vtkErrorCode::NoError);
  auto fail = [this, output]() {
    output->Initialize();
    this->SetErrorCode(vtkErrorCode::UserError);
    return 0;
  };
  if (!this->CheckInput(input))
  {
    return fail();
  }
  if (!input || input->GetNumberOfLines() == 0)
  {
    vtkWarningMacro(<< "Input has no lines (line or polyline cells) to refine; "
                    << (input ? input->GetNumberOfCells() : 0) << " other cells passed through unchanged.");
    if (input)
    {
      output->ShallowCopy(input);
    }
    return 1;
  }
  const vtkSubDInputLines lines = vtkSubDReadInputLines(input, this->Closed);
  if (lines.FirstBadCell >= 0)
  {
    vtkErrorMacro("Cell " << lines.FirstBadCell << " refers to a point id outside 0.." << input->GetNumberOfPoints() - 1
                          << ".");
    return fail();
  }
  if (lines.Empty > 0)
  {
    vtkWarningMacro(<< lines.Empty << " line cell(s) without points were dropped.");
  }
  if (lines.SinglePoint > 0)
  {
    vtkWarningMacro(<< lines.SinglePoint << " polyline(s) of a single point cannot be refined; each is kept as a vertex cell.");
  }

  subd::CurveRules rules;
  rules.Scheme = static_cast<subd::CurveScheme>(this->Scheme);
  rules.Tension = this->Tension;
  const std::vector<unsigned char> corners = vtkSubDReadCurveCorners(input);
  subd::CurvePieces pieces;
  std::vector<subd::Index> firstPiece;
  subd::SplitAtCorners(
    subd::CurveLines{ &lines.Offsets, &lines.Ids, &lines.Closed, &corners }, pieces, firstPiece);
  if (!this->FitsTheMemoryBudget(subd::PredictCurvePoints(rules, pieces, this->NumberOfSubdivisions), input))
  {
    return fail();
  }
  subd::Hierarchy hierarchy;
  subd::CurvePieces finest;
  if (!subd::RefineCurves(rules, static_cast<subd::Index>(input->GetNumberOfPoints()), pieces,
        this->NumberOfSubdivisions, hierarchy, finest, this->Progress(0.0, 0.4)))
  {
    output->Initialize();
    return 1; // aborted: empty output, not an error
  }
  // Points: the input's points first when other cells use them.
  const bool keepInputPoints = input->GetNumberOfVerts() + input->GetNumberOfPolys() + input->GetNumberOfStrips() > 0;
  const vtkIdType shift = keepInputPoints ? input->GetNumberOfPoints() : 0;
  const std::vector<double> curvePoints = this->WritePoints(input, rules, finest, hierarchy, shift, output);
  this->UpdateProgress(0.5);
  if (!this->InterpolatePointData(input, hierarchy, finest.NumAnchors, shift, output))
  {
    output->Initialize();
    return 1; // aborted
  }
  if (this->ComputeTangents)
  {
    const subd::Index numCurvePoints = static_cast<subd::Index>(curvePoints.size() / 3);
    output->GetPointData()->SetTangents(UnitTangents(
      subd::CurveTangentStencils(rules, finest, numCurvePoints), finest, curvePoints, numCurvePoints, shift));
  }
  WriteCells(input, lines.CellIds, finest, firstPiece, shift, output);
  this->UpdateProgress(1.0);
  return 1;
}

bool vtkSubDCurveFilter::CheckInput(vtkPolyData* input)
{
  // Checked before anything passes through: a non-finite point is an error, lines or not.
  const vtkIdType badPoint = input && input->GetNumberOfPoints() > 0 ? vtkSubDFirstNonFinitePoint(input->GetPoints()) : -1;
  if (badPoint >= 0)
  {
    double p[3];
    input->GetPoint(badPoint, p);
    vtkErrorMacro("Point " << badPoint << " has a non-finite coordinate (" << p[0] << ", " << p[1] << ", "
                           << p[2] << "): the curves cannot be subdivided.");
    return false;
  }
  // Cells are checked too, also those that only pass through.
  const vtkIdType badCell = input ? vtkSubDFirstCellOutsidePoints(input) : -1;
  if (badCell >= 0)
  {
    vtkErrorMacro("Cell " << badCell << " refers to a point id outside 0.." << input->GetNumberOfPoints() - 1 << ".");
    return false;
  }
  const vtkIdType numPoints = input ? input->GetNumberOfPoints() : 0;
  if (numPoints >= static_cast<vtkIdType>(std::numeric_limits<subd::Index>::max() / 4))
  {
    vtkErrorMacro("Input has " << numPoints << " points; at most "
                               << std::numeric_limits<subd::Index>::max() / 4 << " are supported.");
    return false;
  }
  return true;
}

bool vtkSubDCurveFilter::FitsTheMemoryBudget(double predictedPoints, vtkPolyData* input)
{
  // 3 doubles per point, plus the point data, before anything large exists.
  double bytesPerPoint = 3.0 * sizeof(double) + (this->ComputeTangents ? 24.0 : 0.0);
  for (int a = 0; a < input->GetPointData()->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = input->GetPointData()->GetArray(a))
    {
      bytesPerPoint += array->GetNumberOfComponents() * sizeof(double);
    }
  }
  if (predictedPoints >= std::numeric_limits<subd::Index>::max() / 2 ||
    predictedPoints * bytesPerPoint > this->MaximumMemory * 1024.0 * 1024.0)
  {
    vtkErrorMacro("Refusing " << this->NumberOfSubdivisions << " level(s): about " << predictedPoints
                              << " output points would need " << predictedPoints * bytesPerPoint / (1024.0 * 1024.0)
                              << " MiB, above MaximumMemory (" << this->MaximumMemory << " MiB).");
    return false;
  }
  return true;
}

std::function<bool(double)> vtkSubDCurveFilter::Progress(double first, double span)
{
  return [this, first, span](double fraction) {
    this->UpdateProgress(first + span * fraction);
    return !this->GetAbortExecute();
  };
}

std::vector<double> vtkSubDCurveFilter::WritePoints(vtkPolyData* input, const subd::CurveRules& rules,
  const subd::CurvePieces& finest, subd::Hierarchy& hierarchy, vtkIdType shift, vtkPolyData* output)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  const int levelTables = hierarchy.GetNumStencilTables();
  const subd::Index numCurvePoints = hierarchy.GetNumFinestPoints();
  if (this->ProjectToLimit)
  {
    hierarchy.Stencils.push_back(subd::CurveLimitStencils(rules, finest, numCurvePoints));
  }
  std::vector<double> basePoints(static_cast<size_t>(numPoints) * 3);
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    input->GetPoint(i, basePoints.data() + 3 * i);
  }
  std::vector<double> curvePoints(static_cast<size_t>(numCurvePoints) * 3);
  hierarchy.Evaluate(
    basePoints.data(), 3, curvePoints.data(), vtkSubDPointDataInterpolation::SMPFor, nullptr, levelTables);
  int precision = this->OutputPointsPrecision;
  if (precision == DEFAULT_PRECISION)
  {
    precision = input->GetPoints()->GetDataType() == VTK_DOUBLE ? DOUBLE_PRECISION : SINGLE_PRECISION;
  }
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(precision == DOUBLE_PRECISION ? VTK_DOUBLE : VTK_FLOAT);
  outPoints->SetNumberOfPoints(shift + numCurvePoints);
  for (vtkIdType i = 0; i < shift; ++i)
  {
    outPoints->SetPoint(i, basePoints.data() + 3 * i);
  }
  std::vector<double> limitPoints;
  if (this->ProjectToLimit)
  {
    limitPoints.resize(curvePoints.size());
    hierarchy.Stencils.back().Apply(curvePoints.data(), limitPoints.data(), 3);
  }
  const double* finalPoints = this->ProjectToLimit ? limitPoints.data() : curvePoints.data();
  for (vtkIdType i = 0; i < numCurvePoints; ++i)
  {
    outPoints->SetPoint(shift + i, finalPoints + 3 * i);
  }
  output->SetPoints(outPoints);
  return curvePoints;
}

bool vtkSubDCurveFilter::InterpolatePointData(
  vtkPolyData* input, const subd::Hierarchy& hierarchy, std::int32_t numAnchors, vtkIdType shift, vtkPolyData* output)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  vtkSubDPointDataInterpolation interpolation(hierarchy, vtkSubDPointDataInterpolation::SMPFor, nullptr);
  const int numArrays = inPD->GetNumberOfArrays();
  for (int a = 0; a < numArrays; ++a)
  {
    vtkAbstractArray* abstractArray = inPD->GetAbstractArray(a);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstractArray);
    const std::string name = abstractArray->GetName() ? abstractArray->GetName() : "";
    if (array && array == input->GetPointGhostArray())
    {
      continue; // bit flags, made anew for the output below
    }
    if (!array || array->GetNumberOfTuples() != numPoints)
    {
      vtkWarningMacro(<< "Point-data array '" << name << "' is not numeric or has "
                      << abstractArray->GetNumberOfTuples() << " tuples for " << numPoints
                      << " points; it is not passed on.");
      continue;
    }
    const int attribute = inPD->IsArrayAnAttribute(a);
    vtkSmartPointer<vtkDataArray> curve = interpolation.Interpolate(array, array->GetDataType(),
      attribute == vtkDataSetAttributes::NORMALS, this->Progress(0.5 + 0.4 * a / numArrays, 0.4 / numArrays));
    if (!curve)
    {
      return false;
    }
    if (name == "CornerSharpness")
    {
      // Corners and ends keep theirs (they are anchors); new points are smooth.
      for (vtkIdType i = numAnchors; i < curve->GetNumberOfTuples(); ++i)
      {
        curve->SetComponent(i, 0, 0.0);
      }
    }
    outPD->AddArray(Concatenate(array, curve, shift));
    if (attribute >= 0)
    {
      outPD->SetActiveAttribute(outPD->GetNumberOfArrays() - 1, attribute);
    }
  }
  return true;
}

void vtkSubDCurveFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->GetSchemeAsString() << "\n";
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "Closed: " << (this->Closed ? "On" : "Off") << "\n";
  os << indent << "ProjectToLimit: " << (this->ProjectToLimit ? "On" : "Off") << "\n";
  os << indent << "ComputeTangents: " << (this->ComputeTangents ? "On" : "Off") << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "MaximumMemory: " << this->MaximumMemory << "\n";
}
