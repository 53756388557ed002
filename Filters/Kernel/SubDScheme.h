// SubD kernel: the interface every subdivision scheme implements.
//
// A scheme knows its split (how a level's topology and tags become the next level's) and its
// rules (the stencil table computing the next level's points from this level's). Rules never
// see point storage; the same stencils then refine positions and any other per-point data.
#ifndef SubDScheme_h
#define SubDScheme_h

#include "SubDFaceBlocks.h"
#include "SubDGrandchildRows.h"
#include "SubDLevel.h"
#include "SubDParallel.h"
#include "SubDStencilTable.h"

#include <functional>
#include <memory>
#include <string>

namespace subd
{
/// A level's faces made when asked rather than with the level (Hierarchy::MakeFinestFaces).
struct LaterFaces
{
  Index NumFaces = 0;
  std::function<MeshTopology()> Make; ///< empty when nothing is left to make
};

/// Element counts of a level, in double so that predictions for deep levels cannot overflow.
struct MeshCounts
{
  double Faces = 0, Edges = 0, Vertices = 0, Corners = 0;
  double BoundaryEdges = 0; ///< edges with one face, plus non-manifold ones
};

class SUBDKERNEL_EXPORT Scheme
{
public:
  virtual ~Scheme() = default;
  virtual const char* GetName() const = 0;
  /// The next level's topology and tags (with FacesOnly: faces, holes and origins only).
  virtual Level Split(const Level& parent, ChildTopology depth) const = 0;
  /// Split, calling trimParent(parent) once the split reads no more of `parent` than the
  /// trim keeps (Refine's: what the parent's written rows read). By default after the split;
  /// sqrt(3) calls it before it builds a general child's topology, so that the parent's
  /// whole topology and the child's are not held at once. `lean` says what the child may come
  /// without (Refine asks so for the finest level's parent where the finest split reads
  /// neither the lists of faces around vertices nor the faces' edges:
  /// FinestSplitReadsVertexFacesOrFaceEdges; and also without the lists of edges around
  /// vertices nor the sharpness of a smooth level where it may be split alone): freed after
  /// the split by default, never made by sqrt(3)'s closed form.
  virtual Level SplitAndTrim(
    Level& parent, ChildTopology depth, LeanChild lean, const std::function<void(Level&)>& trimParent) const
  {
    Level child = this->SplitBeforeTrim(parent, depth);
    trimParent(parent);
    TrimToLeanChild(child, lean);
    return child;
  }
  /// SplitAndTrim's split: Split by default. `parent` is kept for its written rows only
  /// (WrittenRowsReadOnly), so a split may free, once it no longer reads them, parts of it
  /// that neither the rest of the split nor those rows read (Doo-Sabin: the lists of edges
  /// around the vertices, read to number the points only).
  virtual Level SplitBeforeTrim(Level& parent, ChildTopology depth) const { return this->Split(parent, depth); }
  /// Whether SplitBeforeTrim frees the lists of edges around the parent's vertices before it
  /// writes a faces-only child (EstimatePeakBytes counts them out of that split's peak).
  virtual bool FacesOnlySplitFreesVertexEdgeLists() const { return false; }
  /// How the splits run their loops: SerialFor unless a caller with threads sets its own.
  /// Splits that derive the child topology in closed form (the quad and triangle splits) use
  /// it; results are the same for any number of threads.
  void SetParallelFor(ParallelFor parallelFor) { this->Parallel = std::move(parallelFor); }
  const ParallelFor& GetParallelFor() const { return this->Parallel; }
  /// Whether a faces-only split (a finest level) records each face's origin, the base face it
  /// comes from (Level::FaceOrigin): on by default. A caller that reads none (no cell data
  /// to carry, no parent ids, no ghosts) turns it off; the splits that write their faces in
  /// parallel (sqrt(3), Doo-Sabin) then spare 4 bytes a finest face at their peak, and keep
  /// a faces-only child's hole flags only where its parent has a hole (Level::IsFaceHole).
  void SetFacesOnlyOrigins(bool keep) { this->FacesOnlyOrigins = keep; }
  bool GetFacesOnlyOrigins() const { return this->FacesOnlyOrigins; }
  /// The tags a split with `depth` of `parent` keeps (FaceTagsKept; see SetFacesOnlyOrigins).
  FaceTagsKept GetFaceTagsKept(const Level& parent, ChildTopology depth) const
  {
    const bool facesOnly = depth == ChildTopology::FacesOnly;
    return FaceTagsKept{ !facesOnly || this->FacesOnlyOrigins, !facesOnly || parent.HasHoles() };
  }
  /// The stencils of the next level's points, rows numbered like Split's child points.
  virtual StencilTable BuildStencils(const Level& parent) const = 0;
  /// Both at once (schemes whose split and stencils share work override it).
  virtual LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const
  {
    LevelRefinement r;
    r.Stencils = this->BuildStencils(parent);
    r.Child = this->Split(parent, depth);
    return r;
  }
  /// The next level's stencils as rows written when they are applied (SubDRowWriting.h),
  /// which keep `parent` instead of storing the rows; nullptr (the default) for schemes
  /// that only store their rows. Refine uses it for every level when asked.
  virtual std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const
  {
    (void)parent;
    return nullptr;
  }
  /// Whether the split into a faces-only child and the rows MakeRowSource writes read the
  /// lists of faces around the parent's vertices (not only their counts) or each face's
  /// edges: where they read neither (sqrt(3)), Refine frees both before the finest level,
  /// faces only, is split from it (the peak of a refinement).
  virtual bool FinestSplitReadsVertexFacesOrFaceEdges() const { return true; }
  /// For a faces-only finest level whose rows are written as applied: whether they can be
  /// written from `grandparent`, the level two above (kept by its own rows, and maybe
  /// trimmed to what those read), instead of from `parent`, its child (whole), which is then
  /// split by SplitFinestAlone and freed instead of kept. False by default; sqrt(3) where
  /// both levels are closed and smooth (SubDSqrt3GrandparentRows.h).
  virtual bool WritesFinestRowsFromGrandparent(const Level& grandparent, const Level& parent) const
  {
    (void)grandparent;
    (void)parent;
    return false;
  }
  /// Whether WritesFinestRowsFromGrandparent may be true (on a closed mesh without sharp
  /// features): what EstimatePeakBytes counts.
  virtual bool MayWriteFinestRowsFromGrandparent() const { return false; }
  /// Those rows (where WritesFinestRowsFromGrandparent): made after the finest split, so
  /// that their tables and the parent's topology are not held at once. `grandparentRows`
  /// are the grandparent's own rows, whose tables they may share.
  virtual std::shared_ptr<const RowSource> MakeFinestRowSourceFromGrandparent(
    std::shared_ptr<const Level> grandparent, const RowSource* grandparentRows) const
  {
    (void)grandparent;
    (void)grandparentRows;
    return nullptr;
  }
  /// MakeRowSource's rows of a level that may become the finest level's grandparent, where
  /// they can be written without the lists around the level's vertices, so that it keeps its
  /// faces alone once its child is split; nullptr (the default) where the scheme or the level
  /// has no such rows. sqrt(3): on a closed smooth level whose child has the closed form (the
  /// case of WritesFinestRowsFromGrandparent), each vertex's ring read from the fans of its
  /// triangles, which the finest level's rows then share.
  virtual std::shared_ptr<const RowSource> MakeRowSourceWithoutVertexLists(std::shared_ptr<const Level> parent) const
  {
    (void)parent;
    return nullptr;
  }
  /// The faces-only finest level of a parent that nothing reads afterwards (its rows come
  /// from the grandparent): the split may first free what of `parent` it does not read.
  /// Split by default.
  virtual Level SplitFinestAlone(Level& parent) const { return this->Split(parent, ChildTopology::FacesOnly); }
  /// True when the rows MakeRowSource writes read nothing of their parent level but `part`
  /// of its topology: Refine then frees the rest of each such level once it is split
  /// (KeepOnly), since it keeps it for those rows only. Only for schemes without
  /// RefineFromGrandparent, whose levels are never read again as grandparents.
  virtual bool WrittenRowsReadOnly(MeshTopology::Part& part) const
  {
    (void)part;
    return false;
  }
  /// For levels whose rows are written as applied (LevelRows::WrittenFromGrandparent):
  /// `parent`'s child (with `depth`) and its rows, written from `grandparent`, whose child
  /// `parent` is (full topology), so that `parent`'s topology need not be kept: it is
  /// released here. A faces-only child gets its tags but not its faces: `childFaces` makes
  /// them (from the grandparent, which the rows keep), so that a caller can first evaluate
  /// the points and free its scratch. `grandparentRows`, if given, are the rows from
  /// `grandparent` to `parent` (tables of theirs may be shared: GrandchildRows). Returns
  /// false, changing nothing, for schemes that cannot (those without GetGrandchildScheme).
  /// `parent` is empty where Refine did not build it (RefinesFromGrandparentAlone(grandparent)).
  /// The midpoint scheme writes a faces-only child so, in closed form (SubDMidpointGrandchild.h),
  /// where its parent was not built, and returns false otherwise.
  virtual bool RefineFromGrandparent(std::shared_ptr<const Level> grandparent, Level& parent, ChildTopology depth,
    StencilTable& rows, Level& child, LaterFaces& childFaces, const RowSource* grandparentRows = nullptr) const;
  /// True for the schemes whose RefineFromGrandparent can return true for any level (those
  /// with GetGrandchildScheme; LowMemory applies to them). The midpoint scheme's returns true
  /// only where Refine skipped the parent, which the leaner modes do alike: false for it.
  bool RefinesFromGrandparent() const
  {
    GrandchildScheme which;
    return this->GetGrandchildScheme(which);
  }
  /// True when RefineFromGrandparent reads nothing of `parent` for a faces-only child (every
  /// row in closed form): Refine then never builds the level above a faces-only finest level,
  /// whatever the LevelRows (except Stored), which is faster and leaner.
  bool RefinesFromGrandparentAlone() const
  {
    GrandchildScheme which;
    return this->GetGrandchildScheme(which) && WritesEveryRowFromGrandparent(which);
  }
  /// True when RefineFromGrandparent reads nothing of `parent` for this `grandparent`: always
  /// when RefinesFromGrandparentAlone(), else when no row needs the parent
  /// (EveryGrandchildRowIsSmooth; with LevelRows::WrittenFromGrandparent or WrittenLean,
  /// Refine then does not build the level above a faces-only finest level).
  /// The midpoint scheme: where its grandchild has a closed form (MidpointGrandchildHasClosedForm).
  virtual bool RefinesFromGrandparentAlone(const Level& grandparent) const
  {
    GrandchildScheme which;
    return this->GetGrandchildScheme(which) && EveryGrandchildRowIsSmooth(which, grandparent);
  }
  /// Where a level's child is not built (RefinesFromGrandparentAlone(level)), whether the
  /// level's own rows and its grandchild, written from it, read nothing of it but `part` of its
  /// topology and, if `faceOrigins`, its faces' origins: Refine then frees the rest once the
  /// rows are made. False by default (the schemes whose grandchild rows are GrandchildRows
  /// keep what those read); the midpoint scheme: its faces with their edges, and its edges'
  /// ends.
  virtual bool GrandchildAloneReadsOnly(MeshTopology::Part& part, bool& faceOrigins) const
  {
    (void)part;
    (void)faceOrigins;
    return false;
  }
  /// Whether `parent`'s child may be split with only what its own rows and its grandchild,
  /// written from it alone, read (SplitForGrandchildAlone): Refine asks so of the levels from
  /// the base to the one three above a faces-only finest level in the leaner modes, splits
  /// each such child so again, and skips the finest level's parent, since a child so split must
  /// have RefinesFromGrandparentAlone and SplitsForGrandchildAlone. False by default; the
  /// midpoint scheme on a closed smooth level (MidpointGrandchildHasClosedForm), whose child
  /// has the closed form too.
  virtual bool SplitsForGrandchildAlone(const Level& parent) const
  {
    (void)parent;
    return false;
  }
  /// That split; Split with the full topology by default.
  virtual Level SplitForGrandchildAlone(const Level& parent) const { return this->Split(parent, ChildTopology::Full); }
  /// Whether SplitsForGrandchildAlone may be true (on a closed mesh without sharp features):
  /// what EstimatePeakBytes counts.
  virtual bool MaySplitForGrandchildAlone() const { return false; }
  /// How much of the levels between the base and a faces-only finest level Refine builds: the
  /// full topology, except for the linear rules, whose rows, splits and grandchild rows read
  /// faces and edges only (the faces of an edge where it is non-manifold): the lists and tags
  /// around each vertex, about half of a level's topology, are then never made.
  ChildTopology GetTopologyBetween() const
  {
    return this->RefinesFromGrandparentAlone() ? ChildTopology::FacesAndEdges : ChildTopology::Full;
  }
  /// Whether a level kept for its rows and its grandchild's (written from it, its child built
  /// or skipped) is still read for the lists of faces around its vertices once split: by its
  /// own rows, the grandchild's rows or faces. Loop's rules read vertex rings through edges
  /// and only count faces, and the butterfly's order their rings through edges' faces, so
  /// Refine frees those lists there after the split (PromoteFinestRows restores them for a
  /// split again); Catmull-Clark's vertex rows sum the faces around.
  bool GrandchildReadsVertexFaceLists() const
  {
    GrandchildScheme which;
    return !this->GetGrandchildScheme(which) ||
      (which != GrandchildScheme::Loop && which != GrandchildScheme::Butterfly);
  }
  /// Whether a level whose grandchild's rows were written from it (RefineFromGrandparent) is
  /// read again for the lists of edges around its vertices: by Catmull-Clark's and Loop's
  /// vertex rows. The butterfly's vertex points are copies, its rings are stored
  /// (ButterflyGrandparentTables) and its own rows keep the crease neighbours they read, so
  /// Refine frees those lists once the grandchild's rows are made.
  bool GrandchildReadsVertexEdgeLists() const
  {
    GrandchildScheme which;
    return !this->GetGrandchildScheme(which) || which != GrandchildScheme::Butterfly;
  }
  /// The counts of the next level of a mesh with the given counts (for size guards).
  virtual MeshCounts PredictChildCounts(const MeshCounts& parent) const = 0;
  /// The same for a closed manifold mesh without sharp features (where the midpoint scheme
  /// keeps no vertex): PredictChildCounts by default.
  virtual MeshCounts PredictClosedSmoothChildCounts(const MeshCounts& parent) const
  {
    return this->PredictChildCounts(parent);
  }
  /// False for schemes whose points only interpolate within a face (linear, bilinear): the
  /// boundary rule cannot change them, so BoundaryRule::None makes no holes (as in
  /// OpenSubdiv, where it only applies to schemes with a neighbourhood).
  virtual bool UsesBoundaryRule() const { return true; }
  /// True for schemes whose rules alternate with Level::Depth (sqrt(3)'s boundary steps): a
  /// mesh they make records its depth so that a later refinement continues it.
  virtual bool DependsOnDepth() const { return false; }
  /// The limit positions of the vertices of `level` (a full-topology level), one row per
  /// vertex (SubDLimitRules.h). Returns false and says why in `error` when the scheme has
  /// no limit masks (yet) or the level does not suit them.
  virtual bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const;
  /// Two rows per vertex of `level` (2v, 2v + 1) spanning the tangent plane of the limit
  /// surface at the vertex's limit point, their cross product pointing to the side the
  /// faces are counter-clockwise from. For the schemes whose limit LimitEvaluator cannot
  /// evaluate (Catmull-Clark and Loop have exact derivatives there). Returns false and says
  /// why when the scheme, or one vertex, has no tangent masks.
  virtual bool BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const;
  /// The rule to prepare the base level with for a requested one.
  BoundaryRule EffectiveBoundaryRule(BoundaryRule requested) const
  {
    return this->UsesBoundaryRule() ? requested : BoundaryRule::EdgeOnly;
  }

protected:
  /// The scheme's rows written from the grandparent (SubDGrandchildRows.h), if it has them.
  virtual bool GetGrandchildScheme(GrandchildScheme& which) const
  {
    (void)which;
    return false;
  }

private:
  ParallelFor Parallel = SerialFor;
  bool FacesOnlyOrigins = true;
};

/// Schemes on the quad split (SubDQuadSplit.h): any polygons in, quads out.
class SUBDKERNEL_EXPORT QuadSplitScheme : public Scheme
{
public:
  Level Split(const Level& parent, ChildTopology depth) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
};

/// Schemes on the triangle split (SubDTriangleSplit.h): triangles in, triangles out.
class SUBDKERNEL_EXPORT TriangleSplitScheme : public Scheme
{
public:
  Level Split(const Level& parent, ChildTopology depth) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
};

/// Catmull-Clark (SubDCatmullClarkRules.h).
class SUBDKERNEL_EXPORT CatmullClarkScheme : public QuadSplitScheme
{
public:
  const char* GetName() const override { return "catmull-clark"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;

protected:
  bool GetGrandchildScheme(GrandchildScheme& which) const override
  {
    which = GrandchildScheme::CatmullClark; // SubDGrandchildRows.h
    return true;
  }
};

/// Bilinear: centroids, midpoints and fixed vertices (SubDLinearRules.h).
class SUBDKERNEL_EXPORT BilinearScheme : public QuadSplitScheme
{
public:
  const char* GetName() const override { return "bilinear"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  /// Interpolating: the identity (SubDLimitRules.h).
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool UsesBoundaryRule() const override { return false; }

protected:
  bool GetGrandchildScheme(GrandchildScheme& which) const override
  {
    which = GrandchildScheme::Bilinear; // SubDGrandchildRows.h
    return true;
  }
};

/// Loop (SubDLoopRules.h).
class SUBDKERNEL_EXPORT LoopScheme : public TriangleSplitScheme
{
public:
  const char* GetName() const override { return "loop"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;

protected:
  bool GetGrandchildScheme(GrandchildScheme& which) const override
  {
    which = GrandchildScheme::Loop; // SubDGrandchildRows.h
    return true;
  }
};

/// Linear triangles: midpoints and fixed vertices (SubDLinearRules.h).
class SUBDKERNEL_EXPORT LinearTriangleScheme : public TriangleSplitScheme
{
public:
  const char* GetName() const override { return "linear-triangles"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  /// Interpolating: the identity (SubDLimitRules.h).
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool UsesBoundaryRule() const override { return false; }

protected:
  bool GetGrandchildScheme(GrandchildScheme& which) const override
  {
    which = GrandchildScheme::LinearTriangles; // SubDGrandchildRows.h
    return true;
  }
};

/// Doo-Sabin: the dual split with the masks of SubDDooSabinRules.h. Any polygons.
class SUBDKERNEL_EXPORT DooSabinScheme : public Scheme
{
public:
  const char* GetName() const override { return "doo-sabin"; }
  /// SubDDualLimit.h.
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const override;
  bool UsesBoundaryRule() const override { return false; }
  Level Split(const Level& parent, ChildTopology depth) const override;
  /// A faces-only split frees the parent's lists of edges around its vertices once the
  /// points are numbered: the faces are written from the faces around them (with the rows'
  /// bit per corner before a sharp edge instead of the faces' edges, MakeDooSabinRowSource:
  /// bunny, level 3, 2 threads, peak 249 to 225 MB).
  Level SplitBeforeTrim(Level& parent, ChildTopology depth) const override;
  bool FacesOnlySplitFreesVertexEdgeLists() const override { return true; }
  StencilTable BuildStencils(const Level& parent) const override;
  LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const override;
  /// MakeDooSabinRowSource: the rows read the parent's faces and the dual numbering only.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool WrittenRowsReadOnly(MeshTopology::Part& part) const override
  {
    part = MeshTopology::Part::Faces;
    return true;
  }
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
};

/// Modified butterfly with tension (SubDButterflyRules.h). Triangles only; interpolating.
class SUBDKERNEL_EXPORT ButterflyScheme : public TriangleSplitScheme
{
public:
  explicit ButterflyScheme(double tension = 0.0)
    : Tension(tension)
  {
  }
  const char* GetName() const override { return "butterfly"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  /// Interpolating: the identity (SubDLimitRules.h).
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool UsesBoundaryRule() const override { return false; }

protected:
  /// Without tension only: the tips' rings would take two more steps around each end.
  bool GetGrandchildScheme(GrandchildScheme& which) const override
  {
    which = GrandchildScheme::Butterfly; // SubDGrandchildRows.h
    return this->Tension == 0.0;
  }

private:
  double Tension;
};

/// Schemes whose split and stencils are built together because they share a point
/// numbering that depends on the mesh (kept boundary vertices, trisected edges): they
/// implement RefineLevel only.
class SUBDKERNEL_EXPORT JointRefinementScheme : public Scheme
{
public:
  Level Split(const Level& parent, ChildTopology depth) const override
  {
    return this->RefineLevel(parent, depth).Child;
  }
  StencilTable BuildStencils(const Level& parent) const override
  {
    return this->RefineLevel(parent, ChildTopology::FacesOnly).Stencils;
  }
  LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const override = 0;
};

/// Kobbelt's sqrt(3) subdivision (SubDSqrt3Rules.h). Triangles only.
class SUBDKERNEL_EXPORT Sqrt3Scheme : public JointRefinementScheme
{
public:
  bool DependsOnDepth() const override { return true; }
  const char* GetName() const override { return "sqrt3"; }
  /// SubDSqrt3Limit.h.
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const override;
  LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const override;
  /// SplitSqrt3: the split without the rows, for rows written as applied.
  Level Split(const Level& parent, ChildTopology depth) const override;
  /// Trims the parent once the split reads no more of it (SplitSqrt3's `parentRead`): before
  /// the child's topology where that is built in general (a mesh with a boundary or sharp
  /// edges), after it in the closed form, before the child's sharpness.
  Level SplitAndTrim(Level& parent, ChildTopology depth, LeanChild lean,
    const std::function<void(Level&)>& trimParent) const override;
  /// MakeSqrt3RowSource: the rows read the parent's faces and vertex rings only.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool WrittenRowsReadOnly(MeshTopology::Part& part) const override
  {
    part = MeshTopology::Part::FacesAndRings;
    return true;
  }
  /// Its flips read each edge's ends and faces and each face's corners, its rows each
  /// vertex's edges and face count.
  bool FinestSplitReadsVertexFacesOrFaceEdges() const override { return false; }
  /// Sqrt3RowsFromGrandparentApply (closed, smooth levels): MakeSqrt3RowSourceFromGrandparent.
  bool WritesFinestRowsFromGrandparent(const Level& grandparent, const Level& parent) const override;
  bool MayWriteFinestRowsFromGrandparent() const override { return true; }
  /// Shares the fans of the grandparent's rows where those read them.
  std::shared_ptr<const RowSource> MakeFinestRowSourceFromGrandparent(
    std::shared_ptr<const Level> grandparent, const RowSource* grandparentRows) const override;
  /// MakeSqrt3RowSourceReadingFans on a level without sharp features whose child has the
  /// closed form (Sqrt3ChildTopology::Applies).
  std::shared_ptr<const RowSource> MakeRowSourceWithoutVertexLists(std::shared_ptr<const Level> parent) const override;
  /// Frees the parent's lists of edges around its vertices and its vertices' sharpness, and
  /// its faces' origins and hole flags where the child keeps none, before the flips (which
  /// read none of them).
  Level SplitFinestAlone(Level& parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
  bool UsesBoundaryRule() const override { return false; }
};

/// Peters-Reif midpoint ("simplest") subdivision, boundaries kept (SubDMidpointSplit.h).
class SUBDKERNEL_EXPORT MidpointScheme : public JointRefinementScheme
{
public:
  const char* GetName() const override { return "midpoint"; }
  /// SubDDualLimit.h.
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
  bool BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const override;
  LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const override;
  /// SplitMidpoint: the split without the rows, for rows written as applied.
  Level Split(const Level& parent, ChildTopology depth) const override;
  /// MakeMidpointRowSource: the rows read the parent's edges' ends only.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool WrittenRowsReadOnly(MeshTopology::Part& part) const override
  {
    part = MeshTopology::Part::EdgeEnds;
    return true;
  }
  /// On a closed smooth level (MidpointGrandchildHasClosedForm) the faces-only finest level
  /// two splits down is written from it alone, its parent never built.
  bool RefinesFromGrandparentAlone(const Level& grandparent) const override;
  using Scheme::RefinesFromGrandparentAlone;
  bool GrandchildAloneReadsOnly(MeshTopology::Part& part, bool& faceOrigins) const override
  {
    part = MeshTopology::Part::FacesWithEdges;
    faceOrigins = this->GetFacesOnlyOrigins();
    return true;
  }
  bool RefineFromGrandparent(std::shared_ptr<const Level> grandparent, Level& parent, ChildTopology depth,
    StencilTable& rows, Level& child, LaterFaces& childFaces, const RowSource* grandparentRows = nullptr) const override;
  /// MidpointGrandchildHasClosedForm(parent): MidpointChildWithEdges.
  bool SplitsForGrandchildAlone(const Level& parent) const override;
  Level SplitForGrandchildAlone(const Level& parent) const override;
  bool MaySplitForGrandchildAlone() const override { return true; }
  /// Exact: a point per edge, a face per face and vertex, two corners per corner, an edge
  /// per corner.
  MeshCounts PredictClosedSmoothChildCounts(const MeshCounts& parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
  bool UsesBoundaryRule() const override { return false; }
};
}

#endif
