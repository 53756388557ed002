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
  Index WriteRow(Index row, Index* sources, double* weights) const;
  /// Every row is known in closed form.
  template <typename T>
  bool ApplySmoothRow(Index row, const T* parents, const T* children, T* dst) const;

private:
  const MeshTopology& Topology;
  Index FirstEdgeRow;
  Index FirstVertexRow;
  Index MaxRowSize = 2;
};

template <typename T>
SUBD_ALWAYS_INLINE bool LinearRowWriter::ApplySmoothRow(Index row, const T* parents, const T*, T* dst) const
{
  PointSum point;
  if (row < this->FirstEdgeRow)
  {
    const IndexSpan fv = this->Topology.GetFaceVertices(row);
    const double w = 1.0 / fv.size();
    for (Index v : fv)
    {
      point.Add(w, parents + 3 * static_cast<size_t>(v));
    }
  }
  else if (row < this->FirstVertexRow)
  {
    const Index* ev = this->Topology.GetEdgeVertices(row - this->FirstEdgeRow);
    point.Add(0.5, parents + 3 * static_cast<size_t>(ev[0]));
    point.Add(0.5, parents + 3 * static_cast<size_t>(ev[1]));
  }
  else
  {
    point.Add(1.0, parents + 3 * static_cast<size_t>(row - this->FirstVertexRow));
  }
  point.Store(dst);
  return true;
}
}

#endif
