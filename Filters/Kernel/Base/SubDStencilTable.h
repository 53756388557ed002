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
#include <memory>
#include <type_traits>
#include <vector>

namespace subd
{
/// Rows that are written when they are applied instead of being stored (SubDRowWriting.h):
/// a level's stencils cost as much memory as its points several times over, so the finest
/// level of a refinement, the largest by far, evaluates straight from its parent's topology.
class SUBDKERNEL_EXPORT RowSource
{
public:
  virtual ~RowSource() = default;
  virtual Index GetNumParents() const = 0;
  virtual Index GetNumRows() const = 0;
  /// The rows' blocks, as in StencilTable.
  virtual std::vector<Index> GetBlockEnds() const = 0;
  /// As StencilTable::ApplyRows.
  virtual void ApplyRows(const double* parents, double* children, int components, Index begin, Index end) const = 0;
  virtual void ApplyRows(const float* parents, float* children, int components, Index begin, Index end) const = 0;
};

/// A RowSource whose Derived applies its rows with one template,
///   template <typename T> void Apply(const T* parents, T* children, int components, Index begin, Index end) const;
/// for both precisions.
template <typename Derived>
class RowSourceWithApply : public RowSource
{
public:
  void ApplyRows(const double* parents, double* children, int components, Index begin, Index end) const override
  {
    static_cast<const Derived*>(this)->Apply(parents, children, components, begin, end);
  }
  void ApplyRows(const float* parents, float* children, int components, Index begin, Index end) const override
  {
    static_cast<const Derived*>(this)->Apply(parents, children, components, begin, end);
  }
};

class SUBDKERNEL_EXPORT StencilTable
{
public:
  StencilTable() = default;
  explicit StencilTable(Index numParents)
    : NumParents(numParents)
  {
  }
  /// A table whose rows `source` writes when applied: it stores no rows, so GetSources,
  /// GetWeights and GetRowSum must not be called on it (IsStored() is false).
  static StencilTable FromSource(std::shared_ptr<const RowSource> source);
  bool IsStored() const { return !this->Source; }
  /// What writes the rows of a table made FromSource (else null).
  const RowSource* GetSource() const { return this->Source.get(); }

  Index GetNumParents() const { return NumParents; }
  Index GetNumRows() const
  {
    return this->Source ? this->Source->GetNumRows() : static_cast<Index>(Offsets.size()) - 1;
  }
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
  /// The same without filling the entries: for writers that write every entry of every row
  /// (in parallel, so that each page is first touched by the thread that fills it).
  void FinalizeSizesUnfilled();
  Index* GetMutableSources(Index row) { return Sources.data() + Offsets[row]; }
  double* GetMutableWeights(Index row) { return Weights.data() + Offsets[row]; }
  /// Ends the current block at `rowEnd` (exclusive).
  void EndBlock(Index rowEnd) { BlockEnds.push_back(rowEnd); }
  /// Appends a row of `size` entries (builders that write rows one after the other).
  void AppendRow(const Index* sources, const double* weights, Index size)
  {
    this->Sources.insert(this->Sources.end(), sources, sources + size);
    this->Weights.insert(this->Weights.end(), weights, weights + size);
    this->Offsets.push_back(static_cast<Index>(this->Sources.size()));
  }
  /// Reserves room for rows and entries before AppendRow.
  void Reserve(Index numRows, size_t numEntries)
  {
    this->Offsets.reserve(static_cast<size_t>(numRows) + 1);
    this->Sources.reserve(numEntries);
    this->Weights.reserve(numEntries);
  }

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
  std::shared_ptr<const RowSource> Source;
  std::vector<Index> Offsets{ 0 };
  LevelArray<Index> Sources;
  LevelArray<double> Weights;
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

/// A point (three values) summed in double as ApplyRow sums it: adding the same weighted
/// points in the same order gives the same bits, which lets a row writer evaluate a row it
/// knows in closed form without writing it (SubDRowWriting.h).
struct PointSum
{
  double X = 0.0, Y = 0.0, Z = 0.0;
  template <typename T>
  void Add(double w, const T* p)
  {
    this->X += w * static_cast<double>(p[0]);
    this->Y += w * static_cast<double>(p[1]);
    this->Z += w * static_cast<double>(p[2]);
  }
  template <typename T>
  void Store(T* dst) const
  {
    dst[0] = static_cast<T>(this->X);
    dst[1] = static_cast<T>(this->Y);
    dst[2] = static_cast<T>(this->Z);
  }
};

/// How many rows ahead a row writer's PrefetchRow asks (SubDRowWriting.h): enough rows to cover a memory access's latency
/// (Catmull-Clark re-applied at level 4, one thread: 16 and 32 alike, 1.25x faster than
/// without; 8 less).
constexpr Index PrefetchDistance = 32;

/// Asks for the three components at `point` ahead of reading them: both ends, since a point
/// of three doubles straddles two 64-byte cache lines one time in four.
template <typename T>
inline void PrefetchPoint(const T* point) noexcept
{
  PrefetchForRead(point);
  PrefetchForRead(point + 2);
}

/// Evaluates one row: dst = sum_k weights[k] * (value of sources[k]), a source below
/// numParents naming a parent, one above a child (see StencilTable). `sum` is scratch for
/// `components` doubles. Three components (points) take an unrolled path.
template <typename T>
inline void ApplyRow(const Index* sources, const double* weights, Index size, Index numParents, const T* parents,
  const T* children, int components, double* sum, T* dst)
{
  auto valuesOf = [&](Index s) {
    return s < numParents ? parents + static_cast<size_t>(s) * components
                          : children + static_cast<size_t>(s - numParents) * components;
  };
  if (components == 3)
  {
    PointSum point;
    for (Index k = 0; k < size; ++k)
    {
      point.Add(weights[k], valuesOf(sources[k]));
    }
    point.Store(dst);
    return;
  }
  for (int c = 0; c < components; ++c)
  {
    sum[c] = 0.0;
  }
  for (Index k = 0; k < size; ++k)
  {
    const T* src = valuesOf(sources[k]);
    const double w = weights[k];
    for (int c = 0; c < components; ++c)
    {
      sum[c] += w * static_cast<double>(src[c]);
    }
  }
  for (int c = 0; c < components; ++c)
  {
    dst[c] = static_cast<T>(sum[c]);
  }
}

template <typename T>
void StencilTable::ApplyRows(
  const T* parents, T* children, int components, Index begin, Index end) const
{
  if (this->Source)
  {
    static_assert(std::is_same<T, double>::value || std::is_same<T, float>::value,
      "rows written on demand apply to double or float values");
    this->Source->ApplyRows(parents, children, components, begin, end);
    return;
  }
  // Small tables are applied many times (local refinements of the limit evaluator): no heap
  // allocation unless the values are wide.
  constexpr int MaxStackComponents = 16;
  double stackSum[MaxStackComponents];
  std::vector<double> heapSum;
  double* sum = stackSum;
  if (components > MaxStackComponents)
  {
    heapSum.resize(static_cast<size_t>(components));
    sum = heapSum.data();
  }
  for (Index row = begin; row < end; ++row)
  {
    const Index first = this->Offsets[row];
    ApplyRow(this->Sources.data() + first, this->Weights.data() + first, this->Offsets[row + 1] - first,
      this->NumParents, parents, children, components, sum, children + static_cast<size_t>(row) * components);
  }
}
}

#endif
