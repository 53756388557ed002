#include "vtkSubDLoopFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDLoopFilter);

subd::Scheme* vtkSubDLoopFilter::NewScheme(bool)
{
  return new subd::LoopScheme;
}

void vtkSubDLoopFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
