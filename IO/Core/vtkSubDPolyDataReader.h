/**
 * @class   vtkSubDPolyDataReader
 * @brief   base of SubD's file readers: file name, opening, error reporting
 *
 * Opens FileName and hands the stream to the subclass's ReadFile. Any failure (no file
 * name, a file that cannot be opened, a problem the subclass reports with Fail) gives an
 * error message naming the file (and the line, when known), an empty output and the
 * matching vtkErrorCode.
 */
#ifndef vtkSubDPolyDataReader_h
#define vtkSubDPolyDataReader_h

#include "SubDIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <iosfwd> // for std::istream
#include <string> // for std::string

class SUBDIO_EXPORT vtkSubDPolyDataReader : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSubDPolyDataReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the file to read. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

protected:
  vtkSubDPolyDataReader();
  ~vtkSubDPolyDataReader() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Reads the open file into `output`. Returns false after reporting the problem with Fail.
  virtual bool ReadFile(std::istream& file, vtkPolyData* output) = 0;

  /// Reports a format problem at `line` of the file (0: not tied to a line); returns false.
  bool Fail(long line, const std::string& what);

  char* FileName = nullptr;

private:
  vtkSubDPolyDataReader(const vtkSubDPolyDataReader&) = delete;
  void operator=(const vtkSubDPolyDataReader&) = delete;
};

#endif
