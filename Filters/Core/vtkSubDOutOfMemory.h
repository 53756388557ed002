// Private helper of SubD's filters: running out of memory is an error, not a crash.
#ifndef vtkSubDOutOfMemory_h
#define vtkSubDOutOfMemory_h

#include "vtkAlgorithm.h"
#include "vtkErrorCode.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"

#include <new>

/// Runs a filter's `work` (its RequestData); a std::bad_alloc thrown inside (the size guard
/// estimates the output, but not what the rest of the process holds) becomes an error
/// message, an empty output and a failed request instead of ending the application.
/// `setErrorCode(code)` sets the filter's error code (a protected member of vtkAlgorithm).
template <typename Work, typename SetErrorCode>
int vtkSubDRunCatchingOutOfMemory(vtkAlgorithm* filter, vtkPolyData* output, Work&& work, SetErrorCode&& setErrorCode)
{
  try
  {
    return work();
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    setErrorCode(vtkErrorCode::UserError);
    vtkErrorWithObjectMacro(filter, "Ran out of memory while computing the output (it is empty): "
                                    "use fewer levels, or a smaller MaximumMemory so that such requests "
                                    "are refused before they start.");
    return 0;
  }
}

#endif
