/**
 * @class   vtkSubDPolyDataWriter
 * @brief   base of SubD's file writers: file name, opening, failure checks
 *
 * Checks the input and FileName, opens the file and hands the stream to the subclass's
 * WriteFile; afterwards a stream that failed (disk full) is reported. Every failure gives an
 * error message naming the file and the matching vtkErrorCode.
 */
#ifndef vtkSubDPolyDataWriter_h
#define vtkSubDPolyDataWriter_h

#include "SubDIOModule.h" // for export macro
#include "vtkWriter.h"

#include <iosfwd> // for std::ostream

class vtkPolyData;

class SUBDIO_EXPORT vtkSubDPolyDataWriter : public vtkWriter
{
public:
  vtkTypeMacro(vtkSubDPolyDataWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Name of the file to write. */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

protected:
  vtkSubDPolyDataWriter() = default;
  ~vtkSubDPolyDataWriter() override;
  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  /// Writes `input` to the open file.
  virtual void WriteFile(vtkPolyData* input, std::ostream& file) = 0;

  char* FileName = nullptr;

private:
  vtkSubDPolyDataWriter(const vtkSubDPolyDataWriter&) = delete;
  void operator=(const vtkSubDPolyDataWriter&) = delete;
};

#endif
