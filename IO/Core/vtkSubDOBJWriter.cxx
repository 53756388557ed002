#include "vtkSubDOBJWriter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSubDStripTriangles.h"
#include "vtkSubDBufferedOutput.h"

#include <vector>

vtkStandardNewMacro(vtkSubDOBJWriter);

void vtkSubDOBJWriter::WriteFile(vtkPolyData* input, std::ostream& file)
{
  vtkSubDBufferedOutput out(file); // numbers in their shortest exact form
  out << "# written by SubD (sharp features as OpenSubdiv tags, 0-based)\n";
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkSubDFormatInParallel(out, numPoints, [input](vtkSubDBufferedOutput& text, vtkIdType i) {
    double p[3];
    input->GetPoint(i, p);
    text << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  });

  // Faces: polygons then strip triangles; holes are numbered among them.
  vtkCellArray* polys = input->GetPolys();
  vtkSubDFormatCellsInParallel(out, polys, [](vtkSubDBufferedOutput& text, const auto& pts) {
    text << 'f';
    for (const auto id : pts)
    {
      text << ' ' << id + 1;
    }
    text << '\n';
  });
  std::vector<vtkIdType> holeFaces;
  if (vtkDataArray* holes = input->GetCellData()->GetArray("Hole"))
  {
    const vtkIdType firstPolyCell = input->GetNumberOfVerts() + input->GetNumberOfLines();
    for (vtkIdType face = 0; face < polys->GetNumberOfCells(); ++face)
    {
      if (holes->GetComponent(firstPolyCell + face, 0) != 0.0)
      {
        holeFaces.push_back(face);
      }
    }
  }
  vtkSubDForEachStripTriangle(input->GetStrips(), [&out](vtkIdType a, vtkIdType b, vtkIdType c) {
    out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
  });

  // Sharp features.
  vtkIdType n;
  const vtkIdType* pts;
  vtkDataArray* sharpness = input->GetCellData()->GetArray("Sharpness");
  vtkIdType cell = input->GetNumberOfVerts();
  vtkCellArray* lines = input->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(n, pts); ++cell)
  {
    if (n < 2)
    {
      continue;
    }
    out << "t crease " << n << "/1/0";
    for (vtkIdType k = 0; k < n; ++k)
    {
      out << ' ' << pts[k];
    }
    out << ' ' << (sharpness ? sharpness->GetComponent(cell, 0) : 10.0) << '\n';
  }
  if (vtkDataArray* corners = input->GetPointData()->GetArray("CornerSharpness"))
  {
    std::vector<vtkIdType> ids;
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      if (corners->GetComponent(i, 0) != 0.0)
      {
        ids.push_back(i);
      }
    }
    if (!ids.empty())
    {
      out << "t corner " << ids.size() << '/' << ids.size() << "/0";
      for (vtkIdType i : ids)
      {
        out << ' ' << i;
      }
      for (vtkIdType i : ids)
      {
        out << ' ' << corners->GetComponent(i, 0);
      }
      out << '\n';
    }
  }
  if (!holeFaces.empty())
  {
    out << "t hole " << holeFaces.size() << "/0/0";
    for (vtkIdType f : holeFaces)
    {
      out << ' ' << f;
    }
    out << '\n';
  }
}

void vtkSubDOBJWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
