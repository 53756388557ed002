#include "vtkSubDCatmullClarkFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDCatmullClarkFilter);

subd::Scheme* vtkSubDCatmullClarkFilter::NewScheme(bool)
{
  return new subd::CatmullClarkScheme(this->SmoothTriangles);
}

void vtkSubDCatmullClarkFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SmoothTriangles: " << (this->SmoothTriangles ? "On" : "Off") << "\n";
}
