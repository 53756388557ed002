#include "vtkSubDDooSabinFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDDooSabinFilter);

subd::Scheme* vtkSubDDooSabinFilter::NewScheme(bool)
{
  return new subd::DooSabinScheme;
}

void vtkSubDDooSabinFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
