#include "vtkSubDSeams.h"

#include "SubDCoincidentPoints.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkDoubleArray.h"
#include "vtkSubDPointDataInterpolation.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace
{
// Whether points p and q carry equal values in `array`.
bool SameTuple(vtkDataArray* array, vtkIdType p, vtkIdType q)
{
  for (int c = 0; c < array->GetNumberOfComponents(); ++c)
  {
    if (array->GetComponent(p, c) != array->GetComponent(q, c))
    {
      return false;
    }
  }
  return true;
}

// Per input point, the first point at the same position (`first`, itself if none comes
// before it) and the first at the same position with the same point data (`firstWithData`).
void FirstAtSamePosition(vtkPolyData* input, std::vector<subd::Index>& first, std::vector<subd::Index>& firstWithData)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &xyz[3 * static_cast<size_t>(i)]);
  }
  first = subd::FirstPointAtSamePosition(xyz.data(), static_cast<subd::Index>(n));
  vtkPointData* pd = input->GetPointData();
  auto sameData = [pd](vtkIdType p, vtkIdType q) {
    for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* array = pd->GetArray(a);
      if (array && !SameTuple(array, p, q))
      {
        return false;
      }
    }
    return true;
  };
  // By data, a point goes to the first point at its position with its data, among a bounded
  // number kept per position (never quadratic).
  firstWithData.resize(static_cast<size_t>(n));
  std::unordered_map<subd::Index, std::vector<subd::Index>> kept; // per first point
  for (vtkIdType i = 0; i < n; ++i)
  {
    firstWithData[i] = static_cast<subd::Index>(i);
    if (first[i] == i)
    {
      continue;
    }
    std::vector<subd::Index>& candidates = kept[first[i]];
    if (candidates.empty())
    {
      candidates.push_back(first[i]);
    }
    const auto match =
      std::find_if(candidates.begin(), candidates.end(), [&](subd::Index q) { return sameData(i, q); });
    if (match != candidates.end())
    {
      firstWithData[i] = *match;
    }
    else if (candidates.size() < 64)
    {
      candidates.push_back(static_cast<subd::Index>(i));
    }
  }
}

// Drops the faces (and their corners' values) that renaming made repeat a point they did
// not repeat in `original`; returns how many.
subd::Index DropFacesRepeatedByWelding(
  subd::FaceScreening& screened, const subd::IndexArray& original, subd::IndexArray& valueOfCorner)
{
  subd::Index dropped = 0;
  subd::IndexArray offsets{ 0 }, vertices, values, kept;
  std::vector<subd::Index> scratch;
  const size_t numFaces = screened.KeptFaces.size();
  for (size_t f = 0; f < numFaces; ++f)
  {
    const subd::Index begin = screened.Offsets[f], n = screened.Offsets[f + 1] - begin;
    if (subd::HasRepeatedVertex(screened.Vertices.data() + begin, n, scratch) &&
      !subd::HasRepeatedVertex(original.data() + begin, n, scratch))
    {
      ++dropped;
      continue;
    }
    vertices.insert(vertices.end(), screened.Vertices.begin() + begin, screened.Vertices.begin() + begin + n);
    values.insert(values.end(), valueOfCorner.begin() + begin, valueOfCorner.begin() + begin + n);
    offsets.push_back(static_cast<subd::Index>(vertices.size()));
    kept.push_back(screened.KeptFaces[f]);
  }
  if (dropped > 0)
  {
    screened.Offsets.swap(offsets);
    screened.Vertices.swap(vertices);
    screened.KeptFaces.swap(kept);
    valueOfCorner.swap(values);
  }
  return dropped;
}
}

vtkSubDSeams vtkSubDWeldCoincidentPoints(vtkPolyData* input, subd::FaceScreening& screened, bool byData,
  subd::Index& numDropped)
{
  vtkSubDSeams seams;
  numDropped = 0;
  std::vector<subd::Index> first, firstWithData;
  FirstAtSamePosition(input, first, firstWithData);
  const std::vector<subd::Index>& weldedTo = byData ? firstWithData : first;
  bool anyWelded = false;
  for (size_t p = 0; p < weldedTo.size() && !anyWelded; ++p)
  {
    anyWelded = weldedTo[p] != static_cast<subd::Index>(p);
  }
  if (!anyWelded)
  {
    return seams;
  }
  vtkPointData* pd = input->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    bool differs = false;
    for (vtkIdType p = 0; array && !differs && p < input->GetNumberOfPoints(); ++p)
    {
      differs = weldedTo[p] != p && !SameTuple(array, p, weldedTo[p]);
    }
    if (differs)
    {
      seams.Arrays.push_back(a);
    }
  }
  // A corner's value: the first point with its position and data, so that points split
  // where their data agree (VTK's OBJ reader splits every corner) are no seam.
  const subd::IndexArray original = screened.Vertices;
  subd::IndexArray valueOfCorner = screened.Vertices;
  for (subd::Index& v : valueOfCorner)
  {
    v = firstWithData[v];
  }
  for (subd::Index& v : screened.Vertices)
  {
    v = weldedTo[v];
  }
  numDropped = DropFacesRepeatedByWelding(screened, original, valueOfCorner);
  if (seams.Any())
  {
    seams.ValueOfCorner = std::move(valueOfCorner);
  }
  seams.WeldedTo = weldedTo;
  return seams;
}

bool vtkSubDRefineSeams(const subd::Scheme& scheme, const subd::Level& base, const vtkSubDSeams& seams,
  subd::FaceVaryingInterpolation mode, int levels, bool limit, vtkSubDSeamChannel& channel, std::string& error)
{
  subd::FaceVaryingBase values = subd::MakeFaceVaryingBase(base, seams.ValueOfCorner.data(), mode);
  channel = vtkSubDSeamChannel();
  channel.UserValue = std::move(values.UserValue);
  channel.Hierarchy.NumBasePoints = static_cast<subd::Index>(channel.UserValue.size());
  if (!subd::Refine(scheme, std::move(values.Values), levels, channel.Hierarchy, nullptr,
        limit ? subd::ChildTopology::Full : subd::ChildTopology::FacesOnly, subd::LevelRows::Written))
  {
    return false;
  }
  if (limit)
  {
    subd::StencilTable table;
    if (!scheme.BuildLimitStencils(channel.Hierarchy.Finest, table, error))
    {
      return false;
    }
    channel.Hierarchy.Stencils.push_back(std::move(table));
  }
  return true;
}

void vtkSubDSelectSplitOutput(const subd::MeshTopology& finest, const std::vector<subd::Index>* emitted,
  vtkSubDSeamChannel& channel, std::vector<vtkIdType>& finestPointOfOutput, std::vector<vtkIdType>& outputPointOfFinest)
{
  const subd::MeshTopology& values = channel.Hierarchy.Finest.Topology;
  const subd::Index numValues = values.GetNumVertices();
  // The finest mesh point of each channel vertex an output face uses (-1: none uses it).
  std::vector<subd::Index> pointOfValue(static_cast<size_t>(numValues), -1);
  const subd::Index numFaces = emitted ? static_cast<subd::Index>(emitted->size()) : finest.GetNumFaces();
  for (subd::Index c = 0; c < numFaces; ++c)
  {
    const subd::Index f = emitted ? (*emitted)[c] : c;
    const subd::IndexSpan points = finest.GetFaceVertices(f), corners = values.GetFaceVertices(f);
    for (subd::Index k = 0; k < corners.size(); ++k)
    {
      pointOfValue[corners[k]] = points[k];
    }
  }
  const auto numOutput = static_cast<size_t>(numValues - std::count(pointOfValue.begin(), pointOfValue.end(), -1));
  const bool everyValue = numOutput == pointOfValue.size();
  channel.OutputPointOfValue.assign(everyValue ? 0 : pointOfValue.size(), -1);
  channel.ValueOfOutput.resize(everyValue ? 0 : numOutput);
  finestPointOfOutput.resize(numOutput);
  outputPointOfFinest.assign(static_cast<size_t>(finest.GetNumVertices()), -1);
  vtkIdType o = 0;
  for (subd::Index value = 0; value < numValues; ++value)
  {
    const subd::Index point = pointOfValue[value];
    if (point < 0)
    {
      continue;
    }
    if (!everyValue)
    {
      channel.OutputPointOfValue[value] = o;
      channel.ValueOfOutput[o] = value;
    }
    finestPointOfOutput[o] = point;
    if (outputPointOfFinest[point] < 0)
    {
      outputPointOfFinest[point] = o;
    }
    ++o;
  }
}

bool vtkSubDAddFaceVaryingArrays(vtkPolyData* input, const vtkSubDSeams& seams, const vtkSubDSeamChannel& channel,
  const subd::ProgressCallback& progress, vtkPolyData* output)
{
  const vtkSubDPointDataInterpolation interpolation(channel.Hierarchy, vtkSubDPointDataInterpolation::SMPFor,
    channel.ValueOfOutput.empty() ? nullptr : &channel.ValueOfOutput);
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  const vtkIdType numBase = static_cast<vtkIdType>(channel.UserValue.size());
  for (int a : seams.Arrays)
  {
    vtkDataArray* source = inPD->GetArray(a);
    if (!source)
    {
      continue;
    }
    vtkNew<vtkDoubleArray> base; // the input's tuples at the base values
    base->SetNumberOfComponents(source->GetNumberOfComponents());
    base->SetNumberOfTuples(numBase);
    for (vtkIdType u = 0; u < numBase; ++u)
    {
      base->SetTuple(u, source->GetTuple(channel.UserValue[u]));
    }
    const int attribute = inPD->IsArrayAnAttribute(a);
    vtkSmartPointer<vtkDataArray> refined =
      interpolation.Interpolate(base, source->GetDataType(), attribute == vtkDataSetAttributes::NORMALS, progress);
    if (!refined)
    {
      return false;
    }
    refined->SetName(source->GetName());
    const vtkIdType numRefined = refined->GetNumberOfTuples();
    refined->Resize(output->GetNumberOfPoints()); // zeros at points no face uses
    refined->SetNumberOfTuples(output->GetNumberOfPoints());
    for (vtkIdType p = numRefined; p < output->GetNumberOfPoints(); ++p)
    {
      for (int c = 0; c < refined->GetNumberOfComponents(); ++c)
      {
        refined->SetComponent(p, c, 0.0);
      }
    }
    outPD->AddArray(refined);
    if (attribute >= 0)
    {
      outPD->SetActiveAttribute(outPD->GetNumberOfArrays() - 1, attribute);
    }
  }
  return true;
}
