// Private helper of SubD's filters: hands a kernel array's storage to a VTK array without
// copying it.
//
// vtkBuffer frees foreign memory through a plain function of the pointer only, so the
// vectors whose storage VTK arrays hold are kept in a registry keyed by that pointer; the
// array's free function takes its vector out and destroys it. An output's connectivity
// (the largest array of a refined mesh after its points) is then written once, by the
// kernel, instead of built there and copied here.
#ifndef vtkSubDAdoptedArray_h
#define vtkSubDAdoptedArray_h

#include "SubDFiltersModule.h" // export macro
#include "SubDTypes.h"          // IndexArray
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"

/// A single-component array over `values`' storage; `values` is left empty.
SUBDFILTERS_EXPORT vtkSmartPointer<vtkTypeInt32Array> vtkSubDAdoptVector(subd::IndexArray&& values);

/// How many adopted vectors VTK arrays still hold (for tests: 0 once they are all freed).
SUBDFILTERS_EXPORT std::size_t vtkSubDNumberOfAdoptedVectors();

#endif
