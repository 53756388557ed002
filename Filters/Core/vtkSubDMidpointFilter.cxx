#include "vtkSubDMidpointFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDMidpointFilter);

subd::Scheme* vtkSubDMidpointFilter::NewScheme(bool)
{
  return new subd::MidpointScheme;
}

void vtkSubDMidpointFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
