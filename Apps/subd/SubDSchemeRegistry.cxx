#include "SubDSchemeRegistry.h"

#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDLinearFilter.h"
#include "vtkSubDLoopFilter.h"
#include "vtkSubDMidpointFilter.h"
#include "vtkSubDSqrt3Filter.h"

namespace subdapp
{
namespace
{
template <typename Filter>
vtkSmartPointer<Filter> NewSurfaceFilter(const SchemeOptions& options)
{
  auto filter = vtkSmartPointer<Filter>::New();
  filter->SetNumberOfSubdivisions(options.Levels);
  filter->SetBoundaryRule(options.BoundaryRule);
  filter->SetCreaseMethod(options.CreaseMethod);
  filter->SetAutomaticCreases(options.FeatureAngle > 0.0);
  filter->SetProjectToLimit(options.ProjectToLimit);
  filter->SetComputeLimitNormals(options.LimitNormals);
  filter->SetComputeCurvature(options.LimitCurvature);
  if (options.FeatureAngle > 0.0)
  {
    filter->SetFeatureAngle(options.FeatureAngle);
  }
  return filter;
}

template <typename Filter>
vtkSmartPointer<vtkPolyDataAlgorithm> MakeSurfaceFilter(const SchemeOptions& options)
{
  return NewSurfaceFilter<Filter>(options);
}

vtkSmartPointer<vtkPolyDataAlgorithm> MakeButterfly(const SchemeOptions& options)
{
  auto filter = NewSurfaceFilter<vtkSubDButterflyFilter>(options);
  filter->SetTension(options.Tension);
  return filter;
}
}

const std::vector<SchemeEntry>& Schemes()
{
  static const std::vector<SchemeEntry> schemes = {
    { "catmull-clark", "Catmull-Clark: quads from any polygons (approximating, C2 where regular)",
      &MakeSurfaceFilter<vtkSubDCatmullClarkFilter> },
    { "loop", "Loop: triangles (other polygons are triangulated first; approximating, C2 where regular)",
      &MakeSurfaceFilter<vtkSubDLoopFilter> },
    { "butterfly", "modified butterfly: interpolating, triangles (other polygons are triangulated), --tension W",
      &MakeButterfly },
    { "doo-sabin", "Doo-Sabin: corner cutting of any polygons (approximating, C1; biquadratic where regular)",
      &MakeSurfaceFilter<vtkSubDDooSabinFilter> },
    { "midpoint", "midpoint (Peters-Reif simplest scheme): edge midpoints, boundaries kept (C1)",
      &MakeSurfaceFilter<vtkSubDMidpointFilter> },
    { "sqrt3", "Kobbelt's sqrt(3): triangles, 3x faces per step (approximating, C2 where regular)",
      &MakeSurfaceFilter<vtkSubDSqrt3Filter> },
    { "linear", "linear: more resolution, same shape (triangles split in four, other polygons into quads)",
      &MakeSurfaceFilter<vtkSubDLinearFilter> },
  };
  return schemes;
}

const SchemeEntry* FindScheme(const std::string& name)
{
  for (const SchemeEntry& entry : Schemes())
  {
    if (entry.Name == name)
    {
      return &entry;
    }
  }
  return nullptr;
}
}
