#include "vtkSubDLinearFilter.h"

#include "SubDScheme.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkSubDLinearFilter);

subd::Scheme* vtkSubDLinearFilter::NewScheme(bool allTriangles)
{
  const bool triangles = this->Split == SPLIT_TRIANGLES || (this->Split == SPLIT_AUTO && allTriangles);
  if (triangles)
  {
    return new subd::LinearTriangleScheme;
  }
  return new subd::BilinearScheme;
}

const char* vtkSubDLinearFilter::GetSplitAsString()
{
  switch (this->Split)
  {
    case SPLIT_QUADS:
      return "Quads";
    case SPLIT_TRIANGLES:
      return "Triangles";
    default:
      return "Auto";
  }
}

void vtkSubDLinearFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Split: " << this->GetSplitAsString() << "\n";
}
