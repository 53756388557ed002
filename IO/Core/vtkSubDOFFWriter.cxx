#include "vtkSubDOFFWriter.h"

#include "vtkCellArray.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSubDStripTriangles.h"
#include "vtkSubDBufferedOutput.h"

vtkStandardNewMacro(vtkSubDOFFWriter);

void vtkSubDOFFWriter::WriteFile(vtkPolyData* input, std::ostream& file)
{
  if (input->GetNumberOfLines() + input->GetNumberOfVerts() > 0)
  {
    vtkWarningMacro("OFF holds only polygons: " << input->GetNumberOfLines() << " lines and "
                                               << input->GetNumberOfVerts() << " verts are not written.");
  }
  vtkCellArray* strips = input->GetStrips();
  const vtkIdType numTriangles = vtkSubDCountStripTriangles(strips);
  vtkIdType n;
  const vtkIdType* pts;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkSubDBufferedOutput out(file); // numbers in their shortest exact form
  out << "OFF\n" << numPoints << ' ' << input->GetNumberOfPolys() + numTriangles << " 0\n";
  double p[3];
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    input->GetPoint(i, p);
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
  {
    out << n;
    for (vtkIdType k = 0; k < n; ++k)
    {
      out << ' ' << pts[k];
    }
    out << '\n';
  }
  vtkSubDForEachStripTriangle(strips, [&out](vtkIdType a, vtkIdType b, vtkIdType c) {
    out << "3 " << a << ' ' << b << ' ' << c << '\n';
  });
}

void vtkSubDOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
