/**
 * @class   vtkSubDLinearFilter
 * @brief   linear subdivision: more resolution, same shape
 *
 * Refines a polygon mesh without smoothing it; every point-data array is interpolated
 * linearly, so data that is linear over each face (bilinear over each quad) is reproduced
 * exactly. Two splits:
 *
 * - quad split (bilinear): each n-gon becomes n quads around its centroid; new points are
 *   face centroids and edge midpoints, old points stay (OpenSubdiv's Sdc::SCHEME_BILINEAR);
 * - triangle split: each triangle becomes four; new points are edge midpoints, old points
 *   stay (VTK's vtkLinearSubdivisionFilter, without its triangles-only restriction).
 *
 * Split (default SPLIT_AUTO) picks the triangle split when every input face is a triangle and
 * the quad split otherwise; SPLIT_QUADS and SPLIT_TRIANGLES force one (polygons are then
 * triangulated first (ear clipping), with a warning). BoundaryRule has no effect here: with no
 * smoothing there is nothing to interpolate differently at a boundary.
 *
 * The surface does not change shape, so creases change no point; crease lines are still
 * refined and carried to the output (with decayed sharpness) like every primal scheme's.
 *
 * The rules read each face's edges and each edge's ends only, never the faces or edges around
 * a vertex. Without crease lines or corner sharpness, limit options or ghost cells, the input's
 * topology is built so too (subd::MeshTopology::BuildFacesAndEdges, a fifth faster than the
 * full one): its non-manifold edges are reported, but not a vertex where otherwise manifold
 * faces pinch (a bowtie), which changes nothing here.
 *
 * Attributes, cell data, errors, progress and stencil caching: see vtkSubDSurfaceFilter.
 *
 * A polygon that repeats a point is kept as OpenSubdiv's bilinear scheme keeps it (triangle
 * split: triangles only, larger polygons collapsed first; see
 * vtkSubDSurfaceFilter::SetCollapseRepeatedCorners).
 */
#ifndef vtkSubDLinearFilter_h
#define vtkSubDLinearFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkSubDSurfaceFilter.h"

class SUBDFILTERS_EXPORT vtkSubDLinearFilter : public vtkSubDSurfaceFilter
{
public:
  static vtkSubDLinearFilter* New();
  vtkTypeMacro(vtkSubDLinearFilter, vtkSubDSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Splits
  {
    SPLIT_AUTO = 0,
    SPLIT_QUADS = 1,
    SPLIT_TRIANGLES = 2
  };

  ///@{
  /**
   * Which split to use (default SPLIT_AUTO: triangles for all-triangle input, else quads).
   */
  vtkSetClampMacro(Split, int, SPLIT_AUTO, SPLIT_TRIANGLES);
  vtkGetMacro(Split, int);
  void SetSplitToAuto() { this->SetSplit(SPLIT_AUTO); }
  void SetSplitToQuads() { this->SetSplit(SPLIT_QUADS); }
  void SetSplitToTriangles() { this->SetSplit(SPLIT_TRIANGLES); }
  const char* GetSplitAsString();
  ///@}

protected:
  vtkSubDLinearFilter() = default;
  ~vtkSubDLinearFilter() override = default;

  subd::Scheme* NewScheme(bool allTriangles) override;
  bool RequiresTriangles() override { return this->Split == SPLIT_TRIANGLES; }
  bool KeepsRepeatedCorners() override { return true; }
  bool RefinesFaceVaryingData() override { return true; }

  int Split = SPLIT_AUTO;

private:
  vtkSubDLinearFilter(const vtkSubDLinearFilter&) = delete;
  void operator=(const vtkSubDLinearFilter&) = delete;
};

#endif
