#include "SubDCageEditing.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <vector>

namespace subdapp
{
namespace
{
constexpr double InfiniteSharpness = 10.0;

// One crease segment: its ends, sharpness, and the cell its data comes from (-1: none).
struct Segment
{
  vtkIdType A, B;
  double Sharpness;
  vtkIdType Source;
};

std::vector<Segment> ReadSegments(vtkPolyData* cage)
{
  std::vector<Segment> segments;
  vtkDataArray* sharpness = cage->GetCellData()->GetArray("Sharpness");
  const vtkIdType firstLine = cage->GetNumberOfVerts();
  vtkCellArray* lines = cage->GetLines();
  vtkNew<vtkIdList> cell;
  vtkIdType index = 0;
  for (lines->InitTraversal(); lines->GetNextCell(cell); ++index)
  {
    const vtkIdType id = firstLine + index;
    const double s = sharpness ? sharpness->GetComponent(id, 0) : InfiniteSharpness;
    for (vtkIdType k = 0; k + 1 < cell->GetNumberOfIds(); ++k)
    {
      segments.push_back({ cell->GetId(k), cell->GetId(k + 1), s, id });
    }
  }
  return segments;
}
}

bool IsCageEdge(vtkPolyData* cage, vtkIdType a, vtkIdType b)
{
  vtkCellArray* polys = cage->GetPolys();
  vtkNew<vtkIdList> cell;
  for (polys->InitTraversal(); polys->GetNextCell(cell);)
  {
    const vtkIdType n = cell->GetNumberOfIds();
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType p = cell->GetId(k), q = cell->GetId((k + 1) % n);
      if ((p == a && q == b) || (p == b && q == a))
      {
        return true;
      }
    }
  }
  return false;
}

double GetEdgeSharpness(vtkPolyData* cage, vtkIdType a, vtkIdType b)
{
  for (const Segment& s : ReadSegments(cage))
  {
    if ((s.A == a && s.B == b) || (s.A == b && s.B == a))
    {
      return s.Sharpness;
    }
  }
  return 0.0;
}

bool SetEdgeSharpness(vtkPolyData* cage, vtkIdType a, vtkIdType b, double sharpness, std::string& error)
{
  if (!(sharpness >= 0.0))
  {
    error = "a sharpness must be a number >= 0";
    return false;
  }
  if (!IsCageEdge(cage, a, b))
  {
    error = "(" + std::to_string(a) + ", " + std::to_string(b) + ") is not an edge of the cage's polygons";
    return false;
  }
  std::vector<Segment> segments = ReadSegments(cage);
  bool found = false;
  for (Segment& s : segments)
  {
    if ((s.A == a && s.B == b) || (s.A == b && s.B == a))
    {
      s.Sharpness = sharpness;
      found = true;
    }
  }
  if (!found)
  {
    segments.push_back({ a, b, sharpness, -1 });
  }

  // Rebuild: verts, the segments, polys and strips, each cell's data copied from its source.
  vtkNew<vtkPolyData> edited;
  edited->SetPoints(cage->GetPoints());
  edited->GetPointData()->ShallowCopy(cage->GetPointData());
  edited->SetVerts(cage->GetVerts());
  vtkNew<vtkCellArray> lines;
  std::vector<vtkIdType> sources;
  std::vector<float> values;
  for (vtkIdType v = 0; v < cage->GetNumberOfVerts(); ++v)
  {
    sources.push_back(v);
    values.push_back(0.0f);
  }
  for (const Segment& s : segments)
  {
    if (s.Sharpness > 0.0)
    {
      const vtkIdType ends[2] = { s.A, s.B };
      lines->InsertNextCell(2, ends);
      sources.push_back(s.Source);
      values.push_back(static_cast<float>(s.Sharpness));
    }
  }
  edited->SetLines(lines);
  edited->SetPolys(cage->GetPolys());
  edited->SetStrips(cage->GetStrips());
  const vtkIdType firstPoly = cage->GetNumberOfVerts() + cage->GetNumberOfLines();
  for (vtkIdType c = 0; c < cage->GetNumberOfPolys() + cage->GetNumberOfStrips(); ++c)
  {
    sources.push_back(firstPoly + c);
    values.push_back(0.0f);
  }
  vtkCellData* from = cage->GetCellData();
  vtkCellData* to = edited->GetCellData();
  to->CopyAllocate(from, static_cast<vtkIdType>(sources.size()));
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(sources.size()); ++c)
  {
    if (sources[c] >= 0)
    {
      to->CopyData(from, sources[c], c);
    }
    else
    {
      to->NullData(c);
    }
  }
  vtkNew<vtkFloatArray> sharpnessArray;
  sharpnessArray->SetName("Sharpness");
  sharpnessArray->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (vtkIdType c = 0; c < static_cast<vtkIdType>(values.size()); ++c)
  {
    sharpnessArray->SetValue(c, values[c]);
  }
  to->RemoveArray("Sharpness");
  to->AddArray(sharpnessArray);
  cage->ShallowCopy(edited);
  cage->Modified();
  return true;
}

double GetVertexSharpness(vtkPolyData* cage, vtkIdType v)
{
  vtkDataArray* corners = cage->GetPointData()->GetArray("CornerSharpness");
  return corners && v >= 0 && v < corners->GetNumberOfTuples() ? corners->GetComponent(v, 0) : 0.0;
}

bool SetVertexSharpness(vtkPolyData* cage, vtkIdType v, double sharpness, std::string& error)
{
  if (!(sharpness >= 0.0))
  {
    error = "a sharpness must be a number >= 0";
    return false;
  }
  if (v < 0 || v >= cage->GetNumberOfPoints())
  {
    error = "the cage has no vertex " + std::to_string(v);
    return false;
  }
  vtkDataArray* corners = cage->GetPointData()->GetArray("CornerSharpness");
  if (!corners)
  {
    vtkNew<vtkFloatArray> added;
    added->SetName("CornerSharpness");
    added->SetNumberOfTuples(cage->GetNumberOfPoints());
    added->Fill(0.0);
    cage->GetPointData()->AddArray(added);
    corners = added;
  }
  corners->SetComponent(v, 0, sharpness);
  corners->Modified();
  cage->Modified();
  return true;
}
}
