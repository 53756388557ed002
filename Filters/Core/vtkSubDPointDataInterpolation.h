// Private helper of vtkSubDSurfaceFilter: applies a kernel hierarchy's stencils to one
// vtkDataArray of per-point values and returns the refined array.
//
// Values are refined in double precision whatever the array type, then stored in the
// requested type: integer types are rounded to nearest and clamped to the type's range
// (stencils with negative weights must not wrap an unsigned char colour around), and an
// array flagged as normals is re-normalized, since averaged unit vectors are shorter.
#ifndef vtkSubDPointDataInterpolation_h
#define vtkSubDPointDataInterpolation_h

#include "SubDRefiner.h"
#include "vtkDataArray.h"
#include "vtkSmartPointer.h"

#include <vector>

class vtkSubDPointDataInterpolation
{
public:
  /// `selection`, when given, lists the finest points to output, in output order.
  /// `scratch`, when given, holds the intermediate levels' values (kept by the caller).
  vtkSubDPointDataInterpolation(const subd::Hierarchy& hierarchy, subd::ParallelFor parallelFor,
    const std::vector<vtkIdType>* selection, subd::EvaluationScratch<double>* scratch = nullptr)
    : Hierarchy(hierarchy)
    , ParallelFor(std::move(parallelFor))
    , Selection(selection)
    , Scratch(scratch)
  {
  }

  /// Returns the refined array (same name and component names as `base`), or nullptr when
  /// `progress` asked to stop. `recycled`, if it has the output's type and size, is written
  /// instead of a new array: the caller passes one that nothing else holds (a previous
  /// output's), which spares a new array's first touch of every page, a sixth of the time
  /// of re-applying cached stencils.
  vtkSmartPointer<vtkDataArray> Interpolate(vtkDataArray* base, int outputType, bool normalize,
    const subd::ProgressCallback& progress, vtkDataArray* recycled = nullptr) const;

  /// Runs the kernel's row loops with vtkSMPTools (a subd::ParallelFor).
  static void SMPFor(subd::Index begin, subd::Index end, const subd::RangeTask& task);

  /// Stores `n` tuples of double values (rows `selection`[i] of `values`, or the first n)
  /// into `out` (already sized) by the rules above: integers rounded and clamped, vectors
  /// re-normalized when `normalize`.
  static bool Store(const double* values, int components, const std::vector<vtkIdType>* selection, vtkIdType n,
    bool normalize, vtkDataArray* out);

private:
  const subd::Hierarchy& Hierarchy;
  subd::ParallelFor ParallelFor;
  const std::vector<vtkIdType>* Selection;
  subd::EvaluationScratch<double>* Scratch;
};

#endif
