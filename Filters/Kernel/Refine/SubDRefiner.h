// SubD kernel: refines a base level N times with a scheme and evaluates per-point data.
//
// Refinement (topology + stencils) depends only on the connectivity and tags; evaluation
// applies the stored stencils to any per-point data. Keeping them apart is what lets a
// caller refine once and re-evaluate cheaply when only point positions change.
#ifndef SubDRefiner_h
#define SubDRefiner_h

#include "SubDParallel.h"
#include "SubDScheme.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace subd
{
/// Reports progress in [0, 1]; returning false asks the work to stop.
using ProgressCallback = std::function<bool(double)>;

/// Room for the values of the levels between the base and the finest. A caller that
/// evaluates again and again (re-applied stencils when points move) keeps one: reused, its
/// pages are not faulted in anew each time. Sized to the largest evaluation it served, but
/// for the level before the finest's parent, which a first evaluation frees (Evaluate).
template <typename T>
struct EvaluationScratch
{
  LevelArray<T> Levels[2];
  bool IsEmpty() const { return this->Levels[0].empty() && this->Levels[1].empty(); }
};

struct SUBDKERNEL_EXPORT Hierarchy
{
  Index NumBasePoints = 0;
  /// One per level, level 0 -> 1 first; a caller may append tables that map the finest
  /// points to as many points (the limit projection), which Evaluate then applies too.
  std::vector<StencilTable> Stencils;
  Level Finest; ///< the last level: its faces, holes and origins (edges: see Refine)

  int GetNumStencilTables() const { return static_cast<int>(Stencils.size()); }
  /// The points the tables make (curve hierarchies have tables but no Finest level).
  Index GetNumFinestPoints() const
  {
    return Stencils.empty() ? Finest.Topology.GetNumVertices() : Stencils.back().GetNumRows();
  }

  Index GetNumFinestFaces() const { return this->Finest.Topology.GetNumFaces(); }

  /// Applies every level's stencils to `components` values per base point; `finest` receives
  /// GetNumFinestPoints() * components values. T is float or double (accumulation is in
  /// double either way). Returns false when progress asked to stop. `numTables` (if not
  /// negative) applies only the first tables (the levels, without an appended limit table).
  /// `scratch`, if given, holds the intermediate levels (else they are allocated here).
  template <typename T>
  bool Evaluate(const T* base, int components, T* finest, const ParallelFor& parallelFor = SerialFor,
    const ProgressCallback& progress = nullptr, int numTables = -1, EvaluationScratch<T>* scratch = nullptr) const;
};

/// How each level's stencils are kept.
enum class LevelRows
{
  Stored,  ///< a StencilTable per level (its rows can be inspected)
  Written, ///< written as they are applied, from the level above, where the scheme can
           ///< (Scheme::MakeRowSource): a fraction of the memory and time of storing them,
           ///< and applied in parallel where building a table is serial. Each level's
           ///< topology is then kept by its rows.
};

/// Refines `base` `levels` times: per level, the scheme's split, then its rows. The finest
/// level has faces only unless `finest` asks for its full topology and tags (to read its
/// sharp edges, evaluate its limit), OpenSubdiv's fullTopologyInLastLevel. Returns false if progress
/// asked to stop (out is then incomplete).
SUBDKERNEL_EXPORT bool Refine(const Scheme& scheme, Level base, int levels, Hierarchy& out,
  const ProgressCallback& progress = nullptr, ChildTopology finest = ChildTopology::FacesOnly,
  LevelRows levelRows = LevelRows::Stored);

template <typename T>
bool Hierarchy::Evaluate(const T* base, int components, T* finest, const ParallelFor& parallelFor,
  const ProgressCallback& progress, int numTables, EvaluationScratch<T>* scratch) const
{
  const int levels = numTables < 0 ? this->GetNumStencilTables() : std::min(numTables, this->GetNumStencilTables());
  if (levels == 0)
  {
    std::copy(base, base + static_cast<size_t>(this->NumBasePoints) * components, finest);
    return true;
  }
  EvaluationScratch<T> ownScratch;
  EvaluationScratch<T>& use = scratch ? *scratch : ownScratch;
  // A scratch that starts empty serves a first evaluation (a refinement's, or one not
  // reused): the level before the finest's parent is freed before the finest level is
  // written, the peak of the evaluation. A reused scratch keeps both for the next one.
  const bool firstUse = use.IsEmpty();
  LevelArray<T>* room = use.Levels; // written before read
  const T* parents = base;
  for (int l = 0; l < levels; ++l)
  {
    const StencilTable& table = this->Stencils[l];
    T* children = finest;
    LevelArray<T>& values = room[l % 2]; // level l - 1's values, if any: read no more
    const size_t needed = static_cast<size_t>(table.GetNumRows()) * components;
    if (l + 1 < levels)
    {
      if (values.size() < needed)
      {
        LevelArray<T>().swap(values); // grown without copying values that are overwritten
        values.resize(needed);
      }
      children = values.data();
    }
    else if (firstUse)
    {
      LevelArray<T>().swap(values);
    }
    const Index blocks = table.GetNumBlocks();
    for (Index b = 0; b < blocks; ++b)
    {
      parallelFor(table.GetBlockBegin(b), table.GetBlockEnd(b),
        [&](Index begin, Index end) { table.ApplyRows(parents, children, components, begin, end); });
      if (progress && !progress((l + static_cast<double>(b + 1) / blocks) / levels))
      {
        return false;
      }
    }
    parents = children;
  }
  return true;
}
}

#endif
