// subd: checks of PLY and STL files before VTK's readers see them.
//
// vtkPLYReader, vtkSTLReader and vtkPolyDataReader trust their files: a PLY file cut short makes the first crash
// (a double free) and a header announcing two billion vertices makes it loop for minutes; a
// binary STL whose triangle count exceeds the file, or a legacy VTK file whose POINTS count
// does, makes the others allocate for it. These
// checks walk the file's structure (header, element counts, list lengths) without building
// anything, and name what is wrong; a file that passes holds everything its header announces.
#ifndef SubDFileChecks_h
#define SubDFileChecks_h

#include <string>

namespace subdapp
{
/// True when `path` is a PLY file (ascii or binary) whose body holds every element its header
/// announces, with a "vertex" element of x, y, z and, if it has faces, a vertex index list.
/// Otherwise false, with `error` set.
bool CheckPLYFile(const std::string& path, std::string& error);

/// True when no count in the legacy VTK file `path` (POINTS, VERTICES, LINES, POLYGONS,
/// TRIANGLE_STRIPS, POINT_DATA, CELL_DATA) promises more values than its bytes can hold
/// (vtkPolyDataReader allocates for the count first). Otherwise false, with `error` set.
bool CheckLegacyVTKFile(const std::string& path, std::string& error);

/// True when no NumberOf... attribute of the VTK XML file `path` exceeds what its bytes can
/// hold even compressed (zlib packs at most about 1000 to 1). Otherwise false, with `error` set.
bool CheckXMLPolyDataFile(const std::string& path, std::string& error);

/// True when `path` is an ASCII STL file (left to the reader) or a binary one whose size holds
/// the triangles its header counts. Otherwise false, with `error` set.
bool CheckSTLFile(const std::string& path, std::string& error);
}

#endif
