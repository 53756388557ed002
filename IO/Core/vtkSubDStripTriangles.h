// Private helper of SubD's writers: the triangles of triangle strips.
#ifndef vtkSubDStripTriangles_h
#define vtkSubDStripTriangles_h

#include "vtkCellArray.h"

/// Calls triangle(a, b, c) for every triangle of every strip. A strip p0 p1 p2 p3 ... is
/// (p0 p1 p2), (p2 p1 p3), ...: orientation alternates so all of them face the same way.
template <typename Triangle>
void vtkSubDForEachStripTriangle(vtkCellArray* strips, Triangle&& triangle)
{
  vtkIdType n;
  const vtkIdType* pts;
  for (strips->InitTraversal(); strips->GetNextCell(n, pts);)
  {
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      const bool even = (k % 2) == 0;
      triangle(even ? pts[k] : pts[k + 1], even ? pts[k + 1] : pts[k], pts[k + 2]);
    }
  }
}

/// The number of triangles in the strips.
inline vtkIdType vtkSubDCountStripTriangles(vtkCellArray* strips)
{
  vtkIdType count = 0;
  vtkSubDForEachStripTriangle(strips, [&count](vtkIdType, vtkIdType, vtkIdType) { ++count; });
  return count;
}

#endif
