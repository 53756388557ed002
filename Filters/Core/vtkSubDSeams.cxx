#include "vtkSubDSeams.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkIdList.h"
#include "vtkSMPTools.h"
#include "vtkSubDPointDataInterpolation.h"
#include "vtkTypeInt32Array.h"

#include <algorithm>
#include <cmath>
#include <numeric>

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
    input->GetPoint(i, &xyz[3 * i]);
  }
  std::vector<subd::Index> order(static_cast<size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&xyz](subd::Index a, subd::Index b) {
    const double* p = &xyz[3 * static_cast<size_t>(a)];
    const double* q = &xyz[3 * static_cast<size_t>(b)];
    return std::lexicographical_compare(p, p + 3, q, q + 3) || (std::equal(p, p + 3, q) && a < b);
  });
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
  first.resize(static_cast<size_t>(n));
  std::iota(first.begin(), first.end(), 0);
  firstWithData = first;
  std::vector<subd::Index> kept; // the points of a run that others with their data weld to
  for (size_t k = 0; k < order.size();)
  {
    const double* position = &xyz[3 * static_cast<size_t>(order[k])];
    size_t end = k + 1;
    while (end < order.size() && std::equal(position, position + 3, &xyz[3 * static_cast<size_t>(order[end])]))
    {
      ++end;
    }
    // The run holds one position, in increasing index. By data, a point goes to the first
    // kept one with its data (among a bounded number: never quadratic).
    kept.assign(1, order[k]);
    for (size_t i = k + 1; i < end; ++i)
    {
      first[order[i]] = order[k];
      const auto match = std::find_if(kept.begin(), kept.end(), [&](subd::Index q) { return sameData(order[i], q); });
      if (match != kept.end())
      {
        firstWithData[order[i]] = *match;
      }
      else if (kept.size() < 64)
      {
        kept.push_back(order[i]);
      }
    }
    k = end;
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

// The value of a refined channel for an array of type `type`: rounded and clamped for
// integer types, as vertex data are (vtkSubDPointDataInterpolation).
double StoredValue(vtkDataArray* array, double value)
{
  const int type = array->GetDataType();
  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    return value;
  }
  return std::min(array->GetDataTypeMax(), std::max(array->GetDataTypeMin(), std::round(value)));
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

namespace
{
// The split output's points and faces: a point per channel vertex that a face uses (in the
// channel's order), then the unsplit points no face uses (ends of lines passed through);
// the faces keep their sizes. `newOfOld` receives, per unsplit point, one of its new points.
void MakeSplitTopology(vtkPolyData* output, const std::function<subd::Index(vtkIdType)>& finestFace,
  vtkSubDSeamChannel& channel, std::vector<vtkIdType>& newOfOld)
{
  const subd::MeshTopology& values = channel.Hierarchy.Finest.Topology;
  vtkCellArray* polys = output->GetPolys();
  const vtkIdType numFaces = polys->GetNumberOfCells();
  // The unsplit point of each channel vertex a face uses (-1: none uses it).
  std::vector<vtkIdType> sourceOf(static_cast<size_t>(values.GetNumVertices()), -1);
  vtkIdType n;
  const vtkIdType* corners;
  for (vtkIdType c = 0; c < numFaces; ++c)
  {
    polys->GetCellAtId(c, n, corners);
    const subd::IndexSpan channelCorners = values.GetFaceVertices(finestFace(c));
    for (vtkIdType k = 0; k < n; ++k)
    {
      sourceOf[channelCorners[k]] = corners[k];
    }
  }
  std::vector<vtkIdType> newOfChannel(sourceOf.size(), -1);
  newOfOld.assign(static_cast<size_t>(output->GetNumberOfPoints()), -1);
  for (size_t v = 0; v < sourceOf.size(); ++v)
  {
    if (sourceOf[v] >= 0)
    {
      newOfChannel[v] = static_cast<vtkIdType>(channel.SourcePoint.size());
      newOfOld[sourceOf[v]] = newOfChannel[v];
      channel.SourcePoint.push_back(sourceOf[v]);
      channel.ChannelVertex.push_back(static_cast<subd::Index>(v));
    }
  }
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    if (newOfOld[p] < 0)
    {
      newOfOld[p] = static_cast<vtkIdType>(channel.SourcePoint.size());
      channel.SourcePoint.push_back(p);
      channel.ChannelVertex.push_back(-1);
    }
  }
  vtkNew<vtkTypeInt32Array> offsets, connectivity;
  offsets->SetNumberOfTuples(numFaces + 1);
  offsets->SetValue(0, 0);
  for (vtkIdType c = 0; c < numFaces; ++c)
  {
    offsets->SetValue(c + 1, offsets->GetValue(c) + static_cast<vtkTypeInt32>(polys->GetCellSize(c)));
  }
  connectivity->SetNumberOfTuples(offsets->GetValue(numFaces));
  vtkSMPTools::For(0, numFaces, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType c = begin; c < end; ++c)
    {
      vtkTypeInt32* out = connectivity->GetPointer(offsets->GetValue(c));
      for (subd::Index v : values.GetFaceVertices(finestFace(c)))
      {
        *out++ = static_cast<vtkTypeInt32>(newOfChannel[v]);
      }
    }
  });
  channel.Faces = vtkSmartPointer<vtkCellArray>::New();
  channel.Faces->SetData(offsets, connectivity);
}

// The refined values of `array` (an input point-data array) at the channel's finest vertices.
std::vector<double> RefinedValues(vtkDataArray* array, const vtkSubDSeamChannel& channel)
{
  const int components = array->GetNumberOfComponents();
  std::vector<double> base(channel.UserValue.size() * static_cast<size_t>(components));
  for (size_t u = 0; u < channel.UserValue.size(); ++u)
  {
    array->GetTuple(channel.UserValue[u], &base[u * components]);
  }
  std::vector<double> finest(static_cast<size_t>(channel.Hierarchy.GetNumFinestPoints()) * components);
  channel.Hierarchy.Evaluate(base.data(), components, finest.data(), &vtkSubDPointDataInterpolation::SMPFor);
  return finest;
}

// The face-varying array of `source` at the split points: the channel's values where a face
// uses the point, 0 elsewhere (a point of a line passed through).
vtkSmartPointer<vtkDataArray> FaceVaryingArray(vtkDataArray* source, bool normals, const vtkSubDSeamChannel& channel)
{
  const int components = source->GetNumberOfComponents();
  const std::vector<double> values = RefinedValues(source, channel);
  vtkSmartPointer<vtkDataArray> target = vtkSmartPointer<vtkDataArray>::Take(source->NewInstance());
  target->SetName(source->GetName());
  target->SetNumberOfComponents(components);
  const vtkIdType numPoints = static_cast<vtkIdType>(channel.SourcePoint.size());
  target->SetNumberOfTuples(numPoints);
  vtkSMPTools::For(0, numPoints, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType p = begin; p < end; ++p)
    {
      const subd::Index v = channel.ChannelVertex[p];
      const double* value = v < 0 ? nullptr : &values[static_cast<size_t>(v) * components];
      const double length =
        value && normals ? std::sqrt(value[0] * value[0] + value[1] * value[1] + value[2] * value[2]) : 1.0;
      for (int c = 0; c < components; ++c)
      {
        target->SetComponent(p, c, value ? StoredValue(target, length > 0.0 ? value[c] / length : value[c]) : 0.0);
      }
    }
  });
  return target;
}
}

void vtkSubDSplitAtSeams(vtkPolyData* input, const vtkSubDSeams& seams,
  const std::function<subd::Index(vtkIdType)>& finestFace, vtkSubDSeamChannel& channel, vtkPolyData* output)
{
  std::vector<vtkIdType> newOfOld;
  if (!channel.Faces)
  {
    MakeSplitTopology(output, finestFace, channel, newOfOld);
  }
  else
  {
    newOfOld.assign(static_cast<size_t>(output->GetNumberOfPoints()), -1);
    for (size_t p = channel.SourcePoint.size(); p-- > 0;)
    {
      newOfOld[channel.SourcePoint[p]] = static_cast<vtkIdType>(p);
    }
  }
  // Every array of the unsplit output, gathered at the split points' sources.
  vtkNew<vtkIdList> sources;
  sources->SetNumberOfIds(static_cast<vtkIdType>(channel.SourcePoint.size()));
  std::copy(channel.SourcePoint.begin(), channel.SourcePoint.end(), sources->GetPointer(0));
  auto gather = [&sources](vtkDataArray* array) {
    vtkSmartPointer<vtkDataArray> split = vtkSmartPointer<vtkDataArray>::Take(array->NewInstance());
    split->SetName(array->GetName());
    split->SetNumberOfComponents(array->GetNumberOfComponents());
    split->SetNumberOfTuples(sources->GetNumberOfIds());
    array->GetTuples(sources, split);
    return split;
  };
  vtkNew<vtkPoints> points;
  points->SetData(gather(output->GetPoints()->GetData()));
  vtkPointData* unsplit = output->GetPointData();
  vtkNew<vtkPointData> split;
  for (int a = 0; a < unsplit->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = unsplit->GetArray(a))
    {
      split->AddArray(gather(array));
      const int attribute = unsplit->IsArrayAnAttribute(a);
      if (attribute >= 0)
      {
        split->SetActiveAttribute(split->GetNumberOfArrays() - 1, attribute);
      }
    }
  }
  vtkPointData* inPD = input->GetPointData();
  for (int a : seams.Arrays)
  {
    if (vtkDataArray* source = inPD->GetArray(a))
    {
      const int attribute = inPD->IsArrayAnAttribute(a);
      split->AddArray(FaceVaryingArray(source, attribute == vtkDataSetAttributes::NORMALS, channel));
      if (attribute >= 0)
      {
        split->SetActiveAttribute(split->GetNumberOfArrays() - 1, attribute);
      }
    }
  }
  vtkNew<vtkCellArray> lines;
  vtkIdType n;
  const vtkIdType* ends;
  vtkCellArray* oldLines = output->GetLines();
  std::vector<vtkIdType> line;
  for (oldLines->InitTraversal(); oldLines->GetNextCell(n, ends);)
  {
    line.assign(ends, ends + n);
    for (vtkIdType& p : line)
    {
      p = newOfOld[p];
    }
    lines->InsertNextCell(n, line.data());
  }
  output->SetPoints(points);
  output->GetPointData()->ShallowCopy(split);
  output->SetLines(lines);
  output->SetPolys(channel.Faces);
}
