// SubD kernel: the weights that compute one level's points from the level above.
//
// One row per child point, in compressed-row form (offsets, source indices, weights in
// double precision). A source index below GetNumParents() names a parent point; an index
// s >= GetNumParents() names the child point s - GetNumParents() computed by an earlier row.
// Letting rows reuse earlier children (e.g. Catmull-Clark edge and vertex points reuse the
// face points) keeps rows short, as the schemes are written in the literature.
//
// Rows are grouped into consecutive blocks: a row only reads children of earlier blocks, so
// all rows of a block can be evaluated in parallel once the previous blocks are done.
#ifndef SubDStencilTable_h
#define SubDStencilTable_h

#include "SubDTypes.h"
#include <vector>

namespace subd
{
class SUBDKERNEL_EXPORT StencilTable
{
public:
  StencilTable() = default;
  explicit StencilTable(Index numParents)
    : NumParents(numParents)
  {
  }

  Index GetNumParents() const { return NumParents; }
  Index GetNumRows() const { return static_cast<Index>(Offsets.size()) - 1; }
  size_t GetNumEntries() const { return Sources.size(); }

  IndexSpan GetSources(Index row) const
  {
    return IndexSpan{ Sources.data() + Offsets[row], Offsets[row + 1] - Offsets[row] };
  }
  const double* GetWeights(Index row) const { return Weights.data() + Offsets[row]; }

  /// Block b holds rows [GetBlockBegin(b), GetBlockEnd(b)).
  Index GetNumBlocks() const { return static_cast<Index>(BlockEnds.size()); }
  Index GetBlockBegin(Index b) const { return b == 0 ? 0 : BlockEnds[b - 1]; }
  Index GetBlockEnd(Index b) const { return BlockEnds[b]; }

  /// Appending rows (builders). Rows are sized first, then filled, so building can be split
  /// among threads: ReserveRows sets the row count, SetRowSize each size, FinalizeSizes the
  /// offsets; then SetEntry fills every row.
  void ReserveRows(Index numRows) { Offsets.assign(static_cast<size_t>(numRows) + 1, 0); }
  void SetRowSize(Index row, Index size) { Offsets[row + 1] = size; }
  void FinalizeSizes();
  Index* GetMutableSources(Index row) { return Sources.data() + Offsets[row]; }
  double* GetMutableWeights(Index row) { return Weights.data() + Offsets[row]; }
  /// Ends the current block at `rowEnd` (exclusive).
  void EndBlock(Index rowEnd) { BlockEnds.push_back(rowEnd); }

  /// Sum of the weights of a row (1 for an affine-invariant scheme).
  double GetRowSum(Index row) const;

  /// Evaluates rows [begin, end) for `components` interleaved values per point:
  /// child[r] = sum_k w_k * source_k. Sources name parents or earlier children (see above).
  template <typename T>
  void ApplyRows(const T* parents, T* children, int components, Index begin, Index end) const;

  /// Evaluates every row, block after block (single-threaded convenience).
  template <typename T>
  void Apply(const T* parents, T* children, int components) const
  {
    for (Index b = 0; b < this->GetNumBlocks(); ++b)
    {
      this->ApplyRows(parents, children, components, this->GetBlockBegin(b), this->GetBlockEnd(b));
    }
  }

private:
  Index NumParents = 0;
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> Sources;
  std::vector<double> Weights;
  std::vector<Index> BlockEnds;
};

/// Rows under construction, in compressed form, each a sum of weighted sources merged as they
/// come (masks composed from other masks: limit and tangent rows, curve levels).
struct SUBDKERNEL_EXPORT StencilRows
{
  std::vector<Index> Offsets{ 0 };
  std::vector<Index> Sources;
  std::vector<double> Weights;

  Index GetNumRows() const { return static_cast<Index>(Offsets.size()) - 1; }
  void Clear();
  /// Adds w * p_source to the current row (merging a source already in it).
  void Add(Index source, double w);
  void EndRow() { Offsets.push_back(static_cast<Index>(Sources.size())); }
  /// Appends rows [begin, end) of `local`, whose sources are indices into `ids`, as rows over
  /// ids[source] (a polygon's local rows in a level's numbering).
  void AppendRenumbered(const StencilRows& local, Index begin, Index end, const Index* ids);
  /// Adds scale * (row `row` of `table`) to the current row, with the table's references to
  /// its own earlier rows expanded, so that the sources are the table's parents.
  void AddRow(const StencilTable& table, Index row, double scale);
  /// The rows as one block of a stencil table over `numParents` points.
  StencilTable ToStencilTable(Index numParents) const;
};

template <typename T>
void StencilTable::ApplyRows(
  const T* parents, T* children, int components, Index begin, Index end) const
{
  constexpr int MaxStackComponents = 16;
  double stackSum[MaxStackComponents];
  std::vector<double> heapSum;
  double* sum = stackSum;
  if (components > MaxStackComponents)
  {
    heapSum.resize(static_cast<size_t>(components));
    sum = heapSum.data();
  }
  const Index numParents = this->NumParents;
  for (Index row = begin; row < end; ++row)
  {
    for (int c = 0; c < components; ++c)
    {
      sum[c] = 0.0;
    }
    const Index first = this->Offsets[row], last = this->Offsets[row + 1];
    for (Index k = first; k < last; ++k)
    {
      const Index s = this->Sources[k];
      const double w = this->Weights[k];
      const T* src = s < numParents ? parents + static_cast<size_t>(s) * components
                                    : children + static_cast<size_t>(s - numParents) * components;
      for (int c = 0; c < components; ++c)
      {
        sum[c] += w * static_cast<double>(src[c]);
      }
    }
    T* dst = children + static_cast<size_t>(row) * components;
    for (int c = 0; c < components; ++c)
    {
      dst[c] = static_cast<T>(sum[c]);
    }
  }
}
}

#endif
