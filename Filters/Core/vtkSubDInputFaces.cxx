#include "vtkSubDInputFaces.h"

#include "SubDMeshTopology.h"

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

std::string vtkSubDNonManifoldWarning(const subd::MeshTopology& topology, const std::vector<std::uint8_t>& faceIsGhost)
{
  if (topology.GetNumNonManifoldEdges() == 0 && topology.GetNumNonManifoldVertices() == 0)
  {
    return "";
  }
  subd::Index edges = topology.GetNumNonManifoldEdges(), vertices = topology.GetNumNonManifoldVertices();
  if (!faceIsGhost.empty())
  {
    // A piece: only what touches its own faces (the rim of its ghost layers is cut anywhere).
    auto touchesOwnFace = [&faceIsGhost](subd::IndexSpan faces) {
      return std::any_of(faces.begin(), faces.end(), [&faceIsGhost](subd::Index f) { return !faceIsGhost[f]; });
    };
    edges = vertices = 0;
    for (subd::Index e = 0; e < topology.GetNumEdges(); ++e)
    {
      edges += topology.GetEdgeTag(e).NonManifold && touchesOwnFace(topology.GetEdgeFaces(e));
    }
    for (subd::Index v = 0; v < topology.GetNumVertices(); ++v)
    {
      vertices += topology.GetVertexTag(v).NonManifold && touchesOwnFace(topology.GetVertexFaces(v));
    }
    if (edges == 0 && vertices == 0)
    {
      return "";
    }
  }
  // A topology without vertex relations (the linear schemes') does not know its vertices.
  const std::string vertexCount =
    topology.HasVertexRelations() ? ", " + std::to_string(vertices) + " non-manifold vertices" : "";
  return "Input is non-manifold (" + std::to_string(edges) + " edges with more than two faces or inconsistent " +
    "orientation" + vertexCount + "); they are subdivided as infinitely sharp";
}
