// The scheme list that subd and the explorer share: each entry's flags say what its filter
// really does (the explorer turns the limit options on from them).
#include "SubDBuiltinCages.h"
#include "SubDFilterTestSupport.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
// Runs `entry` on its kind of built-in input; null on an error.
vtkSmartPointer<vtkPolyData> RunOnBuiltin(const subdapp::SchemeEntry& entry, const subdapp::SchemeOptions& options)
{
  subdapp::MessageCollector messages;
  return subdapp::RunScheme(entry, options, subdapp::MakeBuiltinCage(entry.Curve ? "star" : "pyramid"), messages);
}

TEST(SchemeRegistry, FlagsMatchWhatTheFiltersDo)
{
  for (const subdapp::SchemeEntry& entry : subdapp::Schemes())
  {
    subdapp::SchemeOptions options;
    options.Levels = 1;
    auto plain = RunOnBuiltin(entry, options);
    ASSERT_NE(plain, nullptr) << entry.Name;
    EXPECT_EQ(entry.Curve, plain->GetNumberOfPolys() == 0) << entry.Name;

    options.ProjectToLimit = true;
    EXPECT_EQ(entry.LimitPositions, RunOnBuiltin(entry, options) != nullptr) << entry.Name;

    if (!entry.Curve)
    {
      options.ProjectToLimit = false;
      options.LimitNormals = options.LimitCurvature = true;
      auto geometry = RunOnBuiltin(entry, options);
      EXPECT_EQ(entry.LimitCurvature, geometry != nullptr) << entry.Name;
      if (geometry)
        EXPECT_NE(geometry->GetPointData()->GetArray("Mean_Curvature"), nullptr) << entry.Name;
    }
    else
      EXPECT_FALSE(entry.LimitCurvature) << entry.Name;
  }
}
}

// --interpolate: the solved cage's limit points (the scheme at level 0 with ProjectToLimit)
// are the built-in input's points, for every scheme that has a solve.
TEST(SchemeRegistry, InterpolationCagesHaveTheInputAsTheirLimit)
{
  for (const subdapp::SchemeEntry& entry : subdapp::Schemes())
  {
    if (entry.InterpolationScheme < 0)
    {
      EXPECT_NE(entry.InterpolationNote, nullptr) << entry.Name;
      continue;
    }
    subdapp::SchemeOptions options;
    vtkSmartPointer<vtkPolyData> input = subdapp::MakeBuiltinCage(
      entry.Curve ? "star" : entry.Name == "loop" ? "octahedron" : "open-grid"); // Loop needs triangles
    subdapp::MessageCollector messages;
    const subdapp::InterpolationResult solved = subdapp::RunInterpolation(entry, options, input, messages);
    ASSERT_NE(solved.Cage, nullptr) << entry.Name << ": " << messages.Errors;
    EXPECT_EQ(solved.NumTagged, input->GetNumberOfPoints()) << entry.Name;
    EXPECT_LT(solved.Residual, 1e-13) << entry.Name;
    if (entry.Name == "doo-sabin")
    {
      continue; // its limit points are V-face centroids, not the vertices' level-0 projection
    }
    options.Levels = 0;
    options.ProjectToLimit = true;
    vtkSmartPointer<vtkPolyData> limit = subdapp::RunScheme(entry, options, solved.Cage, messages);
    ASSERT_NE(limit, nullptr) << entry.Name << ": " << messages.Errors;
    EXPECT_LT(subdtest::LargestPointwiseDifference(subdtest::Coordinates(input), subdtest::Coordinates(limit)), 1e-12)
      << entry.Name;
  }
}
