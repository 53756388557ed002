#include "SubDSurfaceGeometry.h"

#include <algorithm>
#include <cmath>

namespace subd
{
namespace
{
double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
void Cross(const double a[3], const double b[3], double out[3])
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}
bool Normalize(double v[3])
{
  const double length = std::sqrt(Dot(v, v));
  if (!(length > 0.0) || !std::isfinite(length))
  {
    return false;
  }
  v[0] /= length;
  v[1] /= length;
  v[2] /= length;
  return true;
}
}

SurfaceGeometry ComputeSurfaceGeometry(const double d[6][3], const double c[6][3])
{
  SurfaceGeometry g;
  Cross(d[1], d[2], g.Normal);
  if (!Normalize(g.Normal))
  {
    return g;
  }
  // Curvature from the curvature point's own frame.
  double n[3];
  Cross(c[1], c[2], n);
  if (!Normalize(n))
  {
    return g;
  }
  const double E = Dot(c[1], c[1]), F = Dot(c[1], c[2]), G = Dot(c[2], c[2]);
  const double L = Dot(c[3], n), M = Dot(c[4], n), N = Dot(c[5], n);
  const double det = E * G - F * F;
  if (!(det > 0.0))
  {
    return g;
  }
  g.Regular = true;
  g.Gaussian = (L * N - M * M) / det;
  g.Mean = -(E * N - 2.0 * F * M + G * L) / (2.0 * det);
  const double root = std::sqrt(std::max(0.0, g.Mean * g.Mean - g.Gaussian));
  g.Maximum = g.Mean + root;
  g.Minimum = g.Mean - root;
  // Shape operator S = -I^-1 II in (du, dv); its eigenvector for k1.
  const double s00 = -(G * L - F * M) / det, s01 = -(G * M - F * N) / det;
  const double s10 = -(E * M - F * L) / det, s11 = -(E * N - F * M) / det;
  double x[2] = { s01, g.Maximum - s00 };
  const double y[2] = { g.Maximum - s11, s10 };
  if (x[0] * x[0] + x[1] * x[1] < y[0] * y[0] + y[1] * y[1])
  {
    x[0] = y[0];
    x[1] = y[1];
  }
  double* dir = g.MaximumDirection;
  for (int k = 0; k < 3; ++k)
  {
    dir[k] = x[0] * c[1][k] + x[1] * c[2][k];
  }
  if (!Normalize(dir))
  {
    // Umbilic: every direction is principal.
    for (int k = 0; k < 3; ++k)
    {
      dir[k] = c[1][k];
    }
    Normalize(dir);
  }
  Cross(n, dir, g.MinimumDirection);
  Normalize(g.MinimumDirection);
  return g;
}
}
