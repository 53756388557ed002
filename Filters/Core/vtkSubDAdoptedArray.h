// Private helper of SubD's filters: hands a kernel array's storage to a VTK array without
// copying it.
//
// vtkBuffer frees foreign memory through a plain function of the pointer only, so the
// vectors whose storage VTK arrays hold are kept in a registry keyed by that pointer; the
// array's free function takes its vector out and destroys it. An output's connectivity
// (the largest array of a refined mesh after its points) is then written once, by the
// kernel, instead of built there and copied here, and its double points live in the
// kernel's allocator (large blocks, SubDTypes.h).
#ifndef vtkSubDAdoptedArray_h
#define vtkSubDAdoptedArray_h

#include "SubDFiltersModule.h" // export macro
#include "SubDTypes.h"          // IndexArray
#include "vtkDoubleArray.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"

/// A single-component array over `values`' storage; `values` is left empty.
SUBDFILTERS_EXPORT vtkSmartPointer<vtkTypeInt32Array> vtkSubDAdoptVector(subd::IndexArray&& values);

/// A new double array of `tuples` tuples, its values not initialised, whose storage comes
/// from the kernel's allocator: a large output (the refined points) is then backed by huge
/// pages where the system grants them (subd::AllocateLargeBlock), so that filling it costs
/// a page fault per 2 MiB rather than per 4 KiB.
SUBDFILTERS_EXPORT vtkSmartPointer<vtkDoubleArray> vtkSubDNewDoubleArray(int components, vtkIdType tuples);

/// How many adopted vectors VTK arrays still hold (for tests: 0 once they are all freed).
SUBDFILTERS_EXPORT std::size_t vtkSubDNumberOfAdoptedVectors();

#endif
