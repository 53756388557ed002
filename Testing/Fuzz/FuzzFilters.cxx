// libFuzzer target: every scheme on random small meshes.
//
// The bytes are read as a recipe (SubDFuzzSupport.h: MeshFromBytes): which scheme and options,
// how many levels, a handful of points, polygons of 1 to 8 corners whose ids may repeat or fall
// outside the points, crease lines with sharpness (negative and NaN included), corner sharpness,
// holes, and now and then a non-finite coordinate; or the limit tessellation. Every filter must give a valid output or an
// error with a message and an empty output (SubDFuzzSupport.h: RunAndCheck); the sanitizers
// catch the rest.
#include "SubDFuzzSupport.h"
#include "SubDSchemeRegistry.h"
#include "vtkPolyData.h"
#include "vtkSubDLimitFilter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  subdfuzz::SilenceVTK();
  subdfuzz::ByteReader bytes(data, size);
  const std::vector<subdapp::SchemeEntry>& schemes = subdapp::Schemes();
  const size_t choice = bytes.Next() % (schemes.size() + 1);
  const uint8_t flags = bytes.Next();
  if (choice == schemes.size())
  {
    // The limit tessellation (Catmull-Clark or Loop) at resolution 1..4.
    vtkNew<vtkSubDLimitFilter> limit;
    limit->SetScheme(flags & 1 ? vtkSubDLimitFilter::LOOP : vtkSubDLimitFilter::CATMULL_CLARK);
    limit->SetResolution(1 + (flags >> 1) % 4);
    limit->SetBoundaryRule((flags >> 3) % 3);
    limit->SetComputeNormals((flags >> 5) & 1);
    limit->SetComputeCurvature((flags >> 6) & 1);
    limit->SetComputeDerivatives(flags >> 7);
    vtkSmartPointer<vtkPolyData> mesh = subdfuzz::MeshFromBytes(bytes);
    subdfuzz::RunAndCheck(limit, mesh, "limit tessellation");
    return 0;
  }
  const subdapp::SchemeEntry& scheme = schemes[choice];
  subdapp::SchemeOptions options;
  options.Levels = flags % 4;
  options.BoundaryRule = (flags >> 2) % 3;
  options.CreaseMethod = (flags >> 4) & 1;
  options.ProjectToLimit = (flags >> 5) & 1;
  if (!scheme.Curve)
  {
    options.LimitNormals = options.LimitCurvature = (flags >> 6) & 1;
  }
  else
  {
    options.Tangents = (flags >> 6) & 1;
    options.Closed = (flags >> 7) & 1;
  }
  if (bytes.Next() % 4 == 0)
  {
    options.FeatureAngle = bytes.Next() % 180;
  }
  vtkSmartPointer<vtkPolyData> mesh = subdfuzz::MeshFromBytes(bytes);
  subdfuzz::RunAndCheck(scheme, options, mesh);
  return 0;
}
