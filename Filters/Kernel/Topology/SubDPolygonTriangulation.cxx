#include "SubDPolygonTriangulation.h"

#include <cmath>

namespace subd
{
namespace
{
void Fan(Index n, std::vector<Index>& triangles)
{
  for (Index k = 1; k + 1 < n; ++k)
  {
    triangles.insert(triangles.end(), { 0, k, k + 1 });
  }
}

double Cross(const double* a, const double* b, const double* c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// True if p lies inside or on triangle abc (counter-clockwise).
bool InTriangle(const double* a, const double* b, const double* c, const double* p)
{
  return Cross(a, b, p) >= 0 && Cross(b, c, p) >= 0 && Cross(c, a, p) >= 0;
}
}

bool TriangulatePolygon(const double* xyz, Index n, std::vector<Index>& triangles)
{
  if (n == 3 || n > EarClippingLimit)
  {
    Fan(n, triangles);
    return n == 3;
  }
  // Newell normal; project onto the plane of its two smaller components, oriented so that
  // the polygon runs counter-clockwise in 2D.
  double normal[3] = { 0, 0, 0 };
  for (Index i = 0; i < n; ++i)
  {
    const double* p = xyz + 3 * i;
    const double* q = xyz + 3 * ((i + 1) % n);
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  int drop = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::abs(normal[k]) > std::abs(normal[drop]))
    {
      drop = k;
    }
  }
  if (normal[drop] == 0.0)
  {
    Fan(n, triangles);
    return false;
  }
  int u = (drop + 1) % 3, v = (drop + 2) % 3;
  if (normal[drop] < 0)
  {
    std::swap(u, v);
  }
  std::vector<double> flat(2 * static_cast<size_t>(n));
  for (Index i = 0; i < n; ++i)
  {
    flat[2 * i] = xyz[3 * i + u];
    flat[2 * i + 1] = xyz[3 * i + v];
  }

  std::vector<Index> remaining(static_cast<size_t>(n));
  for (Index i = 0; i < n; ++i)
  {
    remaining[i] = i;
  }
  const size_t start = triangles.size();
  while (remaining.size() > 3)
  {
    const Index m = static_cast<Index>(remaining.size());
    bool clipped = false;
    for (Index i = 0; i < m && !clipped; ++i)
    {
      const Index a = remaining[(i + m - 1) % m], b = remaining[i], c = remaining[(i + 1) % m];
      const double* pa = &flat[2 * a];
      const double* pb = &flat[2 * b];
      const double* pc = &flat[2 * c];
      if (Cross(pa, pb, pc) <= 0)
      {
        continue; // reflex or flat corner
      }
      bool empty = true;
      for (Index k = 0; k < m && empty; ++k)
      {
        const Index r = remaining[k];
        if (r != a && r != b && r != c)
        {
          empty = !InTriangle(pa, pb, pc, &flat[2 * r]);
        }
      }
      if (empty)
      {
        triangles.insert(triangles.end(), { a, b, c });
        remaining.erase(remaining.begin() + i);
        clipped = true;
      }
    }
    if (!clipped)
    {
      triangles.resize(start);
      Fan(n, triangles);
      return false;
    }
  }
  triangles.insert(triangles.end(), { remaining[0], remaining[1], remaining[2] });
  return true;
}
}
