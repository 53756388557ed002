#include "vtkSubDInterpolateFilter.h"

#include "SubDInterpolation.h"
#include "SubDScheme.h"
#include "vtkSubDCage.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDInterpolationSupport.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLoopFilter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSubDInterpolateFilter);

const char* vtkSubDInterpolateFilter::GetSchemeAsString()
{
  static const char* const names[] = { "catmull-clark", "loop", "doo-sabin" };
  return names[this->Scheme];
}

namespace
{
std::unique_ptr<subd::Scheme> NewScheme(int scheme)
{
  switch (scheme)
  {
    case vtkSubDInterpolateFilter::LOOP:
      return std::make_unique<subd::LoopScheme>();
    case vtkSubDInterpolateFilter::DOO_SABIN:
      return std::make_unique<subd::DooSabinScheme>();
    default:
      return std::make_unique<subd::CatmullClarkScheme>();
  }
}

vtkSmartPointer<vtkSubDSurfaceFilter> NewSurfaceFilter(int scheme)
{
  switch (scheme)
  {
    case vtkSubDInterpolateFilter::LOOP:
      return vtkSmartPointer<vtkSubDLoopFilter>::New();
    case vtkSubDInterpolateFilter::DOO_SABIN:
      return vtkSmartPointer<vtkSubDDooSabinFilter>::New();
    default:
      return vtkSmartPointer<vtkSubDCatmullClarkFilter>::New();
  }
}
}

int vtkSubDInterpolateFilter::Execute(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  auto fail = [this, output](const std::string& why) { return this->Fail(output, why); };

  vtkSubDCage cage;
  std::string error, warning;
  // Polygons repeating a point are kept as the Catmull-Clark and Loop filters keep them.
  const subd::RepeatedCorners repeated = this->Scheme == DOO_SABIN ? subd::RepeatedCorners::Collapse
    : this->Scheme == LOOP                                         ? subd::RepeatedCorners::KeepInTriangles
                                                                   : subd::RepeatedCorners::Keep;
  const vtkSubDCageFaces faces = this->Scheme == LOOP ? vtkSubDCageFaces::Triangles : vtkSubDCageFaces::Polygons;
  if (!vtkSubDReadCage(input, faces, repeated, static_cast<subd::BoundaryRule>(this->BoundaryRule),
        static_cast<subd::CreaseMethod>(this->CreaseMethod), cage, error, warning))
  {
    return fail(error);
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< vtkSubDSentence(warning));
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  std::vector<char> tagged = vtkSubDReadInterpolationTags(input, this->InterpolationArrayName);
  // Points on no face, or only on holes, are not on the surface: they stay where they are.
  vtkIdType offSurface = 0;
  for (vtkIdType v = 0; v < numPoints; ++v)
  {
    const bool onSurface = subd::IsOnLimitSurface(cage.Level, static_cast<subd::Index>(v));
    offSurface += tagged[v] && !onSurface ? 1 : 0;
    tagged[v] = tagged[v] && onSurface;
  }
  if (offSurface > 0)
  {
    vtkWarningMacro(<< offSurface << " tagged point(s) are on no face (or only on holes): they keep their positions.");
  }
  this->UpdateProgress(0.1);

  const std::unique_ptr<subd::Scheme> scheme = NewScheme(this->Scheme);
  std::vector<subd::SparseRow> rows;
  std::vector<std::string> problems;
  if (!subd::BuildVertexLimitRows(*scheme, cage.Level, rows, problems, error))
  {
    return fail(std::string("the ") + this->GetSchemeAsString() + " scheme has no limit points for this cage: " + error);
  }
  for (vtkIdType v = 0; v < numPoints; ++v)
  {
    if (tagged[v] && !problems[v].empty())
    {
      return fail("vertex " + std::to_string(v) + " is tagged but has no " + this->GetSchemeAsString() +
        " limit point: " + problems[v]);
    }
  }
  this->UpdateProgress(0.4);
  std::vector<double> solved;
  if (!this->Solve(rows, tagged, cage.Points, solved, error))
  {
    return fail(error);
  }
  this->UpdateProgress(0.9);

  vtkSmartPointer<vtkPolyData> newCage = vtkSubDWithSolvedPoints(input, solved);
  if (!this->OutputRefinedSurface)
  {
    output->ShallowCopy(newCage);
    return 1;
  }
  vtkSmartPointer<vtkSubDSurfaceFilter> refine = NewSurfaceFilter(this->Scheme);
  refine->SetInputData(newCage);
  refine->SetNumberOfSubdivisions(this->NumberOfSubdivisions);
  refine->SetBoundaryRule(this->BoundaryRule);
  refine->SetCreaseMethod(this->CreaseMethod);
  refine->Update();
  if (refine->GetErrorCode() != vtkErrorCode::NoError)
  {
    return fail("refining the interpolating cage failed (see the error of " + std::string(refine->GetClassName()) +
      ")");
  }
  output->ShallowCopy(refine->GetOutput());
  return 1;
}

void vtkSubDInterpolateFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Scheme: " << this->GetSchemeAsString() << "\n";
  os << indent << "BoundaryRule: " << this->BoundaryRule << "\n";
  os << indent << "CreaseMethod: " << this->CreaseMethod << "\n";
  os << indent << "OutputRefinedSurface: " << this->OutputRefinedSurface << "\n";
  os << indent << "NumberOfSubdivisions: " << this->NumberOfSubdivisions << "\n";
}
