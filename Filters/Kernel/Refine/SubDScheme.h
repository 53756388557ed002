// SubD kernel: the interface every subdivision scheme implements.
//
// A scheme knows its split (how a level's topology and tags become the next level's) and its
// rules (the stencil table computing the next level's points from this level's). Rules never
// see point storage; the same stencils then refine positions and any other per-point data.
#ifndef SubDScheme_h
#define SubDScheme_h

#include "SubDLevel.h"
#include "SubDParallel.h"
#include "SubDStencilTable.h"

#include <functional>
#include <memory>
#include <string>

namespace subd
{
/// Element counts of a level, in double so that predictions for deep levels cannot overflow.
struct MeshCounts
{
  double Faces = 0, Edges = 0, Vertices = 0, Corners = 0;
  double BoundaryEdges = 0; ///< edges with one face, plus non-manifold ones
};

/// What a subdivision scheme is: its split (how a level's topology and tags become the
/// next level's), its rules (the rows of the next level's points), its limit masks and its
/// traits. How a refinement keeps its levels is Refine's business, not the scheme's.
class SUBDKERNEL_EXPORT Scheme
{
public:
  virtual ~Scheme() = default;
  virtual const char* GetName() const = 0;
  /// The next level's topology and tags (with FacesOnly: faces, holes and origins only).
  virtual Level Split(const Level& parent, ChildTopology depth) const = 0;
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
  /// that only store their rows.
  virtual std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const
  {
    (void)parent;
    return nullptr;
  }
  /// The counts of the next level of a mesh with the given counts (for size guards).
  virtual MeshCounts PredictChildCounts(const MeshCounts& parent) const = 0;
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

  /// How the splits and rows run their loops: SerialFor unless a caller with threads sets
  /// its own. Results are the same for any number of threads.
  void SetParallelFor(ParallelFor parallelFor) { this->Parallel = std::move(parallelFor); }
  const ParallelFor& GetParallelFor() const { return this->Parallel; }
  /// The rule to prepare the base level with for a requested one.
  BoundaryRule EffectiveBoundaryRule(BoundaryRule requested) const
  {
    return this->UsesBoundaryRule() ? requested : BoundaryRule::EdgeOnly;
  }

private:
  ParallelFor Parallel = SerialFor;
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

/// Catmull-Clark (SubDCatmullClarkRules.h); `smoothTriangles`: OpenSubdiv's smooth triangle
/// rule (Sdc::Options::TRI_SUB_SMOOTH) for the edges of triangles.
class SUBDKERNEL_EXPORT CatmullClarkScheme : public QuadSplitScheme
{
public:
  explicit CatmullClarkScheme(bool smoothTriangles = false)
    : SmoothTriangles(smoothTriangles)
  {
  }
  const char* GetName() const override { return "catmull-clark"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;

private:
  bool SmoothTriangles;
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
};

/// Loop (SubDLoopRules.h).
class SUBDKERNEL_EXPORT LoopScheme : public TriangleSplitScheme
{
public:
  const char* GetName() const override { return "loop"; }
  StencilTable BuildStencils(const Level& parent) const override;
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  bool BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const override;
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
  StencilTable BuildStencils(const Level& parent) const override;
  LevelRefinement RefineLevel(const Level& parent, ChildTopology depth) const override;
  /// MakeDooSabinRowSource.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
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
  /// MakeSqrt3RowSource.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
  bool UsesBoundaryRule() const override { return false; }
};

/// Peters-Reif midpoint ("simplest") subdivision, boundaries kept (SubDMidpointRules.h).
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
  /// MakeMidpointRowSource.
  std::shared_ptr<const RowSource> MakeRowSource(std::shared_ptr<const Level> parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
  bool UsesBoundaryRule() const override { return false; }
};
}

#endif
