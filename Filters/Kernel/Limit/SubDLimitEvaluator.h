// SubD kernel: exact evaluation of the Catmull-Clark and Loop limit surfaces at any
// (face, u, v), with first and second derivatives, as stencils over the control points.
//
// Method (feature-adaptive evaluation, after Niessner et al. 2012, evaluated exactly):
// - a face that is a regular patch (SubDRegularPatch.h: bicubic B-spline, with phantom
//   points along infinitely sharp creases and boundaries, or Loop's quartic box spline) is
//   evaluated in closed form (SubDPatchBasis.h);
// - any other face is refined locally (SubDLocalLevel.h) and the sample handed to the
//   child face that contains it, in that child's parameters, until the face holding it is
//   regular. Each level isolates extraordinary vertices and lets semi-sharp features decay,
//   so a sample at parameter distance d from an extraordinary vertex is reached after about
//   log2(1/d) levels;
// - a sample exactly at an extraordinary vertex (or any vertex with an irregular rule:
//   dart, crease or corner whose side is not a regular grid), or within 2^-MaxDepth of one,
//   takes the limit point and tangents from the eigenstructure of that vertex
//   (SubDVertexLimit.h). The parametrisation is singular there, so second derivatives, and
//   the curvature, are those of the centre of the vertex's sub-face 2^-CurvatureDepth
//   across (LimitStencil::CurvatureWeights); curvature at such vertices is generally not
//   continuous (it depends on the direction of approach), and this is the value one reads
//   arriving along the face's diagonal. Samples closer than that to the vertex read their
//   curvature at the same kind of point of their own sub-face of that size, and closer than
//   2^-DerivativeDepth take the vertex's tangents: below, the sub-patches are too close
//   together for derivatives in double precision. Positions stay exact.
//
// Parameters: a quad over the unit square, a triangle over the unit triangle (SubDPatchParam.h).
// A Catmull-Clark face that is not a quad is split into quads at its centre like the first
// refinement does: sub-face k is the quad at corner k, with (0,0) at the corner, (1,0) at the
// midpoint of the edge to the next corner, (1,1) at the centre (OpenSubdiv's convention for
// its Ptex faces of non-quads).
#ifndef SubDLimitEvaluator_h
#define SubDLimitEvaluator_h

#include "SubDLocalLevel.h"
#include "SubDPatchBasis.h"
#include "SubDPatchParam.h"

#include <string>
#include <vector>

namespace subd
{
struct FaceSample
{
  double U = 0.0, V = 0.0;
  Index SubFace = 0; ///< Catmull-Clark faces that are not quads: the corner's sub-face
};

/// The limit surface at one sample, as weights over control points.
struct LimitStencil
{
  std::vector<Index> Points;
  /// NumPatchDerivatives rows (PatchDerivative order) of Points.size() weights.
  std::vector<double> Weights;
  /// Empty, or at an extraordinary vertex the rows of the nearby point that curvature is
  /// read at (see above).
  std::vector<double> CurvatureWeights;

  const double* Row(int derivative) const { return Weights.data() + derivative * Points.size(); }
  /// Applies one row to `components` interleaved values per control point.
  void Apply(const std::vector<double>& rows, int derivative, const double* values, int components, double* out) const;
};

class SUBDKERNEL_EXPORT LimitEvaluator
{
public:
  /// `level` needs its full topology; `scheme` is Catmull-Clark or Loop, and no vertex may
  /// have more than MaxValence faces, no face more than MaxValence sides (else IsValid fails,
  /// naming the vertex or face).
  LimitEvaluator(const Scheme& scheme, const Level& level);

  bool IsValid(std::string& error) const;

  /// Evaluates the limit at `samples` of `face`. Returns false (with the reason) for a
  /// hole, a sample outside the face, or a face the scheme cannot evaluate. `rows`: the
  /// leading rows of each stencil wanted (PatchDerivative order: 1 the position, 3 with the
  /// first derivatives, NumPatchDerivatives all, with CurvatureWeights); the others may be 0.
  /// Fewer rows spare the curvature near an extraordinary vertex, read 2^-CurvatureDepth away
  /// (ten local refinements).
  bool EvaluateFace(Index face, const std::vector<FaceSample>& samples, std::vector<LimitStencil>& out,
    std::string& error, int rows = NumPatchDerivatives) const;

  /// Sample at corner `corner` of `face` (for a non-quad Catmull-Clark face: its sub-face's corner).
  static FaceSample CornerSample(Index faceSize, Index corner, bool quads);

  /// The most faces around one vertex the evaluator takes on. Near an irregular vertex it
  /// analyses the subdivision matrix of the vertex's neighbourhood (dense eigenvectors) and
  /// refines that neighbourhood locally for each sample: time grows with the cube of the
  /// valence and memory with its square (valence 1000 took 70 s and 2.3 GB for curvature).
  static constexpr Index MaxValence = 256;
  /// Levels of local refinement after which a sample is taken to be at the vertex it is
  /// closest to (its parameter distance is then below 2^-MaxDepth).
  static constexpr int MaxDepth = 40;
  /// Near an irregular vertex, the depth below which curvature is read at the centre of the
  /// sample's face of that depth, as at the vertex itself: the centre of the vertex's face
  /// 2^-CurvatureDepth across. Deeper, second derivatives would lose digits in double.
  static constexpr int CurvatureDepth = 10;
  /// The depth below which first derivatives are the irregular vertex's tangents (the
  /// position is still followed down to MaxDepth).
  static constexpr int DerivativeDepth = 22;

private:
  struct Pending;
  bool CheckSamples(Index face, const std::vector<FaceSample>& samples, std::string& error) const;
  bool ReadCurvatureAtCentre(const LocalLevel& local, Index face, const ParamFrame& frame, int depth, Pending& p,
    std::string& error) const;
  bool DescendIntoChildren(const LocalLevel& local, Index face, std::vector<Pending>& rest, const ParamFrame& frame,
    int depth, std::string& error) const;
  bool Descend(const LocalLevel& local, Index face, std::vector<Pending>& pending, const ParamFrame& frame,
    int depth, std::string& error) const;
  void EvaluateRegular(const LocalLevel& local, const RegularPatch& patch, const double p[2],
    const ParamFrame& frame, std::vector<double>& weights) const;
  bool EvaluateCorner(const LocalLevel& local, Index face, Index corner, const ParamFrame& frame, int depth,
    bool withCurvature, LimitStencil& out, std::string& error) const;

  const Scheme& TheScheme;
  const Level& TheLevel;
  PatchKind Kind = PatchKind::BSpline;
  bool Valid = false;
  std::string Problem;
};
}

#endif
