#include "SubDLimitEvaluator.h"

#include "SubDVertexLimit.h"

#include <algorithm>
#include <cmath>

namespace subd
{
namespace
{
// Rewrites derivative rows given in a face's local parameters into the root parameters,
// root = frame(local): with A = Axes^-1, D_root = A^T D_local and H_root = A^T H_local A.
void ToRootParameters(const ParamFrame& frame, double* rows, size_t n)
{
  const double det = frame.Axes[0][0] * frame.Axes[1][1] - frame.Axes[0][1] * frame.Axes[1][0];
  const double A[2][2] = { { frame.Axes[1][1] / det, -frame.Axes[0][1] / det },
    { -frame.Axes[1][0] / det, frame.Axes[0][0] / det } };
  double* du = rows + PatchDu * n;
  double* dv = rows + PatchDv * n;
  double* duu = rows + PatchDuu * n;
  double* duv = rows + PatchDuv * n;
  double* dvv = rows + PatchDvv * n;
  for (size_t i = 0; i < n; ++i)
  {
    const double g[2] = { du[i], dv[i] };
    du[i] = A[0][0] * g[0] + A[1][0] * g[1];
    dv[i] = A[0][1] * g[0] + A[1][1] * g[1];
    const double H[2][2] = { { duu[i], duv[i] }, { duv[i], dvv[i] } };
    double out[2][2];
    for (int r = 0; r < 2; ++r)
    {
      for (int c = 0; c < 2; ++c)
      {
        double sum = 0.0;
        for (int a = 0; a < 2; ++a)
        {
          for (int b = 0; b < 2; ++b)
          {
            sum += A[a][r] * H[a][b] * A[b][c];
          }
        }
        out[r][c] = sum;
      }
    }
    duu[i] = out[0][0];
    duv[i] = out[0][1];
    dvv[i] = out[1][1];
  }
}

// The corner of a face at local parameters p (within tol), or InvalidIndex.
Index CornerAt(Index size, const double p[2], double tol)
{
  for (Index k = 0; k < size; ++k)
  {
    double c[2];
    CornerParam(size, k, c);
    if (std::abs(c[0] - p[0]) <= tol && std::abs(c[1] - p[1]) <= tol)
    {
      return k;
    }
  }
  return InvalidIndex;
}
}

struct LimitEvaluator::Pending
{
  double Local[2];
  LimitStencil* Out;
  bool ForCurvature; ///< the nearby point of an extraordinary vertex: no nearby point of its own
  int Rows;          ///< rows still to be written by the patch that holds the sample (6, 3 or 1)
};

void LimitStencil::Apply(const std::vector<double>& rows, int derivative, const double* values, int components,
  double* out) const
{
  const size_t n = this->Points.size();
  const double* w = rows.data() + derivative * n;
  std::fill_n(out, components, 0.0);
  for (size_t i = 0; i < n; ++i)
  {
    const double* value = values + static_cast<size_t>(this->Points[i]) * components;
    for (int c = 0; c < components; ++c)
    {
      out[c] += w[i] * value[c];
    }
  }
}

LimitEvaluator::LimitEvaluator(const Scheme& scheme, const Level& level)
  : TheScheme(scheme)
  , TheLevel(level)
{
  const std::string name = scheme.GetName();
  if (name == "catmull-clark" || name == "loop")
  {
    this->Kind = name == "loop" ? PatchKind::BoxSpline : PatchKind::BSpline;
    this->Valid = level.Topology.HasEdges() && !level.EdgeSharpness.empty();
    this->Problem = this->Valid ? "" : "the level has no edges (refined with faces only)";
    for (Index v = 0; this->Valid && v < level.Topology.GetNumVertices(); ++v)
    {
      const Index valence = level.Topology.GetVertexFaces(v).size();
      if (valence > MaxValence)
      {
        this->Valid = false;
        this->Problem = "vertex " + std::to_string(v) + " has " + std::to_string(valence) +
          " faces around it; the exact limit is evaluated near vertices of at most " + std::to_string(MaxValence);
      }
    }
    // A Catmull-Clark face of n sides becomes a vertex of valence n once split.
    for (Index f = 0; this->Valid && f < level.Topology.GetNumFaces(); ++f)
    {
      if (level.Topology.GetFaceSize(f) > MaxValence)
      {
        this->Valid = false;
        this->Problem = "face " + std::to_string(f) + " has " + std::to_string(level.Topology.GetFaceSize(f)) +
          " sides; the exact limit is evaluated near faces and vertices of at most " + std::to_string(MaxValence);
      }
    }
  }
  else
  {
    this->Problem = std::string("the ") + name + " scheme has no exact limit evaluation (Catmull-Clark and Loop do)";
  }
}

bool LimitEvaluator::IsValid(std::string& error) const
{
  error = this->Problem;
  return this->Valid;
}

FaceSample LimitEvaluator::CornerSample(Index faceSize, Index corner, bool quads)
{
  FaceSample sample;
  if (quads && faceSize != 4)
  {
    sample.SubFace = corner;
    return sample;
  }
  double c[2];
  CornerParam(faceSize, corner, c);
  sample.U = c[0];
  sample.V = c[1];
  return sample;
}

namespace
{
// The stencils of samples in a regular patch: its basis over its points (a phantom point's
// weights spread over the points it is made of).
void RegularPatchStencils(
  PatchKind kind, const RegularPatch& patch, const std::vector<FaceSample>& samples, std::vector<LimitStencil>& out)
{
  std::vector<Index> points;
  for (int i = 0; i < patch.NumPoints; ++i)
  {
    for (int k = 0; k < patch.Points[i].Count; ++k)
    {
      if (std::find(points.begin(), points.end(), patch.Points[i].Points[k]) == points.end())
      {
        points.push_back(patch.Points[i].Points[k]);
      }
    }
  }
  const size_t n = points.size();
  for (size_t s = 0; s < samples.size(); ++s)
  {
    double basis[NumPatchDerivatives][16];
    EvaluatePatchBasis(kind, samples[s].U, samples[s].V, basis);
    LimitStencil& stencil = out[s];
    stencil.Points = points;
    stencil.Weights.assign(NumPatchDerivatives * n, 0.0);
    for (int i = 0; i < patch.NumPoints; ++i)
    {
      const PatchPoint& pp = patch.Points[i];
      for (int k = 0; k < pp.Count; ++k)
      {
        const size_t slot = std::find(points.begin(), points.end(), pp.Points[k]) - points.begin();
        for (int d = 0; d < NumPatchDerivatives; ++d)
        {
          stencil.Weights[d * n + slot] += basis[d][i] * pp.Weights[k];
        }
      }
    }
  }
}
}

bool LimitEvaluator::CheckSamples(Index face, const std::vector<FaceSample>& samples, std::string& error) const
{
  const MeshTopology& topo = this->TheLevel.Topology;
  if (face < 0 || face >= topo.GetNumFaces())
  {
    error = "face " + std::to_string(face) + " does not exist (the mesh has " + std::to_string(topo.GetNumFaces()) +
      " faces)";
    return false;
  }
  if (!this->TheLevel.FaceIsHole.empty() && this->TheLevel.FaceIsHole[face])
  {
    error = "face " + std::to_string(face) + " is a hole: it has no limit surface";
    return false;
  }
  const Index size = topo.GetFaceSize(face);
  const bool quads = this->Kind == PatchKind::BSpline;
  if (!quads && size != 3)
  {
    error = "face " + std::to_string(face) + " has " + std::to_string(size) + " sides; Loop needs triangles";
    return false;
  }
  const bool splitFirst = quads && size != 4;
  const Index paramSize = quads ? 4 : 3;
  for (const FaceSample& s : samples)
  {
    const double p[2] = { s.U, s.V };
    if (!std::isfinite(s.U) || !std::isfinite(s.V) || !InsideFace(paramSize, p, 1e-9) ||
      (splitFirst && (s.SubFace < 0 || s.SubFace >= size)))
    {
      error = "sample (" + std::to_string(s.U) + ", " + std::to_string(s.V) + (splitFirst ? ", sub-face " +
        std::to_string(s.SubFace) : std::string()) + ") is outside face " + std::to_string(face);
      return false;
    }
  }
  return true;
}

bool LimitEvaluator::EvaluateFace(Index face, const std::vector<FaceSample>& samples, std::vector<LimitStencil>& out,
  std::string& error, int rows) const
{
  rows = std::max(1, std::min(rows, static_cast<int>(NumPatchDerivatives)));
  out.assign(samples.size(), LimitStencil());
  if (!this->IsValid(error))
  {
    return false;
  }
  if (!this->CheckSamples(face, samples, error))
  {
    return false;
  }
  const Index size = this->TheLevel.Topology.GetFaceSize(face);
  const bool splitFirst = this->Kind == PatchKind::BSpline && size != 4;

  // Regular faces: the patch, straight from the level.
  RegularPatch patch;
  if (!splitFirst && GatherRegularPatch(this->TheLevel, face, this->Kind, patch))
  {
    RegularPatchStencils(this->Kind, patch, samples, out);
    return true;
  }

  std::vector<Index> support;
  const LocalLevel local = ExtractLocalLevel(this->TheLevel, face, support);
  for (LimitStencil& stencil : out)
  {
    stencil.Points = support;
    stencil.Weights.assign(NumPatchDerivatives * support.size(), 0.0);
  }
  if (!splitFirst)
  {
    std::vector<Pending> pending;
    for (size_t s = 0; s < samples.size(); ++s)
    {
      pending.push_back({ { samples[s].U, samples[s].V }, &out[s], false, rows });
    }
    return this->Descend(local, 0, pending, ParamFrame(), 0, error);
  }
  // A polygon: its sub-faces are the children of the first refinement.
  const LocalLevel refined = RefineLocalLevel(this->TheScheme, local);
  for (Index k = 0; k < size; ++k)
  {
    std::vector<Pending> pending;
    for (size_t s = 0; s < samples.size(); ++s)
    {
      if (samples[s].SubFace == k)
      {
        pending.push_back({ { samples[s].U, samples[s].V }, &out[s], false, rows });
      }
    }
    if (!pending.empty())
    {
      const LocalLevel child = ExtractLocalLevel(refined, ChildFace(local.Mesh, 0, k, false));
      if (!this->Descend(child, 0, pending, ParamFrame(), 1, error))
      {
        return false;
      }
    }
  }
  return true;
}

namespace
{
// The children of `face` in the order a sample on the border of several goes to the first:
// those at an irregular corner last, so that it lands in a regular patch sooner (the surface
// is the same on both sides of a border inside a face).
std::vector<Index> ChildOrder(const Level& level, Index face, Index size, PatchKind kind)
{
  std::vector<Index> children, irregular;
  for (Index child = 0; child < 4; ++child)
  {
    const bool atIrregularCorner = child < size && !IsRegularCorner(level, face, child, kind);
    (atIrregularCorner ? irregular : children).push_back(child);
  }
  children.insert(children.end(), irregular.begin(), irregular.end());
  return children;
}
}

bool LimitEvaluator::Descend(const LocalLevel& local, Index face, std::vector<Pending>& pending,
  const ParamFrame& frame, int depth, std::string& error) const
{
  const Index size = this->Kind == PatchKind::BSpline ? 4 : 3;
  const size_t n = static_cast<size_t>(local.SupportSize);
  // Writes the first `rows` rows of `from` into the sample's stencil.
  auto keep = [n](const std::vector<double>& from, int rows, LimitStencil& to) {
    std::copy(from.begin(), from.begin() + rows * n, to.Weights.begin());
  };
  RegularPatch patch;
  if (GatherRegularPatch(local.Mesh, face, this->Kind, patch))
  {
    std::vector<double> weights(NumPatchDerivatives * n);
    for (Pending& p : pending)
    {
      this->EvaluateRegular(local, patch, p.Local, frame, weights);
      keep(weights, p.Rows, *p.Out);
    }
    return true;
  }
  // Samples at a vertex that stays irregular: its eigenstructure.
  std::vector<Pending> rest;
  for (Pending& p : pending)
  {
    Index corner = CornerAt(size, p.Local, 1e-12);
    const bool deepest = depth >= MaxDepth;
    if (corner == InvalidIndex && (deepest || (depth == DerivativeDepth && p.Rows > 1)))
    {
      // The irregular corner nearest the sample.
      double best = 2.0;
      for (Index k = 0; k < size; ++k)
      {
        double c[2];
        CornerParam(size, k, c);
        const double d = std::max(std::abs(c[0] - p.Local[0]), std::abs(c[1] - p.Local[1]));
        if (d < best && !IsRegularCorner(local.Mesh, face, k, this->Kind))
        {
          best = d;
          corner = k;
        }
      }
      if (!deepest && corner != InvalidIndex && IsStableCorner(local.Mesh, face, corner, size))
      {
        // The patches this deep are too close together for derivatives in double: take the
        // vertex's tangents, and go on for the position only.
        LimitStencil vertex;
        vertex.Points = p.Out->Points;
        vertex.Weights.assign(p.Out->Weights.size(), 0.0);
        if (!this->EvaluateCorner(local, face, corner, frame, depth, false, vertex, error))
        {
          return false;
        }
        std::copy(vertex.Weights.begin() + PatchDu * n, vertex.Weights.begin() + PatchDuu * n,
          p.Out->Weights.begin() + PatchDu * n);
        p.Rows = 1;
        corner = InvalidIndex;
      }
    }
    if (corner != InvalidIndex && !IsRegularCorner(local.Mesh, face, corner, this->Kind) &&
      IsStableCorner(local.Mesh, face, corner, size))
    {
      LimitStencil vertex;
      vertex.Points = p.Out->Points;
      vertex.Weights.assign(p.Out->Weights.size(), 0.0);
      const bool withCurvature = !p.ForCurvature && p.Rows == NumPatchDerivatives;
      if (!this->EvaluateCorner(local, face, corner, frame, depth, withCurvature, vertex, error))
      {
        return false;
      }
      keep(vertex.Weights, p.Rows, *p.Out);
      if (withCurvature)
      {
        p.Out->CurvatureWeights = std::move(vertex.CurvatureWeights);
      }
      continue;
    }
    if (depth >= MaxDepth + 16)
    {
      error = "the limit near vertex " + std::to_string(local.Mesh.Topology.GetFaceVertices(face)[0]) +
        " could not be evaluated (no regular patch after " + std::to_string(depth) + " levels)";
      return false;
    }
    if (depth == CurvatureDepth && !p.ForCurvature && p.Rows == NumPatchDerivatives &&
      !this->ReadCurvatureAtCentre(local, face, frame, depth, p, error))
    {
      return false;
    }
    rest.push_back(p);
  }
  if (rest.empty())
  {
    return true;
  }
  return this->DescendIntoChildren(local, face, rest, frame, depth, error);
}

// Within 2^-CurvatureDepth of an irregular vertex, curvature is read at the centre of this
// face, as at the vertex itself (EvaluateCorner): the sample's second derivatives and curvature
// rows from there; its first rows are still to be written.
bool LimitEvaluator::ReadCurvatureAtCentre(const LocalLevel& local, Index face, const ParamFrame& frame, int depth,
  Pending& p, std::string& error) const
{
  const Index size = this->Kind == PatchKind::BSpline ? 4 : 3;
  const size_t n = static_cast<size_t>(local.SupportSize);
  const double centre[2] = { size == 4 ? 0.5 : 1.0 / 3.0, size == 4 ? 0.5 : 1.0 / 3.0 };
  LimitStencil nearby;
  nearby.Points = p.Out->Points;
  nearby.Weights.assign(p.Out->Weights.size(), 0.0);
  std::vector<Pending> aux{ { { centre[0], centre[1] }, &nearby, true, NumPatchDerivatives } };
  if (!this->Descend(local, face, aux, frame, depth, error))
  {
    return false;
  }
  std::copy(nearby.Weights.begin() + PatchDuu * n, nearby.Weights.end(), p.Out->Weights.begin() + PatchDuu * n);
  p.Out->CurvatureWeights = std::move(nearby.Weights);
  p.Rows = 3;
  return true;
}

// Refines the face's neighbourhood once and hands each sample to the child face that holds
// it, in the child's parameters.
bool LimitEvaluator::DescendIntoChildren(const LocalLevel& local, Index face, std::vector<Pending>& rest,
  const ParamFrame& frame, int depth, std::string& error) const
{
  const Index size = this->Kind == PatchKind::BSpline ? 4 : 3;
  const LocalLevel refined = RefineLocalLevel(this->TheScheme, local);
  std::vector<bool> placed(rest.size(), false);
  for (Index child : ChildOrder(local.Mesh, face, size, this->Kind))
  {
    const ParamFrame childFrame = ChildFrame(size, child);
    std::vector<Pending> inside;
    for (size_t i = 0; i < rest.size(); ++i)
    {
      double q[2];
      childFrame.Unmap(rest[i].Local, q);
      if (!placed[i] && InsideFace(size, q, 1e-12))
      {
        placed[i] = true;
        inside.push_back({ { q[0], q[1] }, rest[i].Out, rest[i].ForCurvature, rest[i].Rows });
      }
    }
    if (inside.empty())
    {
      continue;
    }
    const LocalLevel childLocal =
      ExtractLocalLevel(refined, ChildFace(local.Mesh, face, child, this->Kind == PatchKind::BoxSpline));
    if (!this->Descend(childLocal, 0, inside, frame.Then(childFrame), depth + 1, error))
    {
      return false;
    }
  }
  return true;
}

void LimitEvaluator::EvaluateRegular(const LocalLevel& local, const RegularPatch& patch, const double p[2],
  const ParamFrame& frame, std::vector<double>& weights) const
{
  double basis[NumPatchDerivatives][16];
  EvaluatePatchBasis(this->Kind, p[0], p[1], basis);
  const size_t n = static_cast<size_t>(local.SupportSize);
  std::fill(weights.begin(), weights.end(), 0.0);
  for (int i = 0; i < patch.NumPoints; ++i)
  {
    const PatchPoint& pp = patch.Points[i];
    for (int k = 0; k < pp.Count; ++k)
    {
      const double* support = local.GetWeights(pp.Points[k]);
      for (int d = 0; d < NumPatchDerivatives; ++d)
      {
        const double w = basis[d][i] * pp.Weights[k];
        double* row = weights.data() + d * n;
        for (size_t s = 0; s < n; ++s)
        {
          row[s] += w * support[s];
        }
      }
    }
  }
  ToRootParameters(frame, weights.data(), n);
}

bool LimitEvaluator::EvaluateCorner(const LocalLevel& local, Index face, Index corner, const ParamFrame& frame,
  int depth, bool withCurvature, LimitStencil& out, std::string& error) const
{
  const Index size = this->Kind == PatchKind::BSpline ? 4 : 3;
  VertexLimit vertex;
  if (!ComputeVertexLimit(this->TheScheme, local.Mesh, face, corner, vertex, error))
  {
    return false;
  }
  // Second derivatives (and curvature) from a point just inside the face.
  LimitStencil nearby;
  nearby.Points = out.Points;
  nearby.Weights.assign(out.Weights.size(), 0.0);
  double c[2], centre[2] = { size == 4 ? 0.5 : 1.0 / 3.0, size == 4 ? 0.5 : 1.0 / 3.0 };
  CornerParam(size, corner, c);
  const double delta = std::ldexp(1.0, -CurvatureDepth);
  std::vector<Pending> aux{ { { c[0] + delta * (centre[0] - c[0]), c[1] + delta * (centre[1] - c[1]) }, &nearby,
    true, NumPatchDerivatives } };
  if (withCurvature && !this->Descend(local, face, aux, frame, depth, error))
  {
    return false;
  }

  // Position and tangents in the local parameters: the edge to the next corner runs along
  // dn, the edge to the previous one along dp, so T_next = dn.u Du + dn.v Dv, and so on.
  double cn[2], cp[2];
  CornerParam(size, (corner + 1) % size, cn);
  CornerParam(size, (corner + size - 1) % size, cp);
  const double dn[2] = { cn[0] - c[0], cn[1] - c[1] }, dp[2] = { cp[0] - c[0], cp[1] - c[1] };
  const double det = dn[0] * dp[1] - dn[1] * dp[0];
  const size_t n = static_cast<size_t>(local.SupportSize);
  std::vector<double>& w = out.Weights;
  std::fill(w.begin(), w.end(), 0.0);
  for (size_t i = 0; i < vertex.Points.size(); ++i)
  {
    const double* support = local.GetWeights(vertex.Points[i]);
    const double tn = vertex.TangentNext[i], tp = vertex.TangentPrevious[i];
    const double du = (dp[1] * tn - dn[1] * tp) / det;
    const double dv = (-dp[0] * tn + dn[0] * tp) / det;
    for (size_t s = 0; s < n; ++s)
    {
      w[PatchValue * n + s] += vertex.Position[i] * support[s];
      w[PatchDu * n + s] += du * support[s];
      w[PatchDv * n + s] += dv * support[s];
    }
  }
  // Only the first derivatives are rewritten here; the nearby point's rows are in root
  // parameters already.
  std::vector<double> firstOnly(w.begin(), w.end());
  ToRootParameters(frame, firstOnly.data(), n);
  std::copy(firstOnly.begin() + PatchDu * n, firstOnly.begin() + PatchDuu * n, w.begin() + PatchDu * n);
  std::copy(nearby.Weights.begin() + PatchDuu * n, nearby.Weights.end(), w.begin() + PatchDuu * n);
  if (withCurvature)
  {
    out.CurvatureWeights = std::move(nearby.Weights);
  }
  return true;
}
}
