#include "vtkSubDOFFWriter.h"

#include "vtkCellArray.h"
#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSubDStripTriangles.h"
#include "vtksys/FStream.hxx"

#include <iomanip>

vtkStandardNewMacro(vtkSubDOFFWriter);

vtkSubDOFFWriter::vtkSubDOFFWriter() = default;

vtkSubDOFFWriter::~vtkSubDOFFWriter()
{
  this->SetFileName(nullptr);
}

int vtkSubDOFFWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkSubDOFFWriter::WriteData()
{
  vtkPolyData* input = vtkPolyData::SafeDownCast(this->GetInput());
  if (!input)
  {
    vtkErrorMacro("No polydata to write.");
    return;
  }
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  if (input->GetNumberOfLines() + input->GetNumberOfVerts() > 0)
  {
    vtkWarningMacro("OFF holds only polygons: " << input->GetNumberOfLines() << " lines and "
                                               << input->GetNumberOfVerts() << " verts are not written.");
  }
  vtksys::ofstream file(this->FileName);
  if (!file)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "' for writing.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  vtkCellArray* strips = input->GetStrips();
  const vtkIdType numTriangles = vtkSubDCountStripTriangles(strips);
  vtkIdType n;
  const vtkIdType* pts;
  const vtkIdType numPoints = input->GetNumberOfPoints();
  file << "OFF\n" << numPoints << ' ' << input->GetNumberOfPolys() + numTriangles << " 0\n";
  file << std::setprecision(17);
  double p[3];
  for (vtkIdType i = 0; i < numPoints; ++i)
  {
    input->GetPoint(i, p);
    file << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  vtkCellArray* polys = input->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, pts);)
  {
    file << n;
    for (vtkIdType k = 0; k < n; ++k)
    {
      file << ' ' << pts[k];
    }
    file << '\n';
  }
  vtkSubDForEachStripTriangle(strips, [&file](vtkIdType a, vtkIdType b, vtkIdType c) {
    file << "3 " << a << ' ' << b << ' ' << c << '\n';
  });
  file.flush();
  if (!file)
  {
    vtkErrorMacro("Writing '" << this->FileName << "' failed (disk full?).");
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
  }
}

void vtkSubDOFFWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
