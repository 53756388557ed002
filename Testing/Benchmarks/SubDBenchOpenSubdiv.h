// Benchmark helper: OpenSubdiv's uniform refinement of a bench mesh (Far::TopologyRefiner and
// PrimvarRefinerReal<double>), topology and points timed together as SubD's filters are, with
// SubD's default boundary rule (edge only).
#ifndef SubDBenchOpenSubdiv_h
#define SubDBenchOpenSubdiv_h

#include "SubDBenchSupport.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <memory>
#include <utility>
#include <vector>

namespace subdbench
{
struct OsdPoint
{
  double P[3];
  void Clear() { P[0] = P[1] = P[2] = 0; }
  void AddWithWeight(const OsdPoint& s, double w)
  {
    for (int c = 0; c < 3; ++c)
      P[c] += w * s.P[c];
  }
};

/// Seconds and output faces of `level` levels of `scheme` (SCHEME_CATMARK, SCHEME_LOOP).
inline Work RunOpenSubdiv(const BenchMesh& mesh, int level, OpenSubdiv::Sdc::SchemeType scheme)
{
  using namespace OpenSubdiv;
  const Clock::time_point start = Clock::now();
  Far::TopologyDescriptor desc;
  desc.numVertices = mesh.NumVertices();
  desc.numFaces = static_cast<int>(mesh.Sizes.size());
  desc.numVertsPerFace = mesh.Sizes.data();
  desc.vertIndicesPerFace = mesh.Corners.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, options)));
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(level));
  std::vector<OsdPoint> buffer(static_cast<size_t>(refiner->GetNumVerticesTotal()));
  for (int v = 0; v < mesh.NumVertices(); ++v)
    for (int c = 0; c < 3; ++c)
      buffer[v].P[c] = mesh.Points[3 * v + c];
  Far::PrimvarRefinerReal<double> primvar(*refiner);
  OsdPoint* src = buffer.data();
  for (int l = 1; l <= level; ++l)
  {
    OsdPoint* dst = src + refiner->GetLevel(l - 1).GetNumVertices();
    primvar.Interpolate(l, src, dst);
    src = dst;
  }
  return { SecondsSince(start), double(refiner->GetLevel(level).GetNumFaces()) };
}
}

#endif
