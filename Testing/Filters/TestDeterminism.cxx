// Determinism: every scheme gives the same output bit for bit with 1, 2 and 4 threads, with
// VTK's TBB and std::thread SMP backends, and from one run to the next.
//
// The cages are large enough (thousands of faces, creases, boundaries, a point-data array) that
// every parallel loop is cut into several chunks, so a result that depended on how the work was
// split, or on the order threads finish in, would show here.
#include "SubDBuiltinCages.h"
#include "SubDMessageCollector.h"
#include "SubDSchemeRegistry.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace
{
/// Every byte of a polydata that a scheme writes: points, cells, point and cell arrays.
std::vector<unsigned char> Bytes(vtkPolyData* mesh)
{
  std::vector<unsigned char> bytes;
  const auto append = [&bytes](const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), p, p + n);
  };
  const auto appendArray = [&](vtkDataArray* array) {
    if (!array)
    {
      return;
    }
    const char* name = array->GetName() ? array->GetName() : "";
    append(name, std::strlen(name) + 1);
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      const double value = array->GetVariantValue(i).ToDouble();
      append(&value, sizeof value);
    }
  };
  appendArray(mesh->GetPoints() ? mesh->GetPoints()->GetData() : nullptr);
  for (vtkCellArray* cells : { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    appendArray(cells->GetOffsetsArray());
    appendArray(cells->GetConnectivityArray());
  }
  for (vtkDataSetAttributes* data : { static_cast<vtkDataSetAttributes*>(mesh->GetPointData()),
         static_cast<vtkDataSetAttributes*>(mesh->GetCellData()) })
  {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a)
    {
      appendArray(data->GetArray(a));
    }
  }
  return bytes;
}

/// A builtin cage refined linearly into `levels` more levels, with a random point-data array.
vtkSmartPointer<vtkPolyData> LargeCage(const std::string& name, int levels)
{
  vtkSmartPointer<vtkPolyData> cage = subdapp::MakeBuiltinCage(name);
  subdapp::SchemeOptions linear;
  linear.Levels = levels;
  subdapp::MessageCollector messages;
  vtkSmartPointer<vtkPolyData> mesh =
    subdapp::RunScheme(*subdapp::FindScheme("linear"), linear, cage, messages);
  vtkNew<vtkDoubleArray> temperature;
  temperature->SetName("Temperature");
  temperature->SetNumberOfComponents(2);
  temperature->SetNumberOfTuples(mesh->GetNumberOfPoints());
  vtkMath::RandomSeed(7);
  for (vtkIdType i = 0; i < temperature->GetNumberOfValues(); ++i)
  {
    temperature->SetValue(i, vtkMath::Random(-1.0, 1.0));
  }
  mesh->GetPointData()->AddArray(temperature);
  return mesh;
}

std::vector<unsigned char> Run(const subdapp::SchemeEntry& scheme, const subdapp::SchemeOptions& options,
  vtkPolyData* input, const vtkSMPTools::Config& config)
{
  std::vector<unsigned char> bytes;
  vtkSMPTools::LocalScope(config, [&]() {
    vtkSmartPointer<vtkPolyDataAlgorithm> filter = scheme.Make(options);
    filter->SetInputData(input);
    filter->Update();
    bytes = Bytes(filter->GetOutput());
  });
  return bytes;
}

void ExpectDeterministic(vtkPolyData* input, bool curves)
{
  for (const subdapp::SchemeEntry& scheme : subdapp::Schemes())
  {
    if (scheme.Curve != curves)
    {
      continue;
    }
    subdapp::SchemeOptions options;
    options.Levels = curves ? 6 : 2;
    options.ProjectToLimit = scheme.LimitPositions || curves;
    options.LimitNormals = options.LimitCurvature = scheme.LimitCurvature;
    options.Tangents = curves;
    SCOPED_TRACE(scheme.Name);
    const std::vector<unsigned char> serial = Run(scheme, options, input, vtkSMPTools::Config{ 1 });
    ASSERT_GT(serial.size(), 1000u);
    EXPECT_TRUE(serial == Run(scheme, options, input, vtkSMPTools::Config{ 2 })) << "2 threads";
    EXPECT_TRUE(serial == Run(scheme, options, input, vtkSMPTools::Config{ 4 })) << "4 threads";
    EXPECT_TRUE(serial == Run(scheme, options, input, vtkSMPTools::Config{ 4 })) << "4 threads, again";
    EXPECT_TRUE(serial == Run(scheme, options, input, vtkSMPTools::Config{ 3, "STDThread", true }))
      << "3 std::threads";
  }
}

TEST(Determinism, SurfaceSchemesGiveTheSameBytesOnAnyNumberOfThreads)
{
  ExpectDeterministic(LargeCage("creased-cube", 3), false);
  ExpectDeterministic(LargeCage("letter-l", 3), false);
}

TEST(Determinism, CurveSchemesGiveTheSameBytesOnAnyNumberOfThreads)
{
  ExpectDeterministic(subdapp::MakeBuiltinCage("star"), true);
}
}
