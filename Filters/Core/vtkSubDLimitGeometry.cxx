#include "vtkSubDLimitGeometry.h"

#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkSetGet.h"

#include <algorithm>
#include <cmath>

vtkSubDLimitGeometry::vtkSubDLimitGeometry(vtkIdType numPoints, bool normals, bool curvature, bool derivatives)
  : WithNormals(normals)
  , WithCurvature(curvature)
  , WithDerivatives(derivatives)
{
  auto setup = [numPoints](vtkDataArray* array, const char* name, int components) {
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(numPoints);
  };
  setup(this->Normals, "Normals", 3);
  setup(this->Mean, "Mean_Curvature", 1);
  setup(this->Gauss, "Gauss_Curvature", 1);
  setup(this->Maximum, "Maximum_Curvature", 1);
  setup(this->Minimum, "Minimum_Curvature", 1);
  setup(this->MaximumDirection, "Maximum_Curvature_Direction", 3);
  setup(this->MinimumDirection, "Minimum_Curvature_Direction", 3);
  setup(this->Du, "dPdu", 3);
  setup(this->Dv, "dPdv", 3);
}

void vtkSubDLimitGeometry::Apply(const subd::LimitStencil& stencil, const double* points, double d[6][3], double c[6][3])
{
  for (int k = 0; k < 6; ++k)
  {
    stencil.Apply(stencil.Weights, k, points, 3, d[k]);
    if (stencil.CurvatureWeights.empty())
    {
      std::copy(d[k], d[k] + 3, c[k]);
    }
    else
    {
      stencil.Apply(stencil.CurvatureWeights, k, points, 3, c[k]);
    }
  }
}

bool vtkSubDLimitGeometry::Set(vtkIdType i, const double d[6][3], const double c[6][3])
{
  const subd::SurfaceGeometry g = subd::ComputeSurfaceGeometry(d, c);
  return this->SetMean(i, { g }, d);
}

bool vtkSubDLimitGeometry::SetMean(vtkIdType i, const std::vector<subd::SurfaceGeometry>& sides, const double d[6][3])
{
  double n[3] = { 0, 0, 0 }, mean = 0, gauss = 0, kmax = 0, kmin = 0;
  int regular = 0;
  for (const subd::SurfaceGeometry& g : sides)
  {
    if (!g.Regular)
    {
      continue;
    }
    ++regular;
    for (int k = 0; k < 3; ++k)
    {
      n[k] += g.Normal[k];
    }
    mean += g.Mean;
    gauss += g.Gaussian;
    kmax += g.Maximum;
    kmin += g.Minimum;
  }
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const bool ok = regular > 0 && length > 0.0;
  if (ok)
  {
    for (double& x : n)
    {
      x /= length;
    }
    mean /= regular;
    gauss /= regular;
    kmax /= regular;
    kmin /= regular;
  }
  if (!ok)
  {
    ++this->NumUndefined;
  }
  this->Normals->SetTuple3(i, ok ? n[0] : 0.0, ok ? n[1] : 0.0, ok ? n[2] : 0.0);
  this->Mean->SetValue(i, ok ? mean : 0.0);
  this->Gauss->SetValue(i, ok ? gauss : 0.0);
  this->Maximum->SetValue(i, ok ? kmax : 0.0);
  this->Minimum->SetValue(i, ok ? kmin : 0.0);
  const subd::SurfaceGeometry* first = nullptr;
  for (const subd::SurfaceGeometry& g : sides)
  {
    if (g.Regular && !first && ok)
    {
      first = &g;
    }
  }
  const double zero[3] = { 0, 0, 0 };
  this->MaximumDirection->SetTuple(i, first ? first->MaximumDirection : zero);
  this->MinimumDirection->SetTuple(i, first ? first->MinimumDirection : zero);
  this->Du->SetTuple(i, d[1]);
  this->Dv->SetTuple(i, d[2]);
  return ok;
}

void vtkSubDLimitGeometry::Copy(vtkIdType to, vtkIdType from)
{
  for (vtkDataArray* array : { static_cast<vtkDataArray*>(this->Normals), static_cast<vtkDataArray*>(this->Mean),
         static_cast<vtkDataArray*>(this->Gauss), static_cast<vtkDataArray*>(this->Maximum),
         static_cast<vtkDataArray*>(this->Minimum), static_cast<vtkDataArray*>(this->MaximumDirection),
         static_cast<vtkDataArray*>(this->MinimumDirection), static_cast<vtkDataArray*>(this->Du),
         static_cast<vtkDataArray*>(this->Dv) })
  {
    if (array->GetNumberOfTuples() > std::max(to, from))
    {
      array->SetTuple(to, from, array);
    }
  }
}

void vtkSubDLimitGeometry::AddTo(vtkPointData* pd, vtkObject* filter) const
{
  if (this->NumUndefined > 0 && (this->WithNormals || this->WithCurvature))
  {
    vtkWarningWithObjectMacro(filter, << "The limit surface has no tangent plane at " << this->NumUndefined
                                      << " output point(s) (a non-manifold vertex or degenerate geometry): "
                                         "their normals and curvatures are 0.");
  }
  auto add = [pd](vtkDataArray* array) {
    pd->RemoveArray(array->GetName());
    pd->AddArray(array);
  };
  if (this->WithNormals)
  {
    add(this->Normals);
    pd->SetActiveNormals(this->Normals->GetName());
  }
  if (this->WithCurvature)
  {
    for (vtkDataArray* array : { static_cast<vtkDataArray*>(this->Mean), static_cast<vtkDataArray*>(this->Gauss),
           static_cast<vtkDataArray*>(this->Maximum), static_cast<vtkDataArray*>(this->Minimum),
           static_cast<vtkDataArray*>(this->MaximumDirection), static_cast<vtkDataArray*>(this->MinimumDirection) })
    {
      add(array);
    }
  }
  if (this->WithDerivatives)
  {
    add(this->Du);
    add(this->Dv);
  }
}
