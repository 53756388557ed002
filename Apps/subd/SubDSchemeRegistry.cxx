#include "SubDSchemeRegistry.h"
#include "SubDMessageCollector.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkPolyData.h"

#include "vtkSubDButterflyFilter.h"
#include "vtkSubDCatmullClarkFilter.h"
#include "vtkSubDCurveFilter.h"
#include "vtkSubDCurveInterpolateFilter.h"
#include "vtkSubDDooSabinFilter.h"
#include "vtkSubDInterpolateFilter.h"
#include "vtkSubDLimitFilter.h"
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
  filter->SetCollapseRepeatedCorners(options.CollapseRepeatedCorners);
  filter->SetWeldCoincidentPoints(options.Weld);
  filter->SetFaceVaryingInterpolation(options.FaceVaryingInterpolation);
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

// With a tolerance: the limit surface's adaptive tessellation (vtkSubDLimitFilter), the
// levels its deepest level.
vtkSmartPointer<vtkPolyDataAlgorithm> MakeAdaptiveTessellation(const SchemeOptions& options, int scheme)
{
  auto filter = vtkSmartPointer<vtkSubDLimitFilter>::New();
  filter->SetScheme(scheme);
  filter->SetTessellationToAdaptive();
  filter->SetTolerance(options.Tolerance);
  filter->SetMaximumLevel(options.Levels);
  filter->SetBoundaryRule(options.BoundaryRule);
  filter->SetCreaseMethod(options.CreaseMethod);
  filter->SetComputeNormals(options.LimitNormals);
  filter->SetComputeCurvature(options.LimitCurvature);
  filter->SetWeldCoincidentPoints(options.Weld);
  filter->SetFaceVaryingInterpolation(options.FaceVaryingInterpolation);
  return filter;
}

vtkSmartPointer<vtkPolyDataAlgorithm> MakeCatmullClark(const SchemeOptions& options)
{
  if (options.Tolerance > 0.0)
  {
    return MakeAdaptiveTessellation(options, vtkSubDLimitFilter::CATMULL_CLARK);
  }
  auto filter = NewSurfaceFilter<vtkSubDCatmullClarkFilter>(options);
  filter->SetSmoothTriangles(options.SmoothTriangles);
  return filter;
}

vtkSmartPointer<vtkPolyDataAlgorithm> MakeLoop(const SchemeOptions& options)
{
  if (options.Tolerance > 0.0)
  {
    return MakeAdaptiveTessellation(options, vtkSubDLimitFilter::LOOP);
  }
  return NewSurfaceFilter<vtkSubDLoopFilter>(options);
}

vtkSmartPointer<vtkPolyDataAlgorithm> MakeButterfly(const SchemeOptions& options)
{
  auto filter = NewSurfaceFilter<vtkSubDButterflyFilter>(options);
  filter->SetTension(options.TensionGiven ? options.Tension : 0.0);
  return filter;
}

template <int Scheme>
vtkSmartPointer<vtkPolyDataAlgorithm> MakeCurveFilter(const SchemeOptions& options)
{
  auto filter = vtkSmartPointer<vtkSubDCurveFilter>::New();
  filter->SetScheme(Scheme);
  filter->SetNumberOfSubdivisions(options.Levels);
  filter->SetProjectToLimit(options.ProjectToLimit);
  filter->SetComputeTangents(options.Tangents);
  filter->SetClosed(options.Closed);
  if (options.TensionGiven)
  {
    filter->SetTension(options.Tension);
  }
  return filter;
}

const char* const kNoInterpolation =
  "has no interpolation solve (catmull-clark, loop, doo-sabin, chaikin and bspline have one)";
}

const std::vector<SchemeEntry>& Schemes()
{
  static const std::vector<SchemeEntry> schemes = {
    { "catmull-clark", "Catmull-Clark: quads from any polygons (approximating, C2 where regular)",
      false, true, true, &MakeCatmullClark, vtkSubDInterpolateFilter::CATMULL_CLARK,
      nullptr },
    { "loop", "Loop: triangles (other polygons are triangulated first; approximating, C2 where regular)",
      false, true, true, &MakeLoop, vtkSubDInterpolateFilter::LOOP, nullptr },
    { "butterfly", "modified butterfly: interpolating, triangles (other polygons are triangulated), --tension W",
      false, true, false, &MakeButterfly, -1, "interpolates its points already" },
    { "doo-sabin", "Doo-Sabin: corner cutting of any polygons (approximating, C1; biquadratic where regular)",
      false, true, false, &MakeSurfaceFilter<vtkSubDDooSabinFilter>, vtkSubDInterpolateFilter::DOO_SABIN, nullptr },
    { "midpoint", "midpoint (Peters-Reif simplest scheme): edge midpoints, boundaries kept (C1)",
      false, true, false, &MakeSurfaceFilter<vtkSubDMidpointFilter>, -1, kNoInterpolation },
    { "sqrt3", "Kobbelt's sqrt(3): triangles, 3x faces per step (approximating, C2 where regular)",
      false, true, false, &MakeSurfaceFilter<vtkSubDSqrt3Filter>, -1, kNoInterpolation },
    { "linear", "linear: more resolution, same shape (triangles split in four, other polygons into quads)",
      false, true, false, &MakeSurfaceFilter<vtkSubDLinearFilter>, -1, "interpolates its points already" },
    { "chaikin", "curves: Chaikin corner cutting (approximating; the quadratic B-spline, C1)", true, true, false,
      &MakeCurveFilter<vtkSubDCurveFilter::SCHEME_CHAIKIN>, vtkSubDCurveFilter::SCHEME_CHAIKIN, nullptr },
    { "bspline", "curves: cubic B-spline (approximating; C2)", true, true, false,
      &MakeCurveFilter<vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE>, vtkSubDCurveFilter::SCHEME_CUBIC_BSPLINE, nullptr },
    { "four-point", "curves: Dyn-Levin-Gregory 4-point (interpolating; C1), --tension W", true, true, false,
      &MakeCurveFilter<vtkSubDCurveFilter::SCHEME_FOUR_POINT>, -1, "interpolates its points already" },
  };
  return schemes;
}

vtkSmartPointer<vtkPolyData> RunScheme(const SchemeEntry& entry, const SchemeOptions& options, vtkPolyData* input,
  MessageCollector& messages, const SchemeProgress& progress)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = entry.Make(options);
  messages.Watch(filter);
  struct Watcher
  {
    const SchemeProgress* Report;
    vtkAlgorithm* Filter;
    bool Stopped = false;
  } watcher{ &progress, filter };
  if (progress)
  {
    vtkNew<vtkCallbackCommand> callback;
    callback->SetClientData(&watcher);
    callback->SetCallback([](vtkObject*, unsigned long, void* client, void* callData) {
      auto* w = static_cast<Watcher*>(client);
      if (!(*w->Report)(*static_cast<double*>(callData)))
      {
        w->Stopped = true;
        w->Filter->SetAbortExecute(1);
      }
    });
    filter->AddObserver(vtkCommand::ProgressEvent, callback);
  }
  filter->SetInputData(input);
  filter->Update();
  if (watcher.Stopped || !messages.Errors.empty() || filter->GetOutput()->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(filter->GetOutput());
  return result;
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
InterpolationResult RunInterpolation(
  const SchemeEntry& entry, const SchemeOptions& options, vtkPolyData* input, MessageCollector& messages)
{
  InterpolationResult result;
  vtkSmartPointer<vtkSubDInterpolationAlgorithm> filter;
  if (entry.Curve)
  {
    auto curve = vtkSmartPointer<vtkSubDCurveInterpolateFilter>::New();
    curve->SetScheme(entry.InterpolationScheme);
    curve->SetClosed(options.Closed);
    filter = curve;
  }
  else
  {
    auto surface = vtkSmartPointer<vtkSubDInterpolateFilter>::New();
    surface->SetScheme(entry.InterpolationScheme);
    surface->SetBoundaryRule(options.BoundaryRule);
    surface->SetCreaseMethod(options.CreaseMethod);
    filter = surface;
  }
  messages.Watch(filter);
  filter->SetInputData(input);
  filter->Update();
  if (!messages.Errors.empty() || filter->GetErrorCode() != 0)
  {
    return result;
  }
  result.NumTagged = filter->GetNumberOfTaggedPoints();
  result.Residual = filter->GetResidual();
  result.Cage = vtkSmartPointer<vtkPolyData>::New();
  result.Cage->ShallowCopy(filter->GetOutput());
  return result;
}
}
