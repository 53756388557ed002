#include "vtkSubDCurveInterpolateFilter.h"

#include "SubDCurveInterpolation.h"
#include "vtkSubDCurveFilter.h"
#include "vtkSubDInputFaces.h"
#include "vtkSubDInputLines.h"
#include "vtkSubDInterpolationSupport.h"

#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDCurveInterpolateFilter);

const char* vtkSubDCurveInterpolateFilter::GetSchemeAsString()
{
  return subd::ToString(static_cast<subd::CurveScheme>(this->Scheme));
}

int vtkSubDCurveInterpolateFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  auto fail = [this, output](const std::string& why) { return this->Fail(output, why); };

  if (!input || input->GetNumberOfLines() == 0)
  {
    return fail("the input has no lines (line or polyline cells) to interpolate");
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numPoints >= static_cast<vtkIdType>(std::numeric_limits<subd::Index>::max()))
  {
    return fail("the input has " + std::to_string(numPoints) + " points, more than the kernel's indices hold");
  }
  const vtkIdType badPoint = vtkSubDFirstNonFinitePoint(input->GetPoints());
  if (badPoint >= 0)
  {
    return fail("point " + std::to_string(badPoint) + " has a non-finite coordinate");
  }
  const vtkSubDInputLines lines = vtkSubDReadInputLines(input, this->Closed);
  if (lines.FirstBadCell >= 0)
  {
    return fail("cell " + std::to_string(lines.FirstBadCell) + " refers to a point id outside 0.." +
      std::to_string(numPoints - 1));
  }

  subd::CurveRules rules;
  rules.Scheme = static_cast<subd::CurveScheme>(this->Scheme);
  rules.Tension = this->Tension;
  const std::vector<unsigned char> corners = vtkSubDReadCurveCorners(input);
  subd::CurvePieces pieces;
  std::vector<subd::Index> firstPiece;
  subd::SplitAtCorners(subd::CurveLines{ &lines.Offsets, &lines.Ids, &lines.Closed, &corners }, pieces, firstPiece);
  std::vector<subd::SparseRow> rows;
  std::vector<std::string> problems;
  subd::BuildCurveLimitRows(rules, pieces, static_cast<subd::Index>(numPoints), rows, problems);

  // Points on no line are not on any curve: they stay where they are.
  std::vector<char> tagged = vtkSubDReadInterpolationTags(input, this->InterpolationArrayName);
  for (vtkIdType v = 0; v < numPoints; ++v)
  {
    if (tagged[v] && !problems[v].empty())
    {
      return fail("point " + std::to_string(v) + " is tagged but " + problems[v]);
    }
    tagged[v] = tagged[v] && !rows[v].Points.empty();
  }
  this->UpdateProgress(0.2);

  std::vector<double> targets(static_cast<size_t>(numPoints) * 3);
  for (vtkIdType v = 0; v < numPoints; ++v)
  {
    input->GetPoint(v, targets.data() + 3 * v);
  }
  std::vector<double> solved;
  std::string error;
  if (!this->Solve(rows, tagged, targets, solved, error))
  {
    return fail(error);
  }
  this->UpdateProgress(0.8);

  vtkSmartPointer<vtkPolyData> polygons = vtkSubDWithSolvedPoints(input, solved);
  if (!this->OutputRefinedCurve)
  {
    output->ShallowCopy(polygons);
    return 1;
  }
  vtkNew<vtkSubDCurveFilter> refine;
  refine->SetInputData(polygons);
  refine->SetScheme(this->Scheme);
  refine->SetTension(this->Tension);
  refine->SetClosed(this->Closed);
  refine->SetNumberOfSubdivisions(this->NumberOfSubdivisions);
  refine->Update();
  if (refine->GetErrorCode() != vtkErrorCode::NoError)
  {
    return fail("refining the interpolating polygons failed (see the error of vtkSubDCurveFilter)");
  }
  output->ShallowCopy(refine->GetOutput());
  return 1;
}

void vtkSubDCurveInterpolateFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->GetSchemeAsString() << "\n";
  os << indent << "Tension: " << this->Tension << "\n";
  os << indent << "Closed: " << this->Closed << "\n";
  os << indent << "OutputRefinedCurve: " << this->OutputRefinedCurve << "\n";
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
}
