// SubD kernel: Catmull-Clark masks for one level (E. Catmull, J. Clark, "Recursively
// generated B-spline surfaces on arbitrary topological meshes", CAD 10(6), 1978), with the
// boundary and crease rules of Hoppe et al. (SIGGRAPH 1994) and DeRose et al. (SIGGRAPH 1998)
// in the form OpenSubdiv uses, so the results agree with it to round-off:
//
//   face point   f  = average of the face's n vertices
//   edge point   e  = (v0 + v1 + f0 + f1) / 4                     smooth edge (two faces)
//                e  = (1/2 - w)(v0 + v1) + w (f0 + f1)            the same with OpenSubdiv's
//                     smooth triangle rule (Sdc TRI_SUB_SMOOTH): w the mean over the two faces
//                     of 0.47 for a triangle, 1/4 for any other face
//                e  = (v0 + v1) / 2                               sharp, boundary, non-manifold
//   vertex point v' = (n-2)/n v + 1/n^2 sum(e_i) + 1/n^2 sum(f_i)  Smooth or Dart rule, n faces,
//                     e_i the far ends of the n edges, f_i the new face points; where nothing
//                     around v is sharp, the same from the new edge points E_i:
//                v' = (n-3)/n v + 4/n^2 sum(E_i) - 1/n^2 sum(f_i)  (sum(E_i) = (n v + sum(e_i)
//                     + 2 sum(f_i)) / 4), one read per neighbour instead of two
//                v' = 3/4 v + 1/8 (a + b)                         Crease rule, a, b the far ends
//                                                                  of the two sharp edges
//                v' = v                                           Corner rule
//
// The returned table has three blocks: the face points, the edge points, which read the
// face points of the same level, and the vertex points, which read both. Its rows are numbered like the child
// points of the quad split (SubDQuadSplit.h).
#ifndef SubDCatmullClarkRules_h
#define SubDCatmullClarkRules_h

#include <algorithm>

#include "SubDLevel.h"
#include "SubDPrimalRules.h"
#include "SubDQuadSplit.h"
#include "SubDRowWriting.h"
#include "SubDStencilTable.h"

namespace subd
{
/// `smoothTriangles`: OpenSubdiv's smooth triangle rule for the edges of triangles.
SUBDKERNEL_EXPORT StencilTable BuildCatmullClarkStencils(const Level& parent, bool smoothTriangles = false);

/// Catmull-Clark's smooth edge weight on each face point (each end takes 1/2 less it); the
/// crease rule blends the mask with the midpoint (WritePrimalEdgeRow).
constexpr double CatmullClarkEdgeFaceWeight = 0.25;
/// The smooth triangle rule's weight of a triangle's face point.
constexpr double CatmullClarkTriangleFaceWeight = 0.47;

/// The weight of each face point in the smooth edge point of an edge with faces `faces` (two):
/// Catmull-Clark's, or with the smooth triangle rule the mean of the faces' weights.
inline double CatmullClarkEdgeFaceWeightOf(const MeshTopology& topo, IndexSpan faces, bool smoothTriangles)
{
  if (!smoothTriangles)
  {
    return CatmullClarkEdgeFaceWeight;
  }
  auto weight = [&topo](Index f) {
    return topo.GetFaceSize(f) == 3 ? CatmullClarkTriangleFaceWeight : CatmullClarkEdgeFaceWeight;
  };
  return 0.5 * (weight(faces[0]) + weight(faces[1]));
}

/// The smooth edge point of an edge with ends `ends` and face points `facePoints` (children),
/// `faceWeight` on each face point and what remains on the ends.
template <typename Entries>
void CatmullClarkSmoothEdgeMask(
  const Index* ends, const Index* facePoints, Entries& entries, double faceWeight = CatmullClarkEdgeFaceWeight)
{
  const double endWeight = 0.5 - faceWeight;
  entries.Parent(ends[0], endWeight);
  entries.Parent(ends[1], endWeight);
  entries.Child(facePoints[0], faceWeight);
  entries.Child(facePoints[1], faceWeight);
}

/// The smooth vertex point of v from the new edge and face points around it (the form that
/// reads them): (n-3)/n v + 4/n^2 sum(E_i) - 1/n^2 sum(F_i), n faces; edgePoint(i) and
/// facePoint(i) name the i-th of each.
template <typename EdgePoint, typename FacePoint, typename Entries>
void CatmullClarkSmoothVertexMask(
  Index v, Index numEdges, Index numFaces, EdgePoint&& edgePoint, FacePoint&& facePoint, Entries& entries)
{
  const double n = numFaces;
  entries.Parent(v, (n - 3.0) / n);
  for (Index i = 0; i < numEdges; ++i)
  {
    entries.Child(edgePoint(i), 4.0 / (n * n));
  }
  for (Index i = 0; i < numFaces; ++i)
  {
    entries.Child(facePoint(i), -1.0 / (n * n));
  }
}

/// The same vertex point from the parent's ring (the form a crease's semi-sharp transition
/// blends with the crease rule, WritePrimalVertexRow): (n-2)/n v + 1/n^2 sum(e_i) + 1/n^2
/// sum(F_i), e_i the far ends of v's edges.
template <typename FacePoint, typename Entries>
void CatmullClarkRingVertexMask(
  const MeshTopology& topo, Index v, IndexSpan edges, Index numFaces, FacePoint&& facePoint, Entries& entries)
{
  const double n = numFaces;
  const double ringWeight = 1.0 / (n * n);
  entries.Parent(v, (n - 2.0) / n);
  for (Index e : edges)
  {
    entries.Parent(topo.GetOtherEndpoint(e, v), ringWeight);
  }
  for (Index i = 0; i < numFaces; ++i)
  {
    entries.Child(facePoint(i), ringWeight);
  }
}

/// The rows written one at a time (SubDRowWriting.h), each vertex's rule planned as its row
/// is written: what BuildCatmullClarkStencils stores, and what the finest level applies
/// without storing.
class SUBDKERNEL_EXPORT CatmullClarkRowWriter
{
public:
  explicit CatmullClarkRowWriter(
    const Level& parent, const ParallelFor& parallelFor = SerialFor, bool smoothTriangles = false);
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->Number.VertexPoint(this->Topology.GetNumVertices()); }
  std::vector<Index> GetBlockEnds() const
  {
    return { this->Number.EdgePoint(0), this->Number.VertexPoint(0), this->GetNumRows() };
  }
  Index GetMaxRowSize() const { return this->MaxRowSize; }
  Index WriteRow(Index row, Index* sources, double* weights) const;
  /// Face points, smooth edges (two faces, not sharp), vertices with a closed fan and nothing
  /// sharp at or around them (FindSmoothClosedVertices): their masks; false for other rows.
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const;

private:
  Index WriteEdgeRow(Index e, Index* sources, double* weights) const;
  Index WriteVertexRow(Index v, Index* sources, double* weights) const;

  const Level& Parent;
  const MeshTopology& Topology;
  QuadSplitNumbering Number;
  Index MaxRowSize = 4;
  std::vector<std::uint8_t> SmoothVertex; // FindSmoothClosedVertices
  bool SmoothTriangles = false;
};

template <typename Entries>
SUBD_ALWAYS_INLINE bool CatmullClarkRowWriter::VisitSmoothRow(Index row, Entries& entries) const
{
  const MeshTopology& topo = this->Topology;
  if (row < this->Number.NumFaces)
  {
    CentroidMask(topo.GetFaceVertices(row), entries);
    return true;
  }
  const Index firstVertexPoint = this->Number.VertexPoint(0);
  if (row < firstVertexPoint)
  {
    const Index e = row - this->Number.NumFaces;
    if (!IsSmoothEdge(this->Parent, e))
    {
      return false;
    }
    const IndexSpan ef = topo.GetEdgeFaces(e);
    const Index facePoints[2] = { this->Number.FacePoint(ef[0]), this->Number.FacePoint(ef[1]) };
    CatmullClarkSmoothEdgeMask(
      topo.GetEdgeVertices(e), facePoints, entries, CatmullClarkEdgeFaceWeightOf(topo, ef, this->SmoothTriangles));
    return true;
  }
  const Index v = row - firstVertexPoint;
  const IndexSpan faces = topo.GetVertexFaces(v);
  // The mask below reads the new edge points, which is the smooth rule only where they are
  // Catmull-Clark's: next to a triangle under the smooth triangle rule, the ring's form is
  // written instead (WriteVertexRow).
  if (!this->SmoothVertex[v] ||
    (this->SmoothTriangles &&
      std::any_of(faces.begin(), faces.end(), [&topo](Index f) { return topo.GetFaceSize(f) == 3; })))
  {
    return false;
  }
  const IndexSpan edges = topo.GetVertexEdges(v);
  CatmullClarkSmoothVertexMask(
    v, edges.size(), faces.size(), [&](Index i) { return this->Number.EdgePoint(edges[i]); },
    [&](Index i) { return this->Number.FacePoint(faces[i]); }, entries);
  return true;
}
}

#endif
