// Helpers of the oracle tests against OpenSubdiv (Debian's libosd-dev): its refiner of a test
// fixture with the same boundary rule, sharp features and face-varying channel as SubD's base
// level, and SubD's scheme of each kind.
#ifndef SubDOpenSubdivOracle_h
#define SubDOpenSubdivOracle_h

#include "SubDFaceVarying.h"
#include "SubDLevel.h"
#include "SubDScheme.h"
#include "SubDTestMeshes.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace subdtest
{
using namespace OpenSubdiv;
using subd::Index;

struct Point3
{
  double P[3];
  void Clear() { P[0] = P[1] = P[2] = 0.0; }
  void AddWithWeight(const Point3& src, double w)
  {
    for (int c = 0; c < 3; ++c)
    {
      P[c] += w * src.P[c];
    }
  }
};

inline Sdc::Options::VtxBoundaryInterpolation ToOsd(subd::BoundaryRule rule)
{
  switch (rule)
  {
    case subd::BoundaryRule::None:
      return Sdc::Options::VTX_BOUNDARY_NONE;
    case subd::BoundaryRule::EdgeOnly:
      return Sdc::Options::VTX_BOUNDARY_EDGE_ONLY;
    default:
      return Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER;
  }
}

enum class SchemeKind
{
  CatmullClark,
  Loop,
  Bilinear
};

inline std::unique_ptr<subd::Scheme> MakeScheme(SchemeKind kind)
{
  if (kind == SchemeKind::Loop)
    return std::make_unique<subd::LoopScheme>();
  if (kind == SchemeKind::Bilinear)
    return std::make_unique<subd::BilinearScheme>();
  return std::make_unique<subd::CatmullClarkScheme>();
}

/// Sharp features given with a fixture: crease edges as vertex pairs, corner vertices,
/// hole faces, and the crease method.
struct SharpTags
{
  std::string Label;
  std::vector<int> CreasePairs;
  std::vector<float> CreaseSharpness;
  std::vector<int> Corners;
  std::vector<float> CornerSharpness;
  std::vector<int> Holes;
  subd::CreaseMethod Method = subd::CreaseMethod::Uniform;
};

/// A face-varying channel of a fixture: a value index per face corner (in face order), two
/// numbers per value, and the interpolation mode.
struct FaceVaryingChannel
{
  std::vector<Index> ValueOfCorner;
  std::vector<double> Values;
  subd::FaceVaryingInterpolation Mode = subd::FaceVaryingInterpolation::None;
};

/// OpenSubdiv's refiner of a fixture (with `channel` as its face-varying channel 0), not
/// refined yet.
inline std::unique_ptr<Far::TopologyRefiner> CreateOsdRefiner(const subdtest::TestMesh& mesh,
  subd::BoundaryRule rule, SchemeKind kind, const SharpTags& tags, const FaceVaryingChannel* channel = nullptr,
  bool smoothTriangles = false)
{
  std::vector<int> sizes(static_cast<size_t>(mesh.NumFaces()));
  for (Index f = 0; f < mesh.NumFaces(); ++f)
  {
    sizes[f] = mesh.Offsets[f + 1] - mesh.Offsets[f];
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.NumVertices();
  desc.numFaces = mesh.NumFaces();
  desc.numVertsPerFace = sizes.data();
  desc.vertIndicesPerFace = mesh.Vertices.data();
  desc.numCreases = static_cast<int>(tags.CreaseSharpness.size());
  desc.creaseVertexIndexPairs = tags.CreasePairs.data();
  desc.creaseWeights = tags.CreaseSharpness.data();
  desc.numCorners = static_cast<int>(tags.Corners.size());
  desc.cornerVertexIndices = tags.Corners.data();
  desc.cornerWeights = tags.CornerSharpness.data();
  desc.numHoles = static_cast<int>(tags.Holes.size());
  desc.holeIndices = tags.Holes.data();
  Far::TopologyDescriptor::FVarChannel fvar;
  if (channel)
  {
    fvar.numValues = static_cast<int>(channel->Values.size() / 2);
    fvar.valueIndices = channel->ValueOfCorner.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &fvar;
  }
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(ToOsd(rule));
  if (channel)
    options.SetFVarLinearInterpolation(static_cast<Sdc::Options::FVarLinearInterpolation>(channel->Mode));
  if (smoothTriangles)
    options.SetTriangleSubdivision(Sdc::Options::TRI_SUB_SMOOTH);
  options.SetCreasingMethod(
    tags.Method == subd::CreaseMethod::Chaikin ? Sdc::Options::CREASE_CHAIKIN : Sdc::Options::CREASE_UNIFORM);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(
    Factory::Create(desc,
      Factory::Options(kind == SchemeKind::Loop
          ? Sdc::SCHEME_LOOP
          : (kind == SchemeKind::Bilinear ? Sdc::SCHEME_BILINEAR : Sdc::SCHEME_CATMARK),
        options)));
  return refiner;
}

inline std::unique_ptr<Far::TopologyRefiner> MakeOsdRefiner(const subdtest::TestMesh& mesh,
  subd::BoundaryRule rule, int levels, SchemeKind kind, const SharpTags& tags,
  const FaceVaryingChannel* channel = nullptr, bool smoothTriangles = false)
{
  std::unique_ptr<Far::TopologyRefiner> refiner = CreateOsdRefiner(mesh, rule, kind, tags, channel, smoothTriangles);
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.orderVerticesFromFacesFirst = true;
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  return refiner;
}

/// OpenSubdiv's points of `mesh` at the refiner's last level (Far::PrimvarRefinerReal<double>).
inline std::vector<Point3> OsdFinestPoints(const Far::TopologyRefiner& refiner, const subdtest::TestMesh& mesh)
{
  std::vector<Point3> all(static_cast<size_t>(refiner.GetNumVerticesTotal()));
  for (Index v = 0; v < mesh.NumVertices(); ++v)
    std::copy(&mesh.Points[3 * v], &mesh.Points[3 * v] + 3, all[v].P);
  Far::PrimvarRefinerReal<double> primvar(refiner);
  Point3* src = all.data();
  for (int l = 1; l <= refiner.GetMaxLevel(); ++l)
  {
    Point3* dst = src + refiner.GetLevel(l - 1).GetNumVertices();
    primvar.Interpolate(l, src, dst);
    src = dst;
  }
  return std::vector<Point3>(src, all.data() + all.size());
}

/// My child face that is OpenSubdiv's child k of a face whose my face is g of `parent`, its
/// corners turned by `turn` against OpenSubdiv's: the quad split has a child per corner, the
/// triangle split three corner children and the middle one.
inline Index MyChildFace(const subd::MeshTopology& parent, Index g, Index turn, Index k, bool triangles)
{
  return triangles ? 4 * g + (k == 3 ? 3 : (k + turn) % 3) : parent.GetFaceOffset(g) + (k + turn) % parent.GetFaceSize(g);
}

/// The same tags in SubD's form, for the base level of `topology`.
inline subd::BaseTags ToBaseTags(const SharpTags& tags, const subd::MeshTopology& topology)
{
  subd::BaseTags base;
  base.Creasing = tags.Method;
  base.EdgeSharpness.assign(static_cast<size_t>(topology.GetNumEdges()), 0.0f);
  for (size_t i = 0; i < tags.CreaseSharpness.size(); ++i)
  {
    const Index e = topology.FindEdge(tags.CreasePairs[2 * i], tags.CreasePairs[2 * i + 1]);
    EXPECT_NE(e, subd::InvalidIndex) << "crease " << i << " is not an edge";
    if (e != subd::InvalidIndex)
      base.EdgeSharpness[e] = tags.CreaseSharpness[i];
  }
  base.VertexSharpness.assign(static_cast<size_t>(topology.GetNumVertices()), 0.0f);
  for (size_t i = 0; i < tags.Corners.size(); ++i)
  {
    base.VertexSharpness[tags.Corners[i]] = tags.CornerSharpness[i];
  }
  base.FaceIsHole.assign(static_cast<size_t>(topology.GetNumFaces()), 0);
  for (int f : tags.Holes)
  {
    base.FaceIsHole[f] = 1;
  }
  return base;
}

}

#endif
