#include "vtkSubDLegacyReader.h"

#include "vtkObjectFactory.h"
#include "vtkSubDLegacyParser.h"

vtkStandardNewMacro(vtkSubDLegacyReader);

bool vtkSubDLegacyReader::ReadFile(std::istream& file, vtkPolyData* output)
{
  return subdio::ParseFile<subdio::LegacyParser>(
    file, output, [this](long line, const std::string& what) { return this->Fail(line, what); });
}

void vtkSubDLegacyReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
