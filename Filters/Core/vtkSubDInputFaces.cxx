#include "vtkSubDInputFaces.h"

#include "SubDMeshTopology.h"
#include "SubDPolygonTriangulation.h"
#include "vtkSubDPointDataInterpolation.h"

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTypeInt64Array.h"

#include <algorithm>
#include <cmath>

namespace
{
void ReadCells(vtkCellArray* cells, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& conn)
{
  offsets.clear();
  conn.clear();
  offsets.push_back(0);
  vtkIdType n;
  const vtkIdType* pts;
  for (cells->InitTraversal(); cells->GetNextCell(n, pts);)
  {
    conn.insert(conn.end(), pts, pts + n);
    offsets.push_back(static_cast<vtkIdType>(conn.size()));
  }
}
}

vtkSubDInputFaces vtkSubDGatherFaces(vtkPolyData* input)
{
  vtkSubDInputFaces faces;
  vtkCellArray* polys = input->GetPolys();
  vtkCellArray* strips = input->GetStrips();
  const vtkIdType numPolys = polys ? polys->GetNumberOfCells() : 0;
  const vtkIdType numStrips = strips ? strips->GetNumberOfCells() : 0;
  faces.FirstPolyCellId = input->GetNumberOfVerts() + input->GetNumberOfLines();

  if (numStrips == 0 && numPolys > 0 && polys->IsStorage64Bit() && sizeof(vtkIdType) == 8)
  {
    faces.Offsets = reinterpret_cast<const vtkIdType*>(polys->GetOffsetsArray64()->GetPointer(0));
    faces.Connectivity =
      reinterpret_cast<const vtkIdType*>(polys->GetConnectivityArray64()->GetPointer(0));
    faces.NumFaces = numPolys;
    return faces;
  }
  if (numPolys > 0)
  {
    ReadCells(polys, faces.OwnedOffsets, faces.OwnedConnectivity);
  }
  else
  {
    faces.OwnedOffsets.assign(1, 0);
  }
  if (numStrips > 0)
  {
    // A strip p0 p1 p2 p3 ... is the triangles (p0 p1 p2), (p2 p1 p3), ... with alternating
    // orientation so all of them face the same way.
    const vtkIdType firstStripCellId = faces.FirstPolyCellId + numPolys;
    vtkIdType n;
    const vtkIdType* pts;
    vtkIdType s = 0;
    for (strips->InitTraversal(); strips->GetNextCell(n, pts); ++s)
    {
      for (vtkIdType k = 0; k + 2 < n; ++k)
      {
        const bool even = (k % 2) == 0;
        faces.OwnedConnectivity.push_back(even ? pts[k] : pts[k + 1]);
        faces.OwnedConnectivity.push_back(even ? pts[k + 1] : pts[k]);
        faces.OwnedConnectivity.push_back(pts[k + 2]);
        faces.OwnedOffsets.push_back(static_cast<vtkIdType>(faces.OwnedConnectivity.size()));
        faces.StripCellIds.push_back(firstStripCellId + s);
      }
    }
  }
  faces.Offsets = faces.OwnedOffsets.data();
  faces.Connectivity = faces.OwnedConnectivity.data();
  faces.NumFaces = static_cast<vtkIdType>(faces.OwnedOffsets.size()) - 1;
  return faces;
}

vtkIdType vtkSubDFirstNonFinitePoint(vtkPoints* points)
{
  const vtkIdType n = points->GetNumberOfPoints();
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      return i;
    }
  }
  return -1;
}


vtkIdType vtkSubDFirstCellOutsidePoints(vtkPolyData* input)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkIdType cellId = 0;
  for (vtkCellArray* cells : { input->GetVerts(), input->GetLines(), input->GetPolys(), input->GetStrips() })
  {
    vtkIdType n;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cellId)
    {
      for (vtkIdType k = 0; k < n; ++k)
      {
        if (ids[k] < 0 || ids[k] >= numPoints)
        {
          return cellId;
        }
      }
    }
  }
  return -1;
}

bool vtkSubDScreenFaces(const vtkSubDInputFaces& faces, vtkIdType numPoints, vtkIdType numPolys,
  subd::RepeatedCorners repeated, subd::FaceScreening& screened, std::string& error, std::string& warning)
{
  screened = subd::ScreenFaces(static_cast<subd::Index>(numPoints), static_cast<subd::Index>(faces.NumFaces),
    faces.Offsets, faces.Connectivity, &vtkSubDPointDataInterpolation::SMPFor, repeated);
  auto cell = [&](subd::Index face) { return std::to_string(faces.CellIdOf(face, numPolys)); };
  if (screened.NumOutOfRange > 0)
  {
    error = std::to_string(screened.NumOutOfRange) + " input cell(s) refer to points that do not exist; the first, " +
      "cell " + cell(screened.FirstOutOfRangeFace) + ", uses point id " + std::to_string(screened.FirstOutOfRangeId) +
      " but the input has " + std::to_string(numPoints) + " points";
    return false;
  }
  warning.clear();
  const subd::Index kept = screened.NumRepeatingKept, collapsed = screened.NumRepeatingCollapsed;
  if (kept + collapsed > 0) // (the others are dropped, and counted so below)
  {
    std::string what = kept == 0 ? "" : std::to_string(kept) + " kept as OpenSubdiv keeps them (an edge from a point " +
        "to itself and the repeated point infinitely sharp)";
    if (collapsed > 0)
    {
      what += (what.empty() ? "" : ", ") + std::to_string(collapsed) + " with their repeated corners collapsed";
    }
    warning = std::to_string(screened.NumRepeating) + " polygon(s) repeat a point at several corners (the first " +
      "is cell " + cell(screened.FirstRepeatingFace) + "): " + what;
  }
  if (screened.NumDropped > 0)
  {
    warning += (warning.empty() ? "" : "; ") + std::string("ignored ") + std::to_string(screened.NumDropped) +
      " degenerate polygon(s) (fewer than 3 corners or 2 distinct points, or a point repeated after collapsing); " +
      "the first is cell " + cell(screened.FirstDroppedFace);
  }
  return true;
}

namespace
{
// Whether face f names v at several corners.
bool RepeatsVertex(const subd::MeshTopology& topology, subd::Index f, subd::Index v)
{
  const subd::IndexSpan corners = topology.GetFaceVertices(f);
  return std::count(corners.begin(), corners.end(), v) > 1;
}

// What a face that repeats a point makes non-manifold (its edges from a point to itself or
// joining a pair it meets twice; the repeated points), which vtkSubDScreenFaces reports with
// those faces.
bool FromRepeatedCorners(const subd::MeshTopology& topology, subd::Index e)
{
  const subd::Index* ends = topology.GetEdgeVertices(e);
  const subd::IndexSpan faces = topology.GetEdgeFaces(e);
  return std::any_of(faces.begin(), faces.end(), [&](subd::Index f) {
    return RepeatsVertex(topology, f, ends[0]) || RepeatsVertex(topology, f, ends[1]);
  });
}
bool VertexFromRepeatedCorners(const subd::MeshTopology& topology, subd::Index v)
{
  const subd::IndexSpan faces = topology.GetVertexFaces(v); // a face naming v twice is listed twice
  if (std::adjacent_find(faces.begin(), faces.end()) != faces.end())
  {
    return true;
  }
  const subd::IndexSpan edges = topology.GetVertexEdges(v);
  const auto nonManifold = [&topology](subd::Index e) { return topology.GetEdgeTag(e).NonManifold != 0; };
  return std::any_of(edges.begin(), edges.end(), nonManifold) &&
    std::all_of(edges.begin(), edges.end(),
      [&](subd::Index e) { return !nonManifold(e) || FromRepeatedCorners(topology, e); });
}
}

std::string vtkSubDNonManifoldWarning(const subd::MeshTopology& topology, const std::vector<std::uint8_t>& faceIsGhost)
{
  if (topology.GetNumNonManifoldEdges() == 0 && topology.GetNumNonManifoldVertices() == 0)
  {
    return "";
  }
  // A piece: only what touches its own faces (the rim of its ghost layers is cut anywhere).
  auto touchesOwnFace = [&faceIsGhost](subd::IndexSpan faces) {
    return faceIsGhost.empty() ||
      std::any_of(faces.begin(), faces.end(), [&faceIsGhost](subd::Index f) { return !faceIsGhost[f]; });
  };
  subd::Index edges = 0, vertices = 0;
  for (subd::Index e = 0; e < topology.GetNumEdges(); ++e)
  {
    edges += topology.GetEdgeTag(e).NonManifold && touchesOwnFace(topology.GetEdgeFaces(e)) &&
      !FromRepeatedCorners(topology, e);
  }
  // A topology without vertex relations (the linear schemes') does not know its vertices.
  const bool knowsVertices = topology.HasVertexRelations();
  for (subd::Index v = 0; knowsVertices && v < topology.GetNumVertices(); ++v)
  {
    vertices += topology.GetVertexTag(v).NonManifold && touchesOwnFace(topology.GetVertexFaces(v)) &&
      !VertexFromRepeatedCorners(topology, v);
  }
  if (edges == 0 && vertices == 0)
  {
    return "";
  }
  const std::string vertexCount = knowsVertices ? ", " + std::to_string(vertices) + " non-manifold vertices" : "";
  return "Input is non-manifold (" + std::to_string(edges) + " edges with more than two faces or inconsistent " +
    "orientation" + vertexCount + "); they are subdivided as infinitely sharp";
}

subd::Index vtkSubDTriangulateFaces(subd::FaceScreening& faces, vtkPoints* points)
{
  const size_t numFaces = faces.KeptFaces.size();
  subd::Index split = 0;
  for (size_t f = 0; f < numFaces && split == 0; ++f)
  {
    split += faces.Offsets[f + 1] - faces.Offsets[f] > 3;
  }
  if (split == 0)
  {
    return 0;
  }
  split = 0;
  subd::IndexArray offsets{ 0 }, vertices, kept;
  std::vector<subd::Index> local;
  std::vector<double> xyz;
  for (size_t f = 0; f < numFaces; ++f)
  {
    const subd::Index* corners = faces.Vertices.data() + faces.Offsets[f];
    const subd::Index n = faces.Offsets[f + 1] - faces.Offsets[f];
    split += n > 3;
    xyz.resize(3 * static_cast<size_t>(n));
    for (subd::Index k = 0; k < n; ++k)
    {
      points->GetPoint(corners[k], &xyz[3 * k]);
    }
    local.clear();
    subd::TriangulatePolygon(xyz.data(), n, local);
    for (size_t t = 0; t < local.size(); t += 3)
    {
      vertices.insert(vertices.end(), { corners[local[t]], corners[local[t + 1]], corners[local[t + 2]] });
      offsets.push_back(static_cast<subd::Index>(vertices.size()));
      kept.push_back(faces.KeptFaces[f]);
    }
  }
  faces.Offsets.swap(offsets);
  faces.Vertices.swap(vertices);
  faces.KeptFaces.swap(kept);
  return split;
}

std::string vtkSubDSplitPolygonsWarning(subd::Index split)
{
  return std::to_string(split) + " polygon(s) with more than 3 corners were split into triangles: this scheme "
    "is defined on triangles only";
}
