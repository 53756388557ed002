#include "SubDSmoothGrandchild.h"
#include "SubDCatmullClarkRules.h"
#include "SubDLoopRules.h"
#include "SubDPrimalSplitView.h"

namespace subd
{
namespace
{
// Room for the faces and edges around a point of the level between, on the stack: the
// grandparent's vertices may have at most this many edges.
constexpr Index MaxRing = 64;

// What both schemes' rows share: the level between P read from the grandparent, and the
// rows' interface (SubDRowWriting.h), every row a smooth one.
template <typename View, typename Derived>
class SmoothRowWriter
{
public:
  SmoothRowWriter(const Level& grandparent, const ParallelFor& parallelFor)
    : Between(grandparent.Topology, parallelFor)
  {
  }
  Index GetNumParents() const { return this->Between.GetNumVertices(); }
  Index GetMaxRowSize() const { return 1 + 2 * this->Between.GetMaxValence(); }
  Index WriteRow(Index row, Index* sources, double* weights) const
  {
    RowEntries entries{ sources, weights, this->GetNumParents() };
    static_cast<const Derived*>(this)->VisitSmoothRow(row, entries);
    return entries.Size;
  }
  const View& GetBetween() const { return this->Between; }

protected:
  // A point on no face (a point of the input that no face uses) stays where it is, as
  // PlanVertexRule plans it: a corner.
  template <typename Entries>
  static bool IsolatedVertexRow(Index v, Entries& entries)
  {
    entries.Parent(v, 1.0);
    return true;
  }

  View Between;
};

// CatmullClarkRowWriter's smooth rows over the quad split of the grandparent.
class CatmullClarkGrandchildRows : public SmoothRowWriter<QuadSplitView, CatmullClarkGrandchildRows>
{
public:
  using SmoothRowWriter::SmoothRowWriter;
  Index GetNumRows() const { return this->Number.VertexPoint(this->GetNumParents()); }
  std::vector<Index> GetBlockEnds() const
  {
    return { this->Number.EdgePoint(0), this->Number.VertexPoint(0), this->GetNumRows() };
  }
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const
  {
    if (row < this->Number.NumFaces)
    {
      Index corners[4];
      this->Between.GetFaceCorners(row, corners);
      CentroidMask(IndexSpan{ corners, 4 }, entries);
      return true;
    }
    if (row < this->Number.VertexPoint(0))
    {
      Index ends[2], faces[2];
      this->Between.GetEdge(row - this->Number.NumFaces, ends, faces);
      const Index facePoints[2] = { this->Number.FacePoint(faces[0]), this->Number.FacePoint(faces[1]) };
      CatmullClarkSmoothEdgeMask(ends, facePoints, entries);
      return true;
    }
    const Index v = row - this->Number.VertexPoint(0);
    Index faces[MaxRing], corners[MaxRing], edges[MaxRing], numFaces, numEdges;
    this->Between.GetPointRelations(v, faces, corners, edges, numFaces, numEdges);
    if (numFaces == 0)
    {
      return IsolatedVertexRow(v, entries);
    }
    CatmullClarkSmoothVertexMask(
      v, numEdges, numFaces, [&](Index i) { return this->Number.EdgePoint(edges[i]); },
      [&](Index i) { return this->Number.FacePoint(faces[i]); }, entries);
    return true;
  }

private:
  QuadSplitNumbering Number{ this->Between.GetNumFaces(), this->Between.GetNumEdges() };
};

// LoopRowWriter's smooth rows over the triangle split of the grandparent.
class LoopGrandchildRows : public SmoothRowWriter<TriangleSplitView, LoopGrandchildRows>
{
public:
  using SmoothRowWriter::SmoothRowWriter;
  Index GetNumRows() const { return this->Number.VertexPoint(this->GetNumParents()); }
  std::vector<Index> GetBlockEnds() const { return { this->Number.VertexPoint(0), this->GetNumRows() }; }
  template <typename Entries>
  bool VisitSmoothRow(Index row, Entries& entries) const
  {
    if (row < this->Number.VertexPoint(0))
    {
      Index ends[2], faces[2], opposite[2];
      this->Between.GetEdge(row, ends, faces);
      for (int k = 0; k < 2; ++k)
      {
        Index corners[3];
        this->Between.GetFaceCorners(faces[k], corners);
        opposite[k] = MeshTopology::ThirdVertex(corners, ends[0], ends[1]);
      }
      LoopSmoothEdgeMask(ends, opposite, entries);
      return true;
    }
    const Index v = row - this->Number.VertexPoint(0);
    Index edges[MaxRing], numFaces, numEdges;
    this->Between.GetPointRelations(v, nullptr, nullptr, edges, numFaces, numEdges);
    if (numFaces == 0)
    {
      return IsolatedVertexRow(v, entries);
    }
    LoopSmoothVertexMask(
      v, numEdges, this->Beta(numEdges), [&](Index i) { return this->Number.EdgePoint(edges[i]); }, entries);
    return true;
  }

private:
  TriangleSplitNumbering Number{ this->Between.GetNumEdges() };
  LoopBetas Beta;
};

// The finest level: the faces of the level between split again, each grandparent face's
// sixteen grandchildren in order, so that they keep the grandparent's holes and origins
// (Level::FaceTagShift 4).
template <typename View>
Level SplitTwice(const Level& grandparent, const View& between, Index numPoints, const ParallelFor& parallelFor)
{
  const Index numFaces = 4 * between.GetNumFaces();
  const size_t faceSize = View::FaceSize;
  IndexArray offsets(static_cast<size_t>(numFaces) + 1);
  IndexArray vertices(static_cast<size_t>(numFaces) * faceSize);
  parallelFor(0, between.GetNumFaces(), [&](Index begin, Index end) {
    for (Index p = begin; p < end; ++p)
    {
      between.WriteSplitFace(p, vertices.data() + 4 * faceSize * static_cast<size_t>(p));
      for (Index j = 0; j < 4; ++j)
      {
        offsets[4 * p + j] = static_cast<Index>(faceSize) * (4 * p + j);
      }
    }
  });
  offsets[numFaces] = static_cast<Index>(faceSize) * numFaces;
  Level finest;
  finest.Depth = grandparent.Depth + 2;
  finest.Creasing = grandparent.Creasing;
  finest.FaceIsHole = grandparent.FaceIsHole;
  finest.FaceOrigin = grandparent.FaceOrigin;
  finest.FaceTagShift = 4;
  finest.Topology = MeshTopology::BuildFacesOnly(numPoints, std::move(offsets), std::move(vertices));
  return finest;
}

template <typename Writer>
SmoothGrandchild MakeWith(std::shared_ptr<const Level> grandparent, const ParallelFor& parallelFor)
{
  auto rows = std::make_shared<const WrittenRows<Writer>>(grandparent, parallelFor);
  SmoothGrandchild result;
  result.Finest = SplitTwice(*grandparent, rows->GetWriter().GetBetween(), rows->GetNumRows(), parallelFor);
  result.Rows = std::move(rows);
  return result;
}

}

bool HasSmoothGrandchild(const Scheme& scheme, const Level& grandparent)
{
  const MeshTopology& topology = grandparent.Topology;
  const bool catmullClark = dynamic_cast<const CatmullClarkScheme*>(&scheme) != nullptr;
  const bool loop = dynamic_cast<const LoopScheme*>(&scheme) != nullptr;
  const bool viewed = (catmullClark && QuadSplitView::Reads(topology)) || (loop && TriangleSplitView::Reads(topology));
  return viewed && topology.HasEdges() && grandparent.FaceTagShift == 0 && topology.GetMaxValence() <= MaxRing &&
    !grandparent.HasSharpFeatures() && !grandparent.HasHoles();
}

SmoothGrandchild MakeSmoothGrandchild(const Scheme& scheme, std::shared_ptr<const Level> grandparent)
{
  if (dynamic_cast<const CatmullClarkScheme*>(&scheme))
  {
    return MakeWith<CatmullClarkGrandchildRows>(std::move(grandparent), scheme.GetParallelFor());
  }
  return MakeWith<LoopGrandchildRows>(std::move(grandparent), scheme.GetParallelFor());
}

bool BuildLevelBetween(const Scheme& scheme, Hierarchy& hierarchy)
{
  if (hierarchy.Stencils.empty())
  {
    return false;
  }
  const RowSource* rows = hierarchy.Stencils.back().GetSource();
  const Level* grandparent = nullptr;
  if (const auto* catmullClark = dynamic_cast<const WrittenRows<CatmullClarkGrandchildRows>*>(rows))
  {
    grandparent = &catmullClark->GetParent();
  }
  else if (const auto* loop = dynamic_cast<const WrittenRows<LoopGrandchildRows>*>(rows))
  {
    grandparent = &loop->GetParent();
  }
  if (!grandparent)
  {
    return false;
  }
  auto between = std::make_shared<const Level>(scheme.Split(*grandparent, ChildTopology::Full));
  hierarchy.Stencils.back() = StencilTable::FromSource(scheme.MakeRowSource(std::move(between)));
  return true;
}
}
