// Reads the values of a VTK data array from a FileScanner, as ASCII numbers or raw binary.
#ifndef vtkSubDReadValues_h
#define vtkSubDReadValues_h

#include "vtkDataArray.h"
#include "vtkSubDFileScanner.h"

namespace subdio
{
/// Reads `count` values into `array` from value index `start` on (the array is already sized),
/// in the array's own type. ASCII values must be numbers of that type (integers for integer
/// types); binary ones are raw, in the file's byte order. False at the first bad value or when
/// the bytes run out.
inline bool ReadArrayValues(
  FileScanner& scanner, vtkDataArray* array, vtkIdType start, vtkIdType count, bool binary, bool bigEndian)
{
  if (count == 0)
  {
    return true;
  }
  bool ok = false;
  switch (array->GetDataType())
  {
    vtkTemplateMacro({
      auto* values = static_cast<VTK_TT*>(array->GetVoidPointer(start));
      if (binary)
      {
        ok = scanner.NextBinary(values, static_cast<size_t>(count), bigEndian);
      }
      else
      {
        ok = true;
        for (vtkIdType i = 0; i < count && ok; ++i)
        {
          ok = scanner.NextNumber(values[i]);
        }
      }
    });
    default:
      ok = false;
  }
  return ok;
}
}

#endif
