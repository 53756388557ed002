#include "vtkSubDPolyDataReader.h"

#include "vtkErrorCode.h"
#include "vtkPolyData.h"
#include "vtksys/FStream.hxx"

vtkSubDPolyDataReader::vtkSubDPolyDataReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkSubDPolyDataReader::~vtkSubDPolyDataReader()
{
  this->SetFileName(nullptr);
}

bool vtkSubDPolyDataReader::Fail(long line, const std::string& what)
{
  if (line > 0)
  {
    vtkErrorMacro("'" << this->FileName << "', line " << line << ": " << what);
  }
  else
  {
    vtkErrorMacro("'" << this->FileName << "': " << what);
  }
  this->SetErrorCode(vtkErrorCode::FileFormatError);
  return false;
}

int vtkSubDPolyDataReader::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name was set.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 0;
  }
  vtksys::ifstream file(this->FileName);
  if (!file)
  {
    vtkErrorMacro("Cannot open '" << this->FileName << "'.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return 0;
  }
  if (!this->ReadFile(file, output))
  {
    output->Initialize();
    return 0;
  }
  return 1;
}

void vtkSubDPolyDataReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
