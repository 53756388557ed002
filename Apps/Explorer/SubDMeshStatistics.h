// SubD Explorer: the numbers a view shows about its mesh.
#ifndef SubDMeshStatistics_h
#define SubDMeshStatistics_h

#include "vtkType.h"

class vtkPolyData;

namespace subdexplorer
{
struct MeshStatistics
{
  vtkIdType Vertices = 0, Edges = 0, Faces = 0, Lines = 0;
  /// Interior vertices whose valence is not the regular one of the mesh's dominant face
  /// (4 around quads, 6 around triangles); boundary vertices are not counted.
  vtkIdType Extraordinary = 0;
};

/// Counts from the polygons' edges (each undirected edge once), in linear time.
MeshStatistics ComputeMeshStatistics(vtkPolyData* mesh);
}

#endif
