// SubD kernel: the interface every subdivision scheme implements.
//
// A scheme knows its split (how a level's topology and tags become the next level's) and its
// rules (the stencil table computing the next level's points from this level's). Rules never
// see point storage; the same stencils then refine positions and any other per-point data.
#ifndef SubDScheme_h
#define SubDScheme_h

#include "SubDLevel.h"
#include "SubDStencilTable.h"

namespace subd
{
/// Element counts of a level, in double so that predictions for deep levels cannot overflow.
struct MeshCounts
{
  double Faces = 0, Edges = 0, Vertices = 0, Corners = 0;
};

class SUBDKERNEL_EXPORT Scheme
{
public:
  virtual ~Scheme() = default;
  virtual const char* GetName() const = 0;
  /// The next level's topology and tags (with FacesOnly: faces, holes and origins only).
  virtual Level Split(const Level& parent, ChildTopology depth) const = 0;
  /// The stencils of the next level's points, rows numbered like Split's child points.
  virtual StencilTable BuildStencils(const Level& parent) const = 0;
  /// The counts of the next level of a mesh with the given counts (for size guards).
  virtual MeshCounts PredictChildCounts(const MeshCounts& parent) const = 0;
};

/// Catmull-Clark: the quad split with the rules of SubDCatmullClarkRules.h.
class SUBDKERNEL_EXPORT CatmullClarkScheme : public Scheme
{
public:
  const char* GetName() const override { return "catmull-clark"; }
  Level Split(const Level& parent, ChildTopology depth) const override;
  StencilTable BuildStencils(const Level& parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
};

/// Loop: the triangle split with the rules of SubDLoopRules.h. Triangles only.
class SUBDKERNEL_EXPORT LoopScheme : public Scheme
{
public:
  const char* GetName() const override { return "loop"; }
  Level Split(const Level& parent, ChildTopology depth) const override;
  StencilTable BuildStencils(const Level& parent) const override;
  MeshCounts PredictChildCounts(const MeshCounts& parent) const override;
};
}

#endif
