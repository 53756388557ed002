// The scheme list that subd and the explorer share: each entry's flags say what its filter
// really does (the explorer turns the limit options on from them).
#include "SubDBuiltinCages.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

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
