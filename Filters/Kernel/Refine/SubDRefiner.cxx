#include "SubDRefiner.h"
#include "SubDSmoothGrandchild.h"

namespace subd
{
bool Refine(const Scheme& scheme, Level base, int levels, Hierarchy& out, const ProgressCallback& progress,
  ChildTopology finest, LevelRows levelRows)
{
  out.NumBasePoints = base.Topology.GetNumVertices();
  out.Stencils.clear();
  out.Stencils.reserve(static_cast<size_t>(levels > 0 ? levels : 0));
  Level current = std::move(base);
  for (int l = 0; l < levels; ++l)
  {
    const ChildTopology depth = l + 1 == levels ? finest : ChildTopology::Full;
    // Written rows keep the level they read; stored ones are made with the split.
    auto parent = std::make_shared<const Level>(std::move(current));
    std::shared_ptr<const RowSource> rows =
      levelRows == LevelRows::Written ? scheme.MakeRowSource(parent) : nullptr;
    // The last two levels of a smooth closed mesh at once: the level between, the largest
    // a faces-only refinement would keep, is never built (SubDSmoothGrandchild.h).
    if (rows && l + 2 == levels && finest == ChildTopology::FacesOnly && HasSmoothGrandchild(scheme, *parent))
    {
      SmoothGrandchild lastTwo = MakeSmoothGrandchild(scheme, parent);
      out.Stencils.push_back(StencilTable::FromSource(std::move(rows)));
      out.Stencils.push_back(StencilTable::FromSource(std::move(lastTwo.Rows)));
      current = std::move(lastTwo.Finest);
      ++l;
    }
    else if (rows)
    {
      current = scheme.Split(*parent, depth);
      out.Stencils.push_back(StencilTable::FromSource(std::move(rows)));
    }
    else
    {
      LevelRefinement refinement = scheme.RefineLevel(*parent, depth);
      out.Stencils.push_back(std::move(refinement.Stencils));
      current = std::move(refinement.Child);
    }
    if (progress && !progress(static_cast<double>(l + 1) / levels))
    {
      out.Finest = std::move(current);
      return false;
    }
  }
  out.Finest = std::move(current);
  return true;
}
}
