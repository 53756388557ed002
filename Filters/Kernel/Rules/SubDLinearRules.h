// SubD kernel: linear subdivision, which adds resolution without smoothing.
//
// - Bilinear (on the quad split, SubDQuadSplit.h): face point = centroid of the face, edge
//   point = midpoint, vertex point = the vertex. The same surface for any polygon mesh, and
//   OpenSubdiv's Sdc::SCHEME_BILINEAR.
// - Linear triangles (on the triangle split, SubDTriangleSplit.h): edge point = midpoint,
//   vertex point = the vertex; what VTK's vtkLinearSubdivisionFilter does.
// Both are exact for data that varies linearly over each face (bilinearly over a quad).
#ifndef SubDLinearRules_h
#define SubDLinearRules_h

#include "SubDLevel.h"
#include "SubDRowWriting.h"
#include "SubDStencilTable.h"

namespace subd
{
SUBDKERNEL_EXPORT StencilTable BuildBilinearStencils(const Level& parent);
/// Requires every face of `parent` to be a triangle.
SUBDKERNEL_EXPORT StencilTable BuildLinearTriangleStencils(const Level& parent);

/// The rows of either rule written one at a time (SubDRowWriting.h): face points first when
/// `facePoints` (bilinear; the quad split's numbering), then edge points, then vertex points
/// (the triangle split's numbering without face points). One block: no row reads another.
class SUBDKERNEL_EXPORT LinearRowWriter
{
public:
  LinearRowWriter(const Level& parent, bool facePoints);
  Index GetNumParents() const { return this->Topology.GetNumVertices(); }
  Index GetNumRows() const { return this->FirstVertexRow + this->Topology.GetNumVertices(); }
  std::vector<Index> GetBlockEnds() const { return { this->GetNumRows() }; }
  Index GetMaxRowSize() const { return this->MaxRowSize; }
  Index WriteRow(Index row, Index* sources, double* weights) const
  {
    RowEntries entries{ sources, weights, this->GetNumParents() };
    this->VisitSmoothRow(row, entries);
    return entries.Size;
  }
  /// Every row: a centroid, a midpoint or a copy.
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const;

private:
  const MeshTopology& Topology;
  Index FirstEdgeRow;
  Index FirstVertexRow;
  Index MaxRowSize = 2;
};

template <typename Entries>
SUBD_ALWAYS_INLINE bool LinearRowWriter::VisitSmoothRow(Index row, Entries& entries) const
{
  if (row < this->FirstEdgeRow)
  {
    CentroidMask(this->Topology.GetFaceVertices(row), entries);
  }
  else if (row < this->FirstVertexRow)
  {
    MidpointMask(this->Topology.GetEdgeVertices(row - this->FirstEdgeRow), entries);
  }
  else
  {
    CopyMask(row - this->FirstVertexRow, entries);
  }
  return true;
}
}

#endif
