#include "vtkSubDPolyDataWriter.h"

#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"

vtkSubDPolyDataWriter::~vtkSubDPolyDataWriter()
{
  this->SetFileName(nullptr);
}

int vtkSubDPolyDataWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

void vtkSubDPolyDataWriter::WriteData()
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
  vtksys::ofstream file(this->FileName, std::ios::out | std::ios::binary); // bytes as written (PLY)
  if (!file)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "' for writing.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  this->WriteFile(input, file);
  file.flush();
  if (!file)
  {
    vtkErrorMacro("Writing '" << this->FileName << "' failed (disk full?).");
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
  }
}

void vtkSubDPolyDataWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
