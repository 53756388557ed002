// subd: checks of VTK XML and STL files before VTK's readers see them.
//
// vtkXMLPolyDataReader and vtkSTLReader trust the counts in their files: a NumberOfPoints or
// a binary STL triangle count larger than the file makes them allocate for it (gigabytes,
// or bad_alloc). These checks weigh the counts against the file's size and name what is
// wrong; a file that passes cannot make the reader allocate much more than its size. (Legacy
// .vtk and PLY files are read by SubD's own readers, which check everything as they read.)
#ifndef SubDFileChecks_h
#define SubDFileChecks_h

#include <string>

namespace subdapp
{
/// True when no NumberOf... attribute of the VTK XML file `path` exceeds what its bytes can
/// hold even compressed (zlib packs at most about 1000 to 1). Otherwise false, with `error` set.
bool CheckXMLPolyDataFile(const std::string& path, std::string& error);

/// True when `path` is an ASCII STL file (left to the reader) or a binary one whose size holds
/// the triangles its header counts. Otherwise false, with `error` set.
bool CheckSTLFile(const std::string& path, std::string& error);
}

#endif
