// SubD kernel: the Catmull-Clark rows of the finest level written from its grandparent's
// topology, so that its parent's topology need not be kept.
//
// Rows written as they are applied (SubDRowWriting.h) keep the level they are written from.
// For the finest level that is the largest topology of a refinement (about 170 bytes per
// face, several times the finest points): most of the peak memory. But the finest level's
// parent C is the quad split of its own parent P (SubDQuadSplit.h), and a quad split's
// topology is known in closed form from its parent's (SubDPrimalSplitShape.h): the child
// of P's face f at its corner j is [vertex point of v_j, edge point of edge j, face point of
// f, edge point of edge j - 1], a half of P's edge lies in the children of the edge's faces
// at its vertex, the faces and edges around a point of C are those around the face, edge or
// vertex of P it stands for. So the rows of the smooth points (face points everywhere, edge
// and vertex points away from creases and boundaries: nearly all of them) are written from
// P here, with C's numbering and in the order C's own row writer (CatmullClarkRowWriter)
// writes them, which gives the same bits. The other rows are written once from C when this
// source is made, and stored; then C can go.
//
// The faces of the finest level follow from P the same way (SplitQuadsTwice).
#ifndef SubDCatmullClarkGrandchildRows_h
#define SubDCatmullClarkGrandchildRows_h

#include "SubDLevel.h"
#include "SubDPrimalSplitShape.h"
#include "SubDStencilTable.h"

#include <memory>
#include <vector>

namespace subd
{
class SUBDKERNEL_EXPORT CatmullClarkGrandchildRows final : public RowSource
{
public:
  /// `parent` must be SplitQuads(*grandparent) with its full topology; it is read here and
  /// not kept.
  CatmullClarkGrandchildRows(
    std::shared_ptr<const Level> grandparent, const Level& parent, const ParallelFor& parallelFor = SerialFor);

  Index GetNumParents() const override { return this->NumParents; }
  Index GetNumRows() const override { return this->NumRows; }
  std::vector<Index> GetBlockEnds() const override;
  void ApplyRows(const double* parents, double* children, int components, Index begin, Index end) const override;
  void ApplyRows(const float* parents, float* children, int components, Index begin, Index end) const override;

  /// Every row in a stored table (to inspect them).
  StencilTable ToStencilTable() const;
  /// How the parent's edges are numbered (for SplitQuadsTwice).
  const ChildEdgeNumbering& GetParentEdgeNumbering() const { return this->ParentEdges; }
  /// The rows stored because they are not smooth.
  Index GetNumStoredRows() const { return static_cast<Index>(this->StoredRows.size()); }

private:
  template <typename Emit>
  void WriteRows(Index begin, Index end, Index* sources, double* weights, Emit&& emit) const;
  template <typename T>
  void Apply(const T* parents, T* children, int components, Index begin, Index end) const;

  std::shared_ptr<const Level> Grandparent;
  ChildEdgeNumbering ParentEdges;
  Index NumParentFaces = 0, NumParentEdges = 0, NumParents = 0, NumRows = 0;
  Index MaxRowSize = 4;
  std::vector<Index> StoredRows; // sorted; row StoredRows[i] is StoredTable's row i
  StencilTable StoredTable;
};

/// The finest level (faces only) of two quad splits of `grandparent`, without the level
/// between: the same faces, holes and origins as SplitQuads(SplitQuads(grandparent, Full),
/// FacesOnly). `parentEdges` numbers the edges of the level between
/// (CatmullClarkGrandchildRows::GetParentEdgeNumbering).
SUBDKERNEL_EXPORT Level SplitQuadsTwice(
  const Level& grandparent, const ChildEdgeNumbering& parentEdges, const ParallelFor& parallelFor = SerialFor);
}

#endif
