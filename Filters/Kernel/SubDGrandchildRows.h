// SubD kernel: the Catmull-Clark, Loop and butterfly rows of the finest level written from
// its grandparent's topology, so that its parent's topology need not be kept.
//
// Rows written as they are applied (SubDRowWriting.h) keep the level they are written from.
// For the finest level that is the largest topology of a refinement (about 170 bytes per
// face): most of the peak memory. But the finest level's parent C is a primal split of its
// own parent P (the quad split, SubDQuadSplit.h, for Catmull-Clark; the triangle split,
// SubDTriangleSplit.h, for Loop), and a primal split's topology is known in closed form from
// its parent's (SubDPrimalSplitShape.h): the corners of every child face, the two faces of a
// half of P's edge (the children of the edge's faces at its vertex), the faces and edges
// around a point of C (those around the face, edge or vertex of P it stands for). So the
// rows of the smooth points (face points everywhere, edge and vertex points away from
// creases and boundaries: nearly all of them) are written from P here, with C's numbering
// and in the order C's own row writer (CatmullClarkRowWriter, LoopRowWriter) writes them,
// which gives the same bits. The other rows are written once from C when the source is
// made, and stored; then C can go.
//
// The price: every evaluation works out each point's neighbourhood again, from arrays read
// out of order, which makes re-applying the rows about 1.5x to 2x slower than from C's
// lists. The faces of the finest level follow from P the same way (SplitTwice).
//
// The modified butterfly (without tension) reads two rings around an edge of C: its two
// triangles, the four across their other edges, and the rings of its ends where one is an
// extraordinary vertex of P (every other point of C, the points of P's edges, has valence
// 6). All of those are children of P's faces around the edge, found the same way; the rings
// of P's extraordinary vertices are ordered once (P is a quarter of C).
//
// The linear rules (bilinear on the quad split, linear triangles on the triangle split) have
// no row that needs C: every row is a centroid, a midpoint or a copy. For them C need not be
// built at all, which makes the finest level both leaner and faster to refine.
#ifndef SubDGrandchildRows_h
#define SubDGrandchildRows_h

#include "SubDButterflyRules.h"
#include "SubDLevel.h"
#include "SubDPrimalSplitShape.h"
#include "SubDStencilTable.h"

#include <memory>
#include <vector>

namespace subd
{
enum class GrandchildScheme
{
  CatmullClark,   ///< on the quad split
  Loop,           ///< on the triangle split
  Butterfly,      ///< the modified butterfly without tension, on the triangle split
  Bilinear,       ///< on the quad split; every row in closed form
  LinearTriangles ///< on the triangle split; every row in closed form
};

/// Whether the scheme's split is the quad split (else the triangle split).
inline bool IsQuadSplit(GrandchildScheme scheme)
{
  return scheme == GrandchildScheme::CatmullClark || scheme == GrandchildScheme::Bilinear;
}

/// Whether every row of the scheme is written from the grandparent alone (linear rules: no
/// crease or boundary rule), so that the level between need not be built at all.
inline bool WritesEveryRowFromGrandparent(GrandchildScheme scheme)
{
  return scheme == GrandchildScheme::Bilinear || scheme == GrandchildScheme::LinearTriangles;
}

/// Whether the scheme's rows read the points of the level between only (no row reads another
/// row of the finest level): one block of rows.
inline bool ReadsParentPointsOnly(GrandchildScheme scheme)
{
  return scheme == GrandchildScheme::Butterfly || WritesEveryRowFromGrandparent(scheme);
}

/// For the butterfly's rows: the interior vertices of the grandparent P with a closed fan of
/// other than 6 faces, each with the edges leaving it in the faces of its fan in order
/// (counter-clockwise): the points of those edges are its ring in the level between; and the
/// face across each edge of each triangle.
struct ButterflyGrandparentTables
{
  IndexArray RingOffsets; // per vertex of P (+ 1); an empty ring for the other vertices
  IndexArray RingEdges;
  ButterflyWeightTable Weights;
  // Per corner i of each triangle of P: 4 h + p for the face h across its edge i, that edge
  // being h's edge p (MakeTriangleFaceAcross): P's own row writer's when it has one.
  std::shared_ptr<const IndexArray> FaceAcross;
};

class SUBDKERNEL_EXPORT GrandchildRows final : public RowSource
{
public:
  /// `parent` must be the scheme's split of *grandparent (SplitQuads or SplitTriangles) with
  /// its full topology; it is read here and not kept. `grandparentRows`, when given, are the
  /// rows written from the grandparent to the parent: tables they hold are shared, not made
  /// again (the butterfly's triangles across P's edges).
  GrandchildRows(GrandchildScheme scheme, std::shared_ptr<const Level> grandparent, const Level& parent,
    const ParallelFor& parallelFor = SerialFor, const RowSource* grandparentRows = nullptr);
  /// Without the parent: for the schemes that WritesEveryRowFromGrandparent, and for the others
  /// when EveryGrandchildRowIsSmooth(scheme, *grandparent) (no row to store).
  GrandchildRows(GrandchildScheme scheme, std::shared_ptr<const Level> grandparent,
    const ParallelFor& parallelFor = SerialFor, const RowSource* grandparentRows = nullptr);

  Index GetNumParents() const override { return this->NumParents; }
  Index GetNumRows() const override { return this->NumRows; }
  std::vector<Index> GetBlockEnds() const override;
  void ApplyRows(const double* parents, double* children, int components, Index begin, Index end) const override;
  void ApplyRows(const float* parents, float* children, int components, Index begin, Index end) const override;

  /// Every row in a stored table (to inspect them).
  StencilTable ToStencilTable() const;
  const Level& GetGrandparent() const { return *this->Grandparent; }
  /// How the parent's edges are numbered (for SplitTwice).
  const ChildEdgeNumbering& GetParentEdgeNumbering() const { return this->ParentEdges; }
  /// The rows stored because they are not smooth.
  Index GetNumStoredRows() const { return static_cast<Index>(this->StoredRows.size()); }

private:
  template <typename Emit>
  void WriteRows(Index begin, Index end, Index* buffers, double* weights, Emit&& emit) const;
  template <typename Rules, typename Emit>
  void WriteRowsWith(Index begin, Index end, Index* buffers, double* weights, Emit&& emit) const;
  template <typename T>
  void Apply(const T* parents, T* children, int components, Index begin, Index end) const;

  GrandchildScheme Scheme;
  std::shared_ptr<const Level> Grandparent;
  ChildEdgeNumbering ParentEdges;
  Index NumParents = 0, NumRows = 0, NumFaceRows = 0;
  Index MaxRowSize = 4;
  std::vector<Index> StoredRows; // sorted; row StoredRows[i] is StoredTable's row i
  StencilTable StoredTable;
  ButterflyGrandparentTables ButterflyTables;
};

/// Whether every row GrandchildRows writes from `grandparent` has a smooth form (no row to
/// store), so that the level between need not be built at all (Refine then skips it for a
/// faces-only finest level with LevelRows::WrittenFromGrandparent or WrittenLean). Always
/// true for the linear rules. For Catmull-Clark and Loop: nothing of `grandparent` is sharp,
/// every edge has two faces, and every vertex as many faces as edges (at least one). The level
/// between then has the same, which is what its row writer's IsSmoothRow asks of every row:
/// its edges are halves of those edges (the same faces) or lie inside a face (two faces); its
/// points are those vertices (the same counts), edge points (4 faces and edges on the quad
/// split, 6 on the triangle split) and face points (as many of each as the face has corners);
/// and its sharpness is inherited, so none stays none. The butterfly asks the same, except
/// that a sharp vertex does not matter (it has no vertex rule) and a non-manifold one does
/// (it has no ring): then every point of the level between has a smooth ring, of valence 6
/// but at P's vertices, which no edge of the level between joins.
SUBDKERNEL_EXPORT bool EveryGrandchildRowIsSmooth(GrandchildScheme scheme, const Level& grandparent);

/// The finest level (faces only) of two splits of `grandparent` by `scheme`'s split, without
/// the level between: the same faces, holes and origins as splitting twice (the first with
/// the full topology, the second faces only), the tags kept per face of the level between
/// (Level::FaceTagShift 2), or of the grandparent when each of its faces has four children
/// (4). `parentEdges` numbers the edges of the level between
/// (GrandchildRows::GetParentEdgeNumbering). SplitTwiceTags and SplitTwiceFaces
/// make its two parts, for a caller that makes the faces later (Hierarchy::MakeFinestFaces).
SUBDKERNEL_EXPORT Level SplitTwice(GrandchildScheme scheme, const Level& grandparent,
  const ChildEdgeNumbering& parentEdges, const ParallelFor& parallelFor = SerialFor);
/// SplitTwice's level without faces: its tags, depth and crease method.
SUBDKERNEL_EXPORT Level SplitTwiceTags(
  GrandchildScheme scheme, const Level& grandparent, const ParallelFor& parallelFor = SerialFor);
/// SplitTwice's faces.
SUBDKERNEL_EXPORT MeshTopology SplitTwiceFaces(GrandchildScheme scheme, const MeshTopology& grandparent,
  const ChildEdgeNumbering& parentEdges, const ParallelFor& parallelFor = SerialFor);
/// The number of SplitTwice's faces.
SUBDKERNEL_EXPORT Index CountSplitTwiceFaces(GrandchildScheme scheme, const MeshTopology& grandparent);
}

#endif
