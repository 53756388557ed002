// What the fuzz targets share: reading recipes from bytes, and the one check every run ends
// with. On a violation the target aborts, so that libFuzzer (or the replay driver) keeps the
// input that caused it.
#ifndef SubDFuzzSupport_h
#define SubDFuzzSupport_h

#include "SubDMessageCollector.h"
#include "SubDOutputChecks.h"
#include "SubDQuietOutput.h"
#include "SubDSchemeRegistry.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace subdfuzz
{
/// Reads bytes one at a time; past the end every byte is 0, so any input is a complete recipe.
class ByteReader
{
public:
  ByteReader(const uint8_t* data, size_t size)
    : Data(data)
    , Size(size)
  {
  }
  uint8_t Next() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  bool AtEnd() const { return this->Position >= this->Size; }

private:
  const uint8_t* Data;
  size_t Size;
  size_t Position = 0;
};

/// VTK's messages are part of what is checked (through observers), not output to print.
inline void SilenceVTK()
{
  subdtest::DiscardUnobservedMessages();
}

/// Where the reader target writes its temporary files ($SUBD_FUZZ_SCRATCH, else /tmp).
inline std::string ScratchDirectory()
{
  const char* dir = std::getenv("SUBD_FUZZ_SCRATCH");
  return dir && *dir ? dir : "/tmp";
}

/// A small mesh from a recipe: up to 32 points on a jittered grid (one may be NaN or infinite),
/// up to 24 polygons of 1..8 corners whose ids may repeat or name no point, up to 4 crease
/// lines with "Sharpness" (any value, NaN included), optional "CornerSharpness" and "Hole".
inline vtkSmartPointer<vtkPolyData> MeshFromBytes(ByteReader& bytes)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  const int numPoints = 1 + bytes.Next() % 32;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < numPoints; ++i)
  {
    const int8_t jitter = static_cast<int8_t>(bytes.Next());
    points->InsertNextPoint(i % 6 + jitter / 64.0, (i / 6) % 6, i / 36 + (jitter & 3) / 4.0);
  }
  const uint8_t special = bytes.Next();
  if (special >= 250)
  {
    const double bad = special == 255 ? std::numeric_limits<double>::quiet_NaN()
                                      : std::numeric_limits<double>::infinity();
    points->SetPoint(special % numPoints, bad, 0.0, 0.0);
  }
  mesh->SetPoints(points);
  const auto pointId = [&]() -> vtkIdType {
    const uint8_t b = bytes.Next();
    return b >= 250 ? (b == 255 ? -1 : numPoints + b % 3) : b % numPoints; // rarely out of range
  };

  vtkNew<vtkCellArray> polys;
  const int numFaces = bytes.Next() % 25;
  for (int f = 0; f < numFaces && !bytes.AtEnd(); ++f)
  {
    const int n = 1 + bytes.Next() % 8;
    polys->InsertNextCell(n);
    for (int k = 0; k < n; ++k)
    {
      polys->InsertCellPoint(pointId());
    }
  }
  mesh->SetPolys(polys);

  const uint8_t features = bytes.Next();
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkFloatArray> sharpness;
  sharpness->SetName("Sharpness");
  const int numLines = features % 5;
  for (int l = 0; l < numLines; ++l)
  {
    const int n = 2 + bytes.Next() % 4;
    lines->InsertNextCell(n);
    for (int k = 0; k < n; ++k)
    {
      lines->InsertCellPoint(pointId());
    }
    const uint8_t s = bytes.Next();
    sharpness->InsertNextValue(s == 255 ? std::numeric_limits<float>::quiet_NaN() : (s - 16) / 16.0f);
  }
  if (numLines > 0)
  {
    // Lines come before polygons in VTK's cell numbering: the cell data starts with them.
    mesh->SetLines(lines);
    for (vtkIdType f = 0; f < polys->GetNumberOfCells(); ++f) // the polygons' entries: unused
    {
      sharpness->InsertNextValue(0.0f);
    }
    mesh->GetCellData()->AddArray(sharpness);
  }
  if (features & 8)
  {
    vtkNew<vtkFloatArray> corners;
    corners->SetName("CornerSharpness");
    for (int i = 0; i < numPoints; ++i)
    {
      corners->InsertNextValue(bytes.Next() % 8 == 0 ? 10.0f : 0.0f);
    }
    mesh->GetPointData()->AddArray(corners);
  }
  if (features & 16)
  {
    vtkNew<vtkFloatArray> holes;
    holes->SetName("Hole");
    holes->SetNumberOfTuples(mesh->GetNumberOfCells());
    for (vtkIdType c = 0; c < holes->GetNumberOfTuples(); ++c)
    {
      holes->SetValue(c, bytes.Next() % 5 == 0 ? 1.0f : 0.0f);
    }
    mesh->GetCellData()->AddArray(holes);
  }
  if (features & 32)
  {
    vtkNew<vtkFloatArray> data; // a point-data array to carry along
    data->SetName("Data");
    data->SetNumberOfComponents(2);
    for (int i = 0; i < 2 * numPoints; ++i)
    {
      data->InsertNextValue(static_cast<int8_t>(bytes.Next()) / 8.0f);
    }
    mesh->GetPointData()->AddArray(data);
  }
  return mesh;
}

[[noreturn]] inline void Fail(const std::string& what, const std::string& detail)
{
  std::fprintf(stderr, "SubD fuzz: %s: %s\n", what.c_str(), detail.c_str());
  std::abort();
}

/// Runs `filter` on `input`: it must give a valid output (SubDOutputChecks.h), or an error with
/// a message and an empty output.
inline void RunAndCheck(vtkPolyDataAlgorithm* filter, vtkPolyData* input, const std::string& name)
{
  subdapp::MessageCollector messages;
  messages.Watch(filter);
  filter->SetInputData(input);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  const std::string problems = subdtest::OutputProblems(out, input);
  if (!problems.empty())
  {
    Fail(name + " gave an invalid output", problems);
  }
  if (filter->GetErrorCode() != 0 && messages.Errors.empty())
  {
    Fail(name + " failed without a message", "");
  }
  if (!messages.Errors.empty() && (out->GetNumberOfPoints() != 0 || out->GetNumberOfCells() != 0))
  {
    Fail(name + " reported an error but its output is not empty", messages.Errors);
  }
}

inline void RunAndCheck(const subdapp::SchemeEntry& scheme, const subdapp::SchemeOptions& options, vtkPolyData* input)
{
  RunAndCheck(scheme.Make(options), input, scheme.Name);
}
}

#endif
