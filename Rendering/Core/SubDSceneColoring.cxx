#include "SubDSceneColoring.h"

#include "vtkSubDScene.h"

#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>

namespace subdrender
{
const char* CurvatureArrayName(int coloring)
{
  switch (coloring)
  {
    case vtkSubDScene::COLOR_MEAN_CURVATURE:
      return "Mean_Curvature";
    case vtkSubDScene::COLOR_GAUSSIAN_CURVATURE:
      return "Gauss_Curvature";
    case vtkSubDScene::COLOR_MAXIMUM_CURVATURE:
      return "Maximum_Curvature";
    case vtkSubDScene::COLOR_MINIMUM_CURVATURE:
      return "Minimum_Curvature";
    default:
      return nullptr;
  }
}

void AppendInteriorValues(const std::vector<bool>& boundary, vtkDataArray* curvature, std::vector<double>& values)
{
  const vtkIdType n = std::min(curvature->GetNumberOfTuples(), static_cast<vtkIdType>(boundary.size()));
  for (vtkIdType i = 0; i < n; ++i)
  {
    const double value = curvature->GetComponent(i, 0);
    if (!boundary[static_cast<size_t>(i)] && std::isfinite(value))
    {
      values.push_back(value);
    }
  }
}

namespace
{
// The q-quantile (q in [0, 1]) of `values`, which are reordered.
double Quantile(std::vector<double>& values, double q)
{
  const size_t k =
    std::min(values.size() - 1, static_cast<size_t>(std::max(0.0, q) * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}
}

std::array<double, 2> ColorRange(std::vector<double>& values, bool symmetric, double percentile)
{
  if (values.empty())
  {
    return { -1.0, 1.0 };
  }
  const double fraction = std::max(0.0, std::min(1.0, percentile / 100.0));
  if (symmetric)
  {
    for (double& value : values)
    {
      value = std::abs(value);
    }
    const double m = Quantile(values, fraction);
    return m > 1e-12 ? std::array<double, 2>{ -m, m } : std::array<double, 2>{ -1.0, 1.0 };
  }
  const double tail = 0.5 * (1.0 - fraction);
  const double lo = Quantile(values, tail);
  const double hi = Quantile(values, 1.0 - tail);
  if (hi - lo > 1e-12 * std::max(1.0, std::abs(lo)))
  {
    return { lo, hi };
  }
  return { lo - 1.0, lo + 1.0 };
}

vtkSmartPointer<vtkLookupTable> MakeColorTable(int map, double lo, double hi)
{
  vtkNew<vtkColorTransferFunction> colors;
  // Control points on [0, 1], rescaled below.
  switch (map)
  {
    case vtkSubDScene::COLORMAP_RAINBOW: // hue from blue to red at full saturation
      colors->SetColorSpaceToHSV();
      colors->HSVWrapOff();
      colors->AddHSVPoint(0.0, 0.6667, 1.0, 1.0);
      colors->AddHSVPoint(1.0, 0.0, 1.0, 1.0);
      break;
    case vtkSubDScene::COLORMAP_BLACK_BODY: // the colours of a heated body: black, red, yellow, white
      colors->SetColorSpaceToRGB();
      colors->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
      colors->AddRGBPoint(0.4, 0.85, 0.15, 0.05);
      colors->AddRGBPoint(0.8, 1.0, 0.85, 0.1);
      colors->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
      break;
    case vtkSubDScene::COLORMAP_GRAYSCALE:
      colors->SetColorSpaceToRGB();
      colors->AddRGBPoint(0.0, 0.08, 0.08, 0.08);
      colors->AddRGBPoint(1.0, 0.95, 0.95, 0.95);
      break;
    default: // Moreland's cool-to-warm: blue through a neutral grey to red
      colors->SetColorSpaceToDiverging();
      colors->AddRGBPoint(0.0, 0.230, 0.299, 0.754);
      colors->AddRGBPoint(1.0, 0.706, 0.016, 0.150);
      break;
  }
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  table->SetRange(lo, hi);
  for (int i = 0; i < 256; ++i)
  {
    double rgb[3];
    colors->GetColor(i / 255.0, rgb);
    table->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
  }
  return table;
}
}
