// SubD kernel: the parametrisation of faces and of their children, for limit evaluation.
//
// A quad is parametrised over the unit square, corners 0..3 at (0,0), (1,0), (1,1), (0,1); a
// triangle over the unit triangle, corners at (0,0), (1,0), (0,1) (OpenSubdiv's Ptex
// conventions for Catmull-Clark and Loop). A child face of the quad or triangle split
// (SubDQuadSplit.h, SubDTriangleSplit.h) is parametrised the same way from its own first
// corner, so a parent point p lies in child c at p = Origin + Axes * (u', v').
#ifndef SubDPatchParam_h
#define SubDPatchParam_h

#include "SubDTypes.h"

#include <cmath>

namespace subd
{
/// An affine map from a face's parameters to those of the face it descends from.
struct ParamFrame
{
  double Origin[2] = { 0.0, 0.0 };
  double Axes[2][2] = { { 1.0, 0.0 }, { 0.0, 1.0 } }; ///< Axes[r][c]: column c is the image of unit c

  void Map(const double local[2], double out[2]) const
  {
    out[0] = Origin[0] + Axes[0][0] * local[0] + Axes[0][1] * local[1];
    out[1] = Origin[1] + Axes[1][0] * local[0] + Axes[1][1] * local[1];
  }
  /// Local parameters of a point given in this frame's target.
  void Unmap(const double p[2], double local[2]) const
  {
    const double det = Axes[0][0] * Axes[1][1] - Axes[0][1] * Axes[1][0];
    const double d0 = p[0] - Origin[0], d1 = p[1] - Origin[1];
    local[0] = (Axes[1][1] * d0 - Axes[0][1] * d1) / det;
    local[1] = (-Axes[1][0] * d0 + Axes[0][0] * d1) / det;
  }
  /// This frame followed by `inner` (a frame of a child of this frame's face).
  ParamFrame Then(const ParamFrame& inner) const
  {
    ParamFrame out;
    this->Map(inner.Origin, out.Origin);
    for (int r = 0; r < 2; ++r)
    {
      for (int c = 0; c < 2; ++c)
      {
        out.Axes[r][c] = this->Axes[r][0] * inner.Axes[0][c] + this->Axes[r][1] * inner.Axes[1][c];
      }
    }
    return out;
  }
};

/// Parameters of corner `corner` of a quad (`size` 4) or triangle (`size` 3).
inline void CornerParam(Index size, Index corner, double out[2])
{
  static const double quad[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  static const double tri[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  const double* c = size == 4 ? quad[corner] : tri[corner];
  out[0] = c[0];
  out[1] = c[1];
}

/// The frame of child `child` of a quad (4 children) or triangle (4, the last the middle
/// one) in its parent's parameters.
inline ParamFrame ChildFrame(Index size, Index child)
{
  double q0[2], q1[2], q2[2];
  auto mid = [size](Index a, Index b, double out[2]) {
    double pa[2], pb[2];
    CornerParam(size, a % size, pa);
    CornerParam(size, b % size, pb);
    out[0] = 0.5 * (pa[0] + pb[0]);
    out[1] = 0.5 * (pa[1] + pb[1]);
  };
  if (size == 3 && child == 3)
  {
    mid(0, 1, q0);
    mid(1, 2, q1);
    mid(2, 0, q2);
  }
  else
  {
    CornerParam(size, child, q0);
    mid(child, child + 1, q1);
    mid(child, child + size - 1, q2);
  }
  ParamFrame frame;
  frame.Origin[0] = q0[0];
  frame.Origin[1] = q0[1];
  for (int r = 0; r < 2; ++r)
  {
    frame.Axes[r][0] = q1[r] - q0[r];
    frame.Axes[r][1] = q2[r] - q0[r];
  }
  return frame;
}

/// True if (u, v) lies in the quad's unit square or the triangle's unit triangle, within tol.
inline bool InsideFace(Index size, const double p[2], double tol)
{
  if (p[0] < -tol || p[1] < -tol)
  {
    return false;
  }
  return size == 4 ? (p[0] <= 1.0 + tol && p[1] <= 1.0 + tol) : (p[0] + p[1] <= 1.0 + tol);
}
}

#endif
