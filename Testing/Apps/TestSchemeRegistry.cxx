// The scheme list that subd and the explorer share: each entry's flags say what its filter
// really does (the explorer turns the limit options on from them).
#include "SubDBuiltinCages.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"

#include "vtkPointData.h"
#include "vtkPolyDataAlgorithm.h"

#include <gtest/gtest.h>

namespace
{
// Runs `entry` on its kind of built-in input; returns the output, or null on an error.
vtkSmartPointer<vtkPolyData> RunScheme(const subdapp::SchemeEntry& entry, const subdapp::SchemeOptions& options)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> filter = entry.Make(options);
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(subdapp::MakeBuiltinCage(entry.Curve ? "star" : "pyramid"));
  filter->Update();
  if (!messages.Errors.empty() || filter->GetOutput()->GetNumberOfPoints() == 0)
    return nullptr;
  return filter->GetOutput();
}

TEST(SchemeRegistry, FlagsMatchWhatTheFiltersDo)
{
  for (const subdapp::SchemeEntry& entry : subdapp::Schemes())
  {
    subdapp::SchemeOptions options;
    options.Levels = 1;
    auto plain = RunScheme(entry, options);
    ASSERT_NE(plain, nullptr) << entry.Name;
    EXPECT_EQ(entry.Curve, plain->GetNumberOfPolys() == 0) << entry.Name;

    options.ProjectToLimit = true;
    EXPECT_EQ(entry.LimitPositions, RunScheme(entry, options) != nullptr) << entry.Name;

    if (!entry.Curve)
    {
      options.ProjectToLimit = false;
      options.LimitNormals = options.LimitCurvature = true;
      auto geometry = RunScheme(entry, options);
      EXPECT_EQ(entry.LimitCurvature, geometry != nullptr) << entry.Name;
      if (geometry)
        EXPECT_NE(geometry->GetPointData()->GetArray("Mean_Curvature"), nullptr) << entry.Name;
    }
    else
      EXPECT_FALSE(entry.LimitCurvature) << entry.Name;
  }
}
}
