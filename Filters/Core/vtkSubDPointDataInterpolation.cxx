#include "vtkSubDPointDataInterpolation.h"

#include "vtkDoubleArray.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <limits>
#include <type_traits>

namespace
{
template <typename T>
T StoreAs(double value)
{
  if constexpr (std::is_integral<T>::value)
  {
    const double rounded = std::round(value);
    constexpr double lowest = static_cast<double>(std::numeric_limits<T>::lowest());
    constexpr double highest = static_cast<double>(std::numeric_limits<T>::max());
    if (!(rounded > lowest)) // also catches NaN
    {
      return std::numeric_limits<T>::lowest();
    }
    return rounded >= highest ? std::numeric_limits<T>::max() : static_cast<T>(rounded);
  }
  else
  {
    return static_cast<T>(value);
  }
}

template <typename T>
void StoreTyped(const double* values, int components, const std::vector<vtkIdType>* selection,
  vtkIdType numOut, bool normalize, T* out)
{
  vtkSMPTools::For(0, numOut, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const vtkIdType source = selection ? (*selection)[i] : i;
      const double* v = values + source * components;
      double scale = 1.0;
      if (normalize)
      {
        double norm2 = 0.0;
        for (int c = 0; c < components; ++c)
        {
          norm2 += v[c] * v[c];
        }
        scale = norm2 > 0.0 ? 1.0 / std::sqrt(norm2) : 1.0;
      }
      T* o = out + i * components;
      for (int c = 0; c < components; ++c)
      {
        o[c] = StoreAs<T>(v[c] * scale);
      }
    }
  });
}
}

vtkSmartPointer<vtkDataArray> vtkSubDPointDataInterpolation::Interpolate(
  vtkDataArray* base, int outputType, bool normalize, const subd::ProgressCallback& progress,
  vtkDataArray* recycled) const
{
  const int components = base->GetNumberOfComponents();
  const vtkIdType numBase = base->GetNumberOfTuples();

  // Base values in double: read in place from a double array, copied otherwise (the base
  // level is the small one).
  std::vector<double> baseCopy;
  const double* baseValues = nullptr;
  vtkDoubleArray* baseDouble = vtkDoubleArray::FastDownCast(base);
  if (baseDouble)
  {
    baseValues = baseDouble->GetPointer(0);
  }
  else
  {
    baseCopy.resize(static_cast<size_t>(numBase) * components);
    for (vtkIdType i = 0; i < numBase; ++i)
    {
      base->GetTuple(i, baseCopy.data() + i * components);
    }
    baseValues = baseCopy.data();
  }

  const vtkIdType numFinest = this->Hierarchy.GetNumFinestPoints();
  const vtkIdType numOut = this->Selection ? static_cast<vtkIdType>(this->Selection->size()) : numFinest;
  const bool recycle = recycled && recycled->GetDataType() == outputType &&
    recycled->GetNumberOfComponents() == components && recycled->GetNumberOfTuples() == numOut;
  // Evaluate straight into a double output when nothing needs converting.
  const bool direct = outputType == VTK_DOUBLE && !this->Selection && !normalize;
  vtkSmartPointer<vtkDataArray> out = recycle
    ? vtkSmartPointer<vtkDataArray>(recycled)
    : vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(outputType));
  out->SetName(base->GetName());
  out->SetNumberOfComponents(components);
  for (int c = 0; c < components; ++c)
  {
    if (base->HasAComponentName() && base->GetComponentName(c))
    {
      out->SetComponentName(c, base->GetComponentName(c));
    }
  }
  out->SetNumberOfTuples(numOut);

  subd::LevelArray<double> finest;
  double* finestValues = nullptr;
  if (direct)
  {
    finestValues = vtkDoubleArray::FastDownCast(out)->GetPointer(0);
  }
  else
  {
    finest.resize(static_cast<size_t>(numFinest) * components);
    finestValues = finest.data();
  }
  if (!this->Hierarchy.Evaluate(baseValues, components, finestValues, this->ParallelFor, progress, -1, this->Scratch))
  {
    return nullptr;
  }
  if (!direct && !Store(finestValues, components, this->Selection, numOut, normalize, out))
  {
    return nullptr;
  }
  out->Modified(); // written through its pointer (a recycled array had other values)
  return out;
}

void vtkSubDPointDataInterpolation::SMPFor(subd::Index begin, subd::Index end, const subd::RangeTask& task)
{
  constexpr vtkIdType grain = 2048;
  vtkSMPTools::For(begin, end, grain,
    [&task](vtkIdType b, vtkIdType e) { task(static_cast<subd::Index>(b), static_cast<subd::Index>(e)); });
}

bool vtkSubDPointDataInterpolation::Store(const double* values, int components,
  const std::vector<vtkIdType>* selection, vtkIdType n, bool normalize, vtkDataArray* out)
{
  switch (out->GetDataType())
  {
    vtkTemplateMacro(
      StoreTyped(values, components, selection, n, normalize, static_cast<VTK_TT*>(out->GetVoidPointer(0))));
    default:
      return false;
  }
  return true;
}
