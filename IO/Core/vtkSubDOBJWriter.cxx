#include "vtkSubDOBJWriter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSubDStripTriangles.h"
#include "vtkSubDBufferedOutput.h"

#include <map>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkSubDOBJWriter);

namespace
{
// Numbers the distinct tuples of `array` (compared exactly) in the order they first come;
// returns each tuple's number, and the distinct tuples in `distinct`.
std::vector<vtkIdType> NumberDistinct(vtkDataArray* array, std::vector<std::vector<double>>& distinct)
{
  std::map<std::vector<double>, vtkIdType> numberOf;
  std::vector<vtkIdType> number(static_cast<size_t>(array->GetNumberOfTuples()));
  std::vector<double> tuple(static_cast<size_t>(array->GetNumberOfComponents()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    array->GetTuple(i, tuple.data());
    const auto inserted = numberOf.emplace(tuple, static_cast<vtkIdType>(distinct.size()));
    if (inserted.second)
    {
      distinct.push_back(tuple);
    }
    number[i] = inserted.first->second;
  }
  return number;
}

// The sharp features as OpenSubdiv's tags, naming the `v` of each point (`vertexOf`).
void WriteSharpFeatureTags(vtkPolyData* input, const std::vector<vtkIdType>& vertexOf,
  const std::vector<vtkIdType>& holeFaces, vtkSubDBufferedOutput& out)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
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
      out << ' ' << vertexOf[pts[k]];
    }
    out << ' ' << (sharpness ? sharpness->GetComponent(cell, 0) : 10.0) << '\n';
  }
  if (vtkDataArray* corners = input->GetPointData()->GetArray("CornerSharpness"))
  {
    std::vector<vtkIdType> ids; // points, one per vertex
    std::vector<char> tagged(static_cast<size_t>(numPoints), 0);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      if (corners->GetComponent(i, 0) != 0.0 && !tagged[vertexOf[i]])
      {
        tagged[vertexOf[i]] = 1;
        ids.push_back(i);
      }
    }
    if (!ids.empty())
    {
      out << "t corner " << ids.size() << '/' << ids.size() << "/0";
      for (vtkIdType i : ids)
      {
        out << ' ' << vertexOf[i];
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
}

void vtkSubDOBJWriter::WriteFile(vtkPolyData* input, std::ostream& file)
{
  vtkSubDBufferedOutput out(file); // numbers in their shortest exact form
  out << "# written by SubD (sharp features as OpenSubdiv tags, 0-based)\n";
  const vtkIdType numPoints = input->GetNumberOfPoints();
  // With texture coordinates the points are split at seams (one per position and
  // coordinate): each position is one `v`, each coordinate one `vt`, and corners name both.
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  const bool textured = tcoords && tcoords->GetNumberOfComponents() >= 2 && numPoints > 0;
  std::vector<vtkIdType> vertexOf(static_cast<size_t>(numPoints)), texOf;
  if (textured)
  {
    std::vector<std::vector<double>> positions, coordinates;
    vertexOf = NumberDistinct(input->GetPoints()->GetData(), positions);
    texOf = NumberDistinct(tcoords, coordinates);
    for (const auto& p : positions)
    {
      out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    for (const auto& t : coordinates)
    {
      out << "vt " << t[0] << ' ' << t[1] << '\n';
    }
  }
  else
  {
    std::iota(vertexOf.begin(), vertexOf.end(), 0);
    vtkSubDFormatInParallel(out, numPoints, [input](vtkSubDBufferedOutput& text, vtkIdType i) {
      double p[3];
      input->GetPoint(i, p);
      text << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    });
  }
  auto corner = [&vertexOf, &texOf, textured](vtkSubDBufferedOutput& text, vtkIdType id) {
    text << ' ' << vertexOf[id] + 1;
    if (textured)
    {
      text << '/' << texOf[id] + 1;
    }
  };

  // Faces: polygons then strip triangles; holes are numbered among them.
  vtkCellArray* polys = input->GetPolys();
  vtkSubDFormatCellsInParallel(out, polys, [&corner](vtkSubDBufferedOutput& text, const auto& pts) {
    text << 'f';
    for (const auto id : pts)
    {
      corner(text, id);
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
  vtkSubDForEachStripTriangle(input->GetStrips(), [&out, &corner](vtkIdType a, vtkIdType b, vtkIdType c) {
    out << 'f';
    corner(out, a);
    corner(out, b);
    corner(out, c);
    out << '\n';
  });

  WriteSharpFeatureTags(input, vertexOf, holeFaces, out);
}

void vtkSubDOBJWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
