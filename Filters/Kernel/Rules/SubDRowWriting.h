// SubD kernel: stencil rows written one at a time by a scheme's row writer, then either stored
// in a StencilTable (WriteStencilTable) or applied as they are written (WrittenRows).
//
// A row writer is a small class with
//   Index GetNumParents() const;            // points of the parent level
//   Index GetNumRows() const;               // child points
//   std::vector<Index> GetBlockEnds() const; // as StencilTable's blocks
//   Index GetMaxRowSize() const;            // room WriteRow uses in its buffers (>= any row)
//   Index WriteRow(Index row, Index* sources, double* weights) const; // returns the size
// and optionally
//   template <typename Entries>             // the row of a smooth point, if `row` is one
//   bool VisitSmoothRow(Index row, Entries& entries) const;
//   template <typename T>                   // asks for what that row will read
//   void PrefetchRow(Index row, const T* parents, const T* children) const;
// A scheme's masks are functions that give a row's entries to an Entries sink: RowEntries
// writes them into a row's arrays (a stored table, or a row WriteRow writes), PointEntries
// sums the weighted points straight away, in the same order, so that both give the same
// bits, and PrefetchEntries asks for the points ahead (for a writer without PrefetchRow). VisitSmoothRow calls them for the rows that need no planning (most of a mesh: away
// from creases and boundaries), and WriteRow calls VisitSmoothRow for those rows too: each
// weight is written once. WrittenRows sums the smooth rows through VisitSmoothRow and writes
// the others.
// Writing a row costs little next to reading its sources: its weights come from the
// topology around the row's point, which is small and read in order. Applying rows as they
// are written therefore spares storing the finest level's table, which is several times the
// size of the points it makes (12 bytes per entry, about six entries per point).
#ifndef SubDRowWriting_h
#define SubDRowWriting_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

#include <memory>
#include <type_traits>
#include <vector>

namespace subd
{
/// A mask's entries written into a row: a point of the parent level is source v, a point of
/// the level being made (written by an earlier block of rows) source NumParents + p.
struct RowEntries
{
  Index* Sources;
  double* Weights;
  Index NumParents;
  Index Size = 0;
  void Parent(Index v, double w)
  {
    this->Sources[this->Size] = v;
    this->Weights[this->Size++] = w;
  }
  void Child(Index p, double w) { this->Parent(this->NumParents + p, w); }
};

/// A mask's entries summed as ApplyRow sums a written row (three components, in double).
template <typename T>
struct PointEntries
{
  const T* Parents;
  const T* Children;
  PointSum Sum;
  void Parent(Index v, double w) { this->Sum.Add(w, this->Parents + 3 * static_cast<size_t>(v)); }
  void Child(Index p, double w) { this->Sum.Add(w, this->Children + 3 * static_cast<size_t>(p)); }
};

/// A mask's entries asked for ahead of reading them (PrefetchPoint): a row's points, many
/// rows before it is summed, so that they arrive while the rows between are.
template <typename T>
struct PrefetchEntries
{
  const T* Parents;
  const T* Children;
  void Parent(Index v, double) { PrefetchPoint(this->Parents + 3 * static_cast<size_t>(v)); }
  void Child(Index p, double) { PrefetchPoint(this->Children + 3 * static_cast<size_t>(p)); }
};

/// The masks several schemes share: a face's centroid (Catmull-Clark's face points, the
/// bilinear scheme's, sqrt(3)'s), an edge's midpoint (the crease rule, the linear schemes',
/// the midpoint scheme's), a copy (interpolating schemes' vertex points, corners).
template <typename Entries>
void CentroidMask(IndexSpan corners, Entries& entries)
{
  const double w = 1.0 / corners.size();
  for (Index v : corners)
  {
    entries.Parent(v, w);
  }
}

template <typename Entries>
void MidpointMask(const Index* ends, Entries& entries)
{
  entries.Parent(ends[0], 0.5);
  entries.Parent(ends[1], 0.5);
}

template <typename Entries>
void CopyMask(Index v, Entries& entries)
{
  entries.Parent(v, 1.0);
}

/// Whether a row writer has VisitSmoothRow(row, entries) (see above).
template <typename Writer, typename = void>
struct HasVisitSmoothRow : std::false_type
{
};
template <typename Writer>
struct HasVisitSmoothRow<Writer,
  std::void_t<decltype(std::declval<const Writer&>().VisitSmoothRow(Index(), std::declval<RowEntries&>()))>>
  : std::true_type
{
};

/// The rows of `writer` in a table; `expectedEntries` (a guess) spares reallocations.
template <typename Writer>
StencilTable WriteStencilTable(const Writer& writer, size_t expectedEntries)
{
  StencilTable table(writer.GetNumParents());
  const Index numRows = writer.GetNumRows();
  table.Reserve(numRows, expectedEntries);
  std::vector<Index> sources(static_cast<size_t>(writer.GetMaxRowSize()));
  std::vector<double> weights(sources.size());
  for (Index row = 0; row < numRows; ++row)
  {
    const Index size = writer.WriteRow(row, sources.data(), weights.data());
    table.AppendRow(sources.data(), weights.data(), size);
  }
  for (Index end : writer.GetBlockEnds())
  {
    table.EndBlock(end);
  }
  return table;
}

/// The rows of `writer` in a table, written by `parallelFor` (each row by one task, so the
/// same table for any number of threads): sized in one pass, written in place in another.
template <typename Writer>
StencilTable WriteStencilTable(const Writer& writer, const ParallelFor& parallelFor)
{
  StencilTable table(writer.GetNumParents());
  const Index numRows = writer.GetNumRows();
  table.ReserveRows(numRows);
  parallelFor(0, numRows, [&](Index begin, Index end) {
    std::vector<Index> sources(static_cast<size_t>(writer.GetMaxRowSize()));
    std::vector<double> weights(sources.size());
    for (Index row = begin; row < end; ++row)
    {
      table.SetRowSize(row, writer.WriteRow(row, sources.data(), weights.data()));
    }
  });
  table.FinalizeSizesUnfilled();
  parallelFor(0, numRows, [&](Index begin, Index end) {
    for (Index row = begin; row < end; ++row)
    {
      writer.WriteRow(row, table.GetMutableSources(row), table.GetMutableWeights(row));
    }
  });
  for (Index end : writer.GetBlockEnds())
  {
    table.EndBlock(end);
  }
  return table;
}

/// Whether a row writer has PrefetchRow(row, parents, children): a hint that asks for the
/// points row `row` reads, so that they arrive while the rows before it are evaluated.
template <typename Writer, typename T, typename = void>
struct HasPrefetchRow : std::false_type
{
};
template <typename Writer, typename T>
struct HasPrefetchRow<Writer, T,
  std::void_t<decltype(std::declval<const Writer&>().PrefetchRow(Index(), static_cast<const T*>(nullptr),
    static_cast<const T*>(nullptr)))>> : std::true_type
{
};

/// The rows of a Writer over `parent`, applied as they are written. Keeps the parent level
/// alive: it is what the rows are written from.
template <typename Writer>
class WrittenRows final : public RowSourceWithApply<WrittenRows<Writer>>
{
  friend class RowSourceWithApply<WrittenRows<Writer>>;

public:
  /// `writerOptions` follow the parent level in the Writer's constructor.
  template <typename... WriterOptions>
  explicit WrittenRows(std::shared_ptr<const Level> parent, WriterOptions... writerOptions)
    : Parent(std::move(parent))
    , RowWriter(*this->Parent, writerOptions...)
  {
  }
  Index GetNumParents() const override { return this->RowWriter.GetNumParents(); }
  Index GetNumRows() const override { return this->RowWriter.GetNumRows(); }
  std::vector<Index> GetBlockEnds() const override { return this->RowWriter.GetBlockEnds(); }
  const Writer& GetWriter() const { return this->RowWriter; }
  const Level& GetParent() const { return *this->Parent; }

private:
  template <typename T>
  void Apply(const T* parents, T* children, int components, Index begin, Index end) const
  {
    std::vector<Index> sources(static_cast<size_t>(this->RowWriter.GetMaxRowSize()));
    std::vector<double> weights(sources.size());
    std::vector<double> sum(static_cast<size_t>(components));
    const Index numParents = this->RowWriter.GetNumParents();
    for (Index row = begin; row < end; ++row)
    {
      if (components == 3 && end - row > PrefetchDistance) // no overflow near 2^31 rows
      {
        if constexpr (HasPrefetchRow<Writer, T>::value)
        {
          this->RowWriter.PrefetchRow(row + PrefetchDistance, parents, children);
        }
        else if constexpr (HasVisitSmoothRow<Writer>::value)
        {
          PrefetchEntries<T> ahead{ parents, children };
          this->RowWriter.VisitSmoothRow(row + PrefetchDistance, ahead);
        }
      }
      T* dst = children + static_cast<size_t>(row) * components;
      if constexpr (HasVisitSmoothRow<Writer>::value)
      {
        PointEntries<T> entries{ parents, children, {} };
        if (components == 3 && this->RowWriter.VisitSmoothRow(row, entries))
        {
          entries.Sum.Store(dst);
          continue;
        }
      }
      const Index size = this->RowWriter.WriteRow(row, sources.data(), weights.data());
      ApplyRow(sources.data(), weights.data(), size, numParents, parents, children, components, sum.data(), dst);
    }
  }

  std::shared_ptr<const Level> Parent;
  Writer RowWriter;
};
}

#endif
