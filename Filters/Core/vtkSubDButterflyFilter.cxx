#include "vtkSubDButterflyFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDButterflyFilter);

subd::Scheme* vtkSubDButterflyFilter::NewScheme(bool)
{
  return new subd::ButterflyScheme(this->Tension);
}

void vtkSubDButterflyFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tension: " << this->Tension << "\n";
}
