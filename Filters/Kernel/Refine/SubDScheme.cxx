#include "SubDScheme.h"
#include "SubDLimitRules.h"
#include "SubDCatmullClarkRules.h"
#include "SubDButterflyRules.h"
#include "SubDDooSabinRules.h"
#include "SubDDualLimit.h"
#include "SubDDualSplit.h"
#include "SubDLinearRules.h"
#include "SubDLoopRules.h"
#include "SubDMidpointRules.h"
#include "SubDQuadSplit.h"
#include "SubDRowWriting.h"
#include "SubDSqrt3Limit.h"
#include "SubDSqrt3Rules.h"
#include "SubDTriangleSplit.h"

namespace subd
{
Level QuadSplitScheme::Split(const Level& parent, ChildTopology depth) const
{
  return SplitQuads(parent, depth, this->GetParallelFor());
}

StencilTable CatmullClarkScheme::BuildStencils(const Level& parent) const
{
  return BuildCatmullClarkStencils(parent, this->SmoothTriangles);
}

std::shared_ptr<const RowSource> CatmullClarkScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return std::make_shared<WrittenRows<CatmullClarkRowWriter>>(
    std::move(parent), this->GetParallelFor(), this->SmoothTriangles);
}

MeshCounts QuadSplitScheme::PredictChildCounts(const MeshCounts& parent) const
{
  // Each corner becomes a quad; each edge splits in two and each corner adds an inner edge.
  MeshCounts child;
  child.Faces = parent.Corners;
  child.Edges = 2.0 * parent.Edges + parent.Corners;
  child.Vertices = parent.Faces + parent.Edges + parent.Vertices;
  child.Corners = 4.0 * parent.Corners;
  child.BoundaryEdges = 2.0 * parent.BoundaryEdges;
  return child;
}

Level TriangleSplitScheme::Split(const Level& parent, ChildTopology depth) const
{
  return SplitTriangles(parent, depth, this->GetParallelFor());
}

StencilTable LoopScheme::BuildStencils(const Level& parent) const
{
  return BuildLoopStencils(parent);
}

std::shared_ptr<const RowSource> LinearTriangleScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return std::make_shared<WrittenRows<LinearRowWriter>>(std::move(parent), false);
}

std::shared_ptr<const RowSource> BilinearScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return std::make_shared<WrittenRows<LinearRowWriter>>(std::move(parent), true);
}

std::shared_ptr<const RowSource> ButterflyScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return std::make_shared<WrittenRows<ButterflyRowWriter>>(std::move(parent), this->Tension, this->GetParallelFor());
}

std::shared_ptr<const RowSource> LoopScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return std::make_shared<WrittenRows<LoopRowWriter>>(std::move(parent), this->GetParallelFor());
}

MeshCounts TriangleSplitScheme::PredictChildCounts(const MeshCounts& parent) const
{
  // Each triangle becomes four; each edge splits in two and each triangle adds three inside.
  MeshCounts child;
  child.Faces = 4.0 * parent.Faces;
  child.Edges = 2.0 * parent.Edges + 3.0 * parent.Faces;
  child.Vertices = parent.Vertices + parent.Edges;
  child.Corners = 4.0 * parent.Corners;
  child.BoundaryEdges = 2.0 * parent.BoundaryEdges;
  return child;
}

StencilTable BilinearScheme::BuildStencils(const Level& parent) const
{
  return BuildBilinearStencils(parent);
}

StencilTable LinearTriangleScheme::BuildStencils(const Level& parent) const
{
  return BuildLinearTriangleStencils(parent);
}

Level DooSabinScheme::Split(const Level& parent, ChildTopology depth) const
{
  return SplitDual(parent, NumberDualPoints(parent, this->GetParallelFor()), depth, this->GetParallelFor());
}

StencilTable DooSabinScheme::BuildStencils(const Level& parent) const
{
  return BuildDooSabinStencils(parent, NumberDualPoints(parent, this->GetParallelFor()), this->GetParallelFor());
}

LevelRefinement DooSabinScheme::RefineLevel(const Level& parent, ChildTopology depth) const
{
  // The welded point numbering is needed by both: compute it once.
  const DualPoints points = NumberDualPoints(parent, this->GetParallelFor());
  LevelRefinement r;
  r.Stencils = BuildDooSabinStencils(parent, points, this->GetParallelFor());
  r.Child = SplitDual(parent, points, depth, this->GetParallelFor());
  return r;
}

std::shared_ptr<const RowSource> DooSabinScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return MakeDooSabinRowSource(std::move(parent), this->GetParallelFor());
}

MeshCounts DooSabinScheme::PredictChildCounts(const MeshCounts& parent) const
{
  // Upper bounds (a closed mesh): a point per corner; F-, E- and V-faces; the corners of
  // F-faces (H), E-faces (4E) and V-faces (H); edges: those of the F- and V-faces (H each).
  // A crease turn's second point (SubDDualSplit.h) is welded across its edge, and its extra
  // F-face corner and edge stand for its corner's, which is in no V-face (a sector of one).
  MeshCounts child;
  child.Vertices = parent.Corners;
  child.Faces = parent.Faces + parent.Edges + parent.Vertices;
  child.Corners = 2.0 * parent.Corners + 4.0 * parent.Edges;
  child.Edges = 2.0 * parent.Corners;
  child.BoundaryEdges = 2.0 * parent.BoundaryEdges;
  return child;
}

LevelRefinement MidpointScheme::RefineLevel(const Level& parent, ChildTopology depth) const
{
  return RefineMidpoint(parent, depth, this->GetParallelFor());
}

Level MidpointScheme::Split(const Level& parent, ChildTopology depth) const
{
  return SplitMidpoint(parent, depth, this->GetParallelFor());
}

std::shared_ptr<const RowSource> MidpointScheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return MakeMidpointRowSource(std::move(parent));
}

MeshCounts MidpointScheme::PredictChildCounts(const MeshCounts& parent) const
{
  // Upper bounds (plus kept boundary vertices, at most V): a point per edge; F- and
  // V-faces; each face corner gives one corner to an F-face and one to a V-face. A vertex on
  // an interior crease gets a V-face per sector, which this size guard does not count.
  MeshCounts child;
  child.Vertices = parent.Edges + parent.Vertices;
  child.Faces = parent.Faces + parent.Vertices;
  child.Corners = 2.0 * parent.Corners + 3.0 * parent.Vertices;
  child.Edges = parent.Corners + 2.0 * parent.Vertices;
  child.BoundaryEdges = 2.0 * parent.BoundaryEdges;
  return child;
}

StencilTable ButterflyScheme::BuildStencils(const Level& parent) const
{
  return BuildButterflyStencils(parent, this->Tension, this->GetParallelFor());
}

LevelRefinement Sqrt3Scheme::RefineLevel(const Level& parent, ChildTopology depth) const
{
  return RefineSqrt3(parent, depth, this->GetParallelFor());
}

Level Sqrt3Scheme::Split(const Level& parent, ChildTopology depth) const
{
  return SplitSqrt3(parent, depth, this->GetParallelFor());
}

std::shared_ptr<const RowSource> Sqrt3Scheme::MakeRowSource(std::shared_ptr<const Level> parent) const
{
  return MakeSqrt3RowSource(std::move(parent), this->GetParallelFor());
}

MeshCounts Sqrt3Scheme::PredictChildCounts(const MeshCounts& parent) const
{
  // Three triangles per triangle. Each face adds a point and three edges; in the steps that
  // trisect the boundary (every second one; the prediction does not know which, so it
  // bounds both) each boundary triangle trades its centroid for two edge points (+1 point)
  // and adds one edge, and the boundary triples.
  MeshCounts child;
  child.Faces = 3.0 * parent.Faces;
  child.Vertices = parent.Vertices + parent.Faces + parent.BoundaryEdges;
  child.Edges = parent.Edges + 3.0 * parent.Faces + parent.BoundaryEdges;
  child.Corners = 3.0 * parent.Corners;
  child.BoundaryEdges = 3.0 * parent.BoundaryEdges;
  return child;
}

bool Scheme::BuildLimitStencils(const Level&, StencilTable&, std::string& error) const
{
  error = std::string("the ") + this->GetName() + " scheme has no limit masks yet";
  return false;
}

bool Scheme::BuildLimitTangentStencils(const Level&, StencilTable&, std::string& error) const
{
  error = std::string("the ") + this->GetName() + " scheme has no limit tangent masks";
  return false;
}

bool DooSabinScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const
{
  return BuildDooSabinLimitStencils(level, false, stencils, error);
}

bool DooSabinScheme::BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const
{
  return BuildDooSabinLimitStencils(level, true, tangents, error);
}

bool MidpointScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const
{
  return BuildMidpointLimitStencils(level, false, stencils, error);
}

bool MidpointScheme::BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const
{
  return BuildMidpointLimitStencils(level, true, tangents, error);
}

bool Sqrt3Scheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const
{
  return BuildSqrt3LimitStencils(level, false, stencils, error);
}

bool Sqrt3Scheme::BuildLimitTangentStencils(const Level& level, StencilTable& tangents, std::string& error) const
{
  return BuildSqrt3LimitStencils(level, true, tangents, error);
}

bool BilinearScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string&) const
{
  stencils = BuildInterpolatingLimitStencils(level);
  return true;
}

bool LinearTriangleScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string&) const
{
  stencils = BuildInterpolatingLimitStencils(level);
  return true;
}

bool ButterflyScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string&) const
{
  stencils = BuildInterpolatingLimitStencils(level);
  return true;
}

bool CatmullClarkScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string& error) const
{
  return BuildCatmullClarkLimitStencils(level, stencils, error);
}

bool LoopScheme::BuildLimitStencils(const Level& level, StencilTable& stencils, std::string&) const
{
  stencils = BuildLoopLimitStencils(level);
  return true;
}
}
