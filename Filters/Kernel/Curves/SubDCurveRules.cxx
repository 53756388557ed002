#include "SubDCurveRules.h"

#include <algorithm>

namespace subd
{
const char* ToString(CurveScheme scheme)
{
  switch (scheme)
  {
    case CurveScheme::Chaikin:
      return "Chaikin";
    case CurveScheme::CubicBSpline:
      return "CubicBSpline";
    case CurveScheme::FourPoint:
      return "FourPoint";
  }
  return "Unknown";
}

Index CurveChildCount(const CurveRules& rules, Index n, bool closed)
{
  if (n <= 1)
  {
    return n;
  }
  if (IsClosedPolygon(n, closed))
  {
    return 2 * n;
  }
  if (rules.Scheme == CurveScheme::Chaikin && n > 2)
  {
    return 2 * n - 2;
  }
  return 2 * n - 1;
}

namespace
{
// Adds w * q, where q is point k of an open polygon of n points and k may be one step past
// either end: a phantom point on the polynomial through the nearest min(n, 4) points.
void AddOpenPoint(Index k, Index n, double w, StencilRows& rows)
{
  // Extrapolation one step beyond the end by the polynomial through 2, 3 or 4 points.
  static const double extrapolation[3][4] = { { 2.0, -1.0, 0.0, 0.0 }, { 3.0, -3.0, 1.0, 0.0 },
    { 4.0, -6.0, 4.0, -1.0 } };
  if (k >= 0 && k < n)
  {
    rows.Add(k, w);
    return;
  }
  const Index used = n < 4 ? n : 4;
  const double* weights = extrapolation[used - 2];
  for (Index j = 0; j < used; ++j)
  {
    rows.Add(k < 0 ? j : n - 1 - j, w * weights[j]);
  }
}

void AddPoint(Index k, Index n, bool closed, double w, StencilRows& rows)
{
  if (closed)
  {
    rows.Add(((k % n) + n) % n, w);
  }
  else
  {
    AddOpenPoint(k, n, w, rows);
  }
}

void AppendChaikin(Index n, bool closed, StencilRows& rows)
{
  if (closed)
  {
    for (Index i = 0; i < n; ++i)
    {
      const Index next = (i + 1) % n;
      rows.Add(i, 0.75);
      rows.Add(next, 0.25);
      rows.EndRow();
      rows.Add(i, 0.25);
      rows.Add(next, 0.75);
      rows.EndRow();
    }
    return;
  }
  // Clamped quadratic B-spline: knot insertion at every span's middle (see the header).
  rows.Add(0, 1.0);
  rows.EndRow();
  rows.Add(0, 0.5);
  rows.Add(1, 0.5);
  rows.EndRow();
  for (Index i = 1; i + 2 < n; ++i)
  {
    rows.Add(i, 0.75);
    rows.Add(i + 1, 0.25);
    rows.EndRow();
    rows.Add(i, 0.25);
    rows.Add(i + 1, 0.75);
    rows.EndRow();
  }
  if (n > 2)
  {
    rows.Add(n - 2, 0.5);
    rows.Add(n - 1, 0.5);
    rows.EndRow();
  }
  rows.Add(n - 1, 1.0);
  rows.EndRow();
}

void AppendCubicBSpline(Index n, bool closed, StencilRows& rows)
{
  const Index edges = closed ? n : n - 1;
  for (Index i = 0; i < n; ++i)
  {
    if (!closed && (i == 0 || i == n - 1))
    {
      rows.Add(i, 1.0);
    }
    else
    {
      AddPoint(i - 1, n, closed, 0.125, rows);
      rows.Add(i, 0.75);
      AddPoint(i + 1, n, closed, 0.125, rows);
    }
    rows.EndRow();
    if (i < edges)
    {
      rows.Add(i, 0.5);
      AddPoint(i + 1, n, closed, 0.5, rows);
      rows.EndRow();
    }
  }
}

void AppendFourPoint(Index n, bool closed, double w, StencilRows& rows)
{
  const Index edges = closed ? n : n - 1;
  for (Index i = 0; i < n; ++i)
  {
    rows.Add(i, 1.0);
    rows.EndRow();
    if (i < edges)
    {
      AddPoint(i - 1, n, closed, -w, rows);
      AddPoint(i, n, closed, 0.5 + w, rows);
      AddPoint(i + 1, n, closed, 0.5 + w, rows);
      AddPoint(i + 2, n, closed, -w, rows);
      rows.EndRow();
    }
  }
}
}

void AppendCurveChildRows(const CurveRules& rules, Index n, bool closed, StencilRows& rows)
{
  if (n <= 0)
  {
    return;
  }
  if (n == 1)
  {
    rows.Add(0, 1.0);
    rows.EndRow();
    return;
  }
  closed = IsClosedPolygon(n, closed);
  switch (rules.Scheme)
  {
    case CurveScheme::Chaikin:
      AppendChaikin(n, closed, rows);
      break;
    case CurveScheme::CubicBSpline:
      AppendCubicBSpline(n, closed, rows);
      break;
    case CurveScheme::FourPoint:
      AppendFourPoint(n, closed, rules.Tension, rows);
      break;
  }
}
}
