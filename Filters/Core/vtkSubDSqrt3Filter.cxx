#include "vtkSubDSqrt3Filter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDSqrt3Filter);

subd::Scheme* vtkSubDSqrt3Filter::NewScheme(bool)
{
  return new subd::Sqrt3Scheme;
}

void vtkSubDSqrt3Filter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
