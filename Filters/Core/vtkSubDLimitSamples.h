// Private helper of vtkSubDLimitFilter: the points a tessellation of the limit surface (or a
// list of locations) asks for, and the cells through them.
#ifndef vtkSubDLimitSamples_h
#define vtkSubDLimitSamples_h

#include "SubDLimitEvaluator.h"
#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"

#include <utility>
#include <vector>

/// The samples one face of the cage evaluates, and the output points they become.
struct vtkSubDFaceSamples
{
  subd::Index Face;
  std::vector<subd::FaceSample> Owned; ///< samples this face evaluates
  std::vector<vtkIdType> OwnedIds;     ///< their output points
};

/// The output's points, grouped by the face that evaluates each (a point shared by faces is
/// evaluated once), and its cells with their input cells ("FaceId").
struct vtkSubDLimitSamples
{
  std::vector<vtkSubDFaceSamples> Grids;
  vtkIdType Count = 0;
  vtkNew<vtkCellArray> Cells;
  vtkNew<vtkIdTypeArray> CellFace;
  /// Adaptive and selective tessellations: per cell, the level of the tree cell it lies in
  /// (as a face's level: 2^level segments per face edge); empty otherwise.
  std::vector<int> CellLevels;
  /// (point, the first point at its place) for each point on the second side of a seam: the
  /// sides share their position and vertex data, and take them from one evaluation.
  std::vector<std::pair<vtkIdType, vtkIdType>> SamePlace;
};

#endif
