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
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkSubDBufferedOutput out(file); // numbers in their shortest exact form
  out << "OFF\n" << numPoints << ' ' << input->GetNumberOfPolys() + numTriangles << " 0\n";
  vtkSubDFormatInParallel(out, numPoints, [input](vtkSubDBufferedOutput& text, vtkIdType i) {
    double p[3];
    input->GetPoint(i, p);
    text << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  });
  vtkSubDFormatCellsInParallel(out, input->GetPolys(), [](vtkSubDBufferedOutput& text, const auto& pts) {
    text << pts.size();
    for (const auto id : pts)
    {
      text << ' ' << id;
    }
    text << '\n';
  });
  vtkSubDForEachStripTriangle(strips, [&out](vtkIdType a, vtkIdType b, vtkIdType c) {
    out << "3 " << a << ' ' << b << ' ' << c << '\n';
  });
}

void vtkSubDOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
