#include "SubDRefiner.h"
#include "SubDGrandchildRows.h"

namespace subd
{
bool Refine(const Scheme& scheme, Level base, int levels, Hierarchy& out,
  const ProgressCallback& progress, ChildTopology finest, LevelRows levelRows)
{
  out.NumBasePoints = base.Topology.GetNumVertices();
  out.Stencils.clear();
  out.Stencils.reserve(static_cast<size_t>(levels > 0 ? levels : 0));
  out.FinestFaces = LaterFaces();
  Level current = std::move(base);
  std::shared_ptr<Level> grandparent; // current's parent, kept by the rows written from it
  // A faces-only finest level of a scheme that writes it from its grandparent alone (linear
  // rules) comes from its grandparent whenever rows are written, and its parent, the largest
  // level with a topology, is never built.
  const bool finestFromGrandparentAlone =
    levelRows != LevelRows::Stored && finest == ChildTopology::FacesOnly && scheme.RefinesFromGrandparentAlone();
  // The others skip it too where none of its rows needs it, if asked (LowMemory, WrittenLean).
  const bool finestFromGrandparentIfSmooth = finest == ChildTopology::FacesOnly &&
    (levelRows == LevelRows::WrittenFromGrandparent || levelRows == LevelRows::WrittenLean);
  bool parentSkipped = false; // the finest level's parent was not built
  bool splitAloneTrim = false; // current was trimmed to be split alone (LeanChild::SplitAlone)
  // A full finest level is split from a full parent; else the levels between have what the
  // scheme reads of them.
  const ChildTopology between = finest == ChildTopology::FacesOnly ? scheme.GetTopologyBetween() : ChildTopology::Full;
  for (int l = 0; l < levels; ++l)
  {
    const bool last = l + 1 == levels;
    const ChildTopology depth = last ? finest : between;
    bool refined = false;
    // Every other level, ending with the finest, from its grandparent: the largest topology of
    // all, the finest level's parent, need not outlive its step, nor do the ones two, four...
    // levels above it. (The level after one written from its grandparent has no grandparent
    // kept to be written from.)
    const bool everyOther = levelRows == LevelRows::WrittenFromGrandparent && (levels - 1 - l) % 2 == 0;
    if ((everyOther || (last && parentSkipped)) && grandparent)
    {
      StencilTable rows;
      Level child;
      // The last rows pushed are the grandparent's (it is kept for them).
      refined = scheme.RefineFromGrandparent(
        grandparent, current, depth, rows, child, out.FinestFaces, out.Stencils.back().GetSource());
      if (refined)
      {
        if (!scheme.GrandchildReadsVertexEdgeLists())
        {
          // Read by the rows' construction only: neither the grandparent's own rows nor its
          // grandchild's read them again (PromoteFinestRows builds them for a split again).
          grandparent->Topology.ReleaseVertexEdgeLists();
        }
        out.Stencils.push_back(std::move(rows));
        current = std::move(child);
        grandparent = nullptr;
      }
    }
    std::shared_ptr<const RowSource> writtenRows;
    // A faces-only finest level's rows written from its grandparent where the scheme can
    // (sqrt(3) on closed smooth levels), asked for by the leaner modes: its parent, the
    // largest topology, is then split and freed, not kept for them.
    if (!refined && last && depth == ChildTopology::FacesOnly && grandparent &&
      (levelRows == LevelRows::WrittenLean || levelRows == LevelRows::WrittenFromGrandparent) &&
      scheme.WritesFinestRowsFromGrandparent(*grandparent, current))
    {
      current = scheme.SplitFinestAlone(current); // the parent, freed here
      writtenRows = scheme.MakeFinestRowSourceFromGrandparent(std::move(grandparent), out.Stencils.back().GetSource());
      out.Stencils.push_back(StencilTable::FromSource(writtenRows));
      refined = true;
    }
    if (!refined && splitAloneTrim)
    {
      RestoreSplitAloneTrim(current, scheme.GetParallelFor()); // refined in general after all
    }
    if (levelRows != LevelRows::Stored && !refined)
    {
      auto parent = std::make_shared<Level>(std::move(current));
      if (last && depth == ChildTopology::FacesOnly && !scheme.FinestSplitReadsVertexFacesOrFaceEdges())
      {
        parent->Topology.ReleaseVertexFaceLists(); // a large share of the split's peak
        parent->Topology.ReleaseFaceEdges();
      }
      // The level two above a faces-only finest one whose rows may be written from it: rows
      // reading its faces alone where the scheme has them, so that it keeps nothing else.
      const bool finestGrandparent = l + 2 == levels && finestFromGrandparentIfSmooth;
      writtenRows = finestGrandparent ? scheme.MakeRowSourceWithoutVertexLists(parent) : nullptr;
      const bool rowsReadFacesOnly = writtenRows != nullptr;
      if (!writtenRows)
      {
        writtenRows = scheme.MakeRowSource(parent);
      }
      if (writtenRows)
      {
        out.Stencils.push_back(StencilTable::FromSource(writtenRows));
        // The finest level's parent is not built when the finest comes from its grandparent
        // alone (RefineFromGrandparent reads nothing of it): always for the linear rules, and
        // for the others written from their grandparent when none of their rows needs it.
        parentSkipped = l + 2 == levels &&
          (finestFromGrandparentAlone || (finestFromGrandparentIfSmooth && scheme.RefinesFromGrandparentAlone(*parent)));
        // Once split, the level is kept for its rows (and its grandchild's): what they never
        // read goes, when the split allows before the child's topology is built.
        auto trim = [&scheme, rowsReadFacesOnly](Level& split) {
          MeshTopology::Part part;
          if (rowsReadFacesOnly)
          {
            KeepOnly(split, MeshTopology::Part::Faces, scheme.GetParallelFor());
          }
          else if (scheme.WrittenRowsReadOnly(part))
          {
            KeepOnly(split, part, scheme.GetParallelFor());
          }
          if (!scheme.GrandchildReadsVertexFaceLists())
          {
            // A fifth of a level's topology, all of it in the peak of the levels after.
            split.Topology.ReleaseVertexFaceLists();
          }
        };
        if (parentSkipped)
        {
          current = Level();
          MeshTopology::Part grandchildPart;
          bool grandchildOrigins = false;
          if (scheme.GrandchildAloneReadsOnly(grandchildPart, grandchildOrigins))
          {
            KeepOnly(*parent, grandchildPart, scheme.GetParallelFor(), grandchildOrigins);
          }
          else
          {
            trim(*parent);
          }
        }
        else if (l + 3 <= levels && finestFromGrandparentIfSmooth && scheme.SplitsForGrandchildAlone(*parent))
        {
          // A level down to the finest level's grandparent, split with what its rows and its
          // own split (the finest level, for the grandparent) read alone: the next one is split
          // so again, and the finest level's parent is skipped (above, at the next step: the
          // lean level has the closed form, RefinesFromGrandparentAlone).
          current = scheme.SplitForGrandchildAlone(*parent);
          trim(*parent);
        }
        else
        {
          // The finest level's parent comes without its lists of faces around vertices and
          // its faces' edges, if the finest split reads neither; and without what only its
          // own rows would read where those may come from its parent (split alone).
          const bool leanChild = l + 2 == levels && finest == ChildTopology::FacesOnly &&
            !scheme.FinestSplitReadsVertexFacesOrFaceEdges();
          const LeanChild lean =
            !leanChild ? LeanChild::No : rowsReadFacesOnly ? LeanChild::SplitAlone : LeanChild::WithoutFaceLists;
          current = scheme.SplitAndTrim(*parent, depth, lean, trim);
          splitAloneTrim = lean == LeanChild::SplitAlone;
        }
        grandparent = parent;
      }
      else
      {
        current = std::move(*parent); // the scheme stores its rows: refined below
        grandparent = nullptr;
      }
    }
    if (!writtenRows && !refined)
    {
      LevelRefinement refinement = scheme.RefineLevel(current, depth);
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
  if (levelRows == LevelRows::WrittenFromGrandparent)
  {
    ReleaseFreeMemory(); // the topologies of the levels between
  }
  return true;
}

namespace
{
// The finest level's rows if they are written from its grandparent (the parent not kept),
// for a scheme whose rows cost something to work out. The parent's own rows are the same
// rows (GrandchildRows writes them in its writer's order and weights).
const GrandchildRows* FinestRowsWithoutParent(const Scheme& scheme, const Hierarchy& hierarchy)
{
  if (hierarchy.Stencils.empty() || scheme.RefinesFromGrandparentAlone())
  {
    return nullptr; // the linear rules' rows are centroids, midpoints and copies
  }
  return dynamic_cast<const GrandchildRows*>(hierarchy.Stencils.back().GetSource());
}
}

bool HasFinestRowsToPromote(const Scheme& scheme, const Hierarchy& hierarchy)
{
  return FinestRowsWithoutParent(scheme, hierarchy) != nullptr;
}

bool PromoteFinestRows(const Scheme& scheme, Hierarchy& hierarchy)
{
  const GrandchildRows* rows = FinestRowsWithoutParent(scheme, hierarchy);
  if (!rows)
  {
    return false;
  }
  const Level& grandparent = rows->GetGrandparent();
  std::shared_ptr<Level> parent;
  if (grandparent.Topology.HasVertexFaceLists() && grandparent.Topology.HasVertexRelations())
  {
    parent = std::make_shared<Level>(scheme.Split(grandparent, ChildTopology::Full));
  }
  else
  {
    // The split reads the faces and edges around each vertex, freed after refining: a copy
    // has them again for as long as the split takes (the rows keep the grandparent as it is).
    Level whole = grandparent;
    whole.Topology.RestoreVertexFaceLists(scheme.GetParallelFor());
    whole.Topology.RestoreVertexEdgeLists(scheme.GetParallelFor());
    parent = std::make_shared<Level>(scheme.Split(whole, ChildTopology::Full));
  }
  hierarchy.Stencils.back() = StencilTable::FromSource(scheme.MakeRowSource(parent));
  return true;
}
}
