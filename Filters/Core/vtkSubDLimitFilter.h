/**
 * @class   vtkSubDLimitFilter
 * @brief   exact evaluation of the Catmull-Clark or Loop limit surface of a control cage
 *
 * vtkSubDLimitFilter evaluates the limit surface that Catmull-Clark (Catmull, Clark 1978) or
 * Loop (Loop 1987) subdivision of the input polygons converges to, exactly (to round-off),
 * without refining the whole cage:
 *
 * - on a uniform grid of Resolution segments along every edge of every face (a Catmull-Clark
 *   face that is not a quad is split at its centre into quads, one per corner, each with
 *   Resolution/2 segments, Resolution then rounded up to even), giving a watertight
 *   tessellation of the limit surface: points on shared edges and vertices are evaluated
 *   once and shared; Catmull-Clark gives quads, Loop triangles; each cell has the cell data
 *   of the input cell it comes from, and "FaceId" names that cell; or
 * - adaptively (Tessellation ADAPTIVE): triangles within Tolerance of the limit surface
 *   (relative to the cage's bounding-box diagonal, or in the cage's units with
 *   ToleranceIsAbsolute), measured along the limit's normal at each triangle's edge midpoints
 *   and centroid, with as few triangles as the refinement finds: each face's domain (a
 *   Catmull-Clark polygon that is not a quad: the quad at each corner) is a tree of cells,
 *   a quad cut across u, across v or both where its chords stray from the surface (a Loop
 *   triangle into four), down to MaximumLevel (2^MaximumLevel segments per face edge); a cell
 *   takes every point of its finer neighbours on its sides as a vertex of its triangles, so
 *   the mesh is watertight, with no cracks and no T-junctions, across faces as within them (a
 *   restricted subdivision of the parameter domains in the manner of Von Herzen and Barr,
 *   "Accurate triangulations of deformed, intersecting surfaces", SIGGRAPH 1987, here without
 *   the 2:1 restriction, on the exact limit). Triangles the deepest level could not bring
 *   within the tolerance are counted in a warning;
 * - selectively (Tessellation SELECTIVE): each face refined to the level its cell-data array
 *   RefineLevelArrayName (default "RefineLevel") asks for (clamped to 0..MaximumLevel), its
 *   points those of the uniform tessellation at Resolution 2^level, crack-free where levels
 *   meet as above. Both give triangles, with "FaceId" as above and "RefineLevel",
 *   the level of the tree cell each lies in;
 * - at the locations given on the second input (SetLocationsConnection): any vtkDataSet
 *   whose point data has "FaceId" (the input cell id of a polygon) and "FaceUV" (2
 *   components: (u, v) in the unit square of a quad, corners 0..3 at (0,0), (1,0), (1,1),
 *   (0,1), or in the unit triangle of a triangle, corners at (0,0), (1,0), (0,1)), and for a
 *   Catmull-Clark polygon that is not a quad "SubFace" (the corner k whose quad is meant,
 *   with (0,0) at the corner, (1,0) at the middle of the edge to the next corner, (1,1) at the
 *   centre). The output has one vertex cell per location, and the locations' point data.
 *
 * With ComputeLocations, each point of a tessellation also carries where it was evaluated:
 * point data "FaceId", "FaceUV" and "SubFace" as the locations input takes them (a point shared
 * by faces names one of them), so that the output can be evaluated again, as locations.
 *
 * Adaptive and selective tessellations refuse, before making them, more cells than
 * MaximumMemory (MiB) allows; a Tolerance that is not a positive number is an error.
 *
 * Each output point carries the cage's point data, evaluated with the same limit weights,
 * and on request the limit surface's "Normals" (ComputeNormals, default on), curvature
 * (ComputeCurvature: "Mean_Curvature", "Gauss_Curvature", "Maximum_Curvature",
 * "Minimum_Curvature", "Maximum_Curvature_Direction", "Minimum_Curvature_Direction"; positive
 * where convex) and first derivatives "dPdu", "dPdv" (ComputeDerivatives), all from the
 * exact first and second derivatives of the limit surface.
 *
 * Method (SubDLimitEvaluator.h): regular faces are bicubic B-spline (Catmull-Clark) or
 * quartic box-spline (Loop) patches, with phantom points along infinitely sharp creases and
 * boundaries; other faces are refined locally, only around the face, until the sample lies
 * in a regular patch (feature-adaptive evaluation, Niessner et al., ACM TOG 2012); at an
 * extraordinary vertex, or a dart, crease or corner vertex that is not regular, the limit
 * point and tangent plane come from the eigenvectors of the subdivision matrix (Halstead,
 * Kass, DeRose, SIGGRAPH 1993; Zorin 1998), and curvature, which is in general not defined
 * there, is read at the centre of the vertex's sub-face 2^-10 across. It agrees with
 * OpenSubdiv's feature-adaptive patches to 1e-14 in positions and first derivatives and
 * 1e-12 in second derivatives (TestOracleOpenSubdiv).
 *
 * Sharp features are read as vtkSubDSurfaceFilter reads them (lines with "Sharpness",
 * "CornerSharpness", "Hole"), with the same BoundaryRule and CreaseMethod, and its faces the
 * same way (polygons, then the triangles of strips; degenerate polygons dropped with a
 * warning; polygons that repeat a point kept as OpenSubdiv keeps them, the Loop scheme's
 * larger ones collapsed, as the Catmull-Clark and Loop filters do; for Loop, polygons with more
 * than three corners split into triangles as vtkSubDLoopFilter splits them, with a warning).
 * Bad input (no polygons, NaN points, a location outside its face or on a missing or hole face,
 * or on a polygon Loop split into triangles) is an error naming the culprit, with an empty
 * output.
 *
 * Pieces of a distributed mesh (as vtkSubDSurfaceFilter): the tessellation of a piece asks
 * upstream for one layer of ghost cells - the limit surface over a face depends on the faces
 * around its corners only - and tessellates its own faces, so that the pieces together are the
 * whole tessellation (points on the seams are in both pieces; "FaceId" is a cell id of the
 * piece). Asked for ghost levels itself, it asks for that many more and adds the first layers
 * of ghost faces, marked in "vtkGhostType". A piece without polygons gives an empty output.
 * The locations are not split: each piece evaluates the locations it is given on the cells of
 * its own input. Adaptive and selective tessellations are made of the whole mesh (a face takes
 * the points of its neighbours' refinement, and they those of theirs): the first piece asks
 * upstream for all of it and holds the whole tessellation, the others are empty.
 *
 * @sa vtkSubDCatmullClarkFilter vtkSubDLoopFilter
 */
#ifndef vtkSubDLimitFilter_h
#define vtkSubDLimitFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <cstdint> // for subd::Index
#include <vector>

struct vtkSubDCage;
struct vtkSubDLimitSamples;
namespace subd
{
using Index = std::int32_t;
class LimitEvaluator;
}

class SUBDFILTERS_EXPORT vtkSubDLimitFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSubDLimitFilter* New();
  vtkTypeMacro(vtkSubDLimitFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Schemes
  {
    CATMULL_CLARK = 0,
    LOOP = 1
  };

  ///@{
  /// The scheme whose limit surface is evaluated (default CATMULL_CLARK).
  vtkSetClampMacro(Scheme, int, CATMULL_CLARK, LOOP);
  vtkGetMacro(Scheme, int);
  void SetSchemeToCatmullClark() { this->SetScheme(CATMULL_CLARK); }
  void SetSchemeToLoop() { this->SetScheme(LOOP); }
  ///@}

  ///@{
  /// Segments along each face edge of the tessellation (default 4, 1..1024).
  vtkSetClampMacro(Resolution, int, 1, 1024);
  vtkGetMacro(Resolution, int);
  ///@}

  enum Tessellations
  {
    UNIFORM = 0,
    ADAPTIVE = 1,
    SELECTIVE = 2
  };

  ///@{
  /// How a tessellation is made (default UNIFORM; see the class description). Ignored when
  /// locations are given.
  vtkSetClampMacro(Tessellation, int, UNIFORM, SELECTIVE);
  vtkGetMacro(Tessellation, int);
  void SetTessellationToUniform() { this->SetTessellation(UNIFORM); }
  void SetTessellationToAdaptive() { this->SetTessellation(ADAPTIVE); }
  void SetTessellationToSelective() { this->SetTessellation(SELECTIVE); }
  ///@}

  ///@{
  /// ADAPTIVE: the largest distance from a triangle to the limit surface, a fraction of the
  /// cage's bounding-box diagonal (default 1e-3), or in the cage's units when
  /// ToleranceIsAbsolute is on (default off). Must be a positive number.
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  vtkSetMacro(ToleranceIsAbsolute, bool);
  vtkGetMacro(ToleranceIsAbsolute, bool);
  vtkBooleanMacro(ToleranceIsAbsolute, bool);
  ///@}

  ///@{
  /// ADAPTIVE and SELECTIVE: the deepest level a face is refined to, 2^level segments along
  /// its edges (default 12, 0..24).
  vtkSetClampMacro(MaximumLevel, int, 0, 24);
  vtkGetMacro(MaximumLevel, int);
  ///@}

  ///@{
  /// SELECTIVE: the cell-data array of the level each input polygon asks for (default
  /// "RefineLevel").
  vtkSetStringMacro(RefineLevelArrayName);
  vtkGetStringMacro(RefineLevelArrayName);
  ///@}

  ///@{
  /// ADAPTIVE and SELECTIVE: the most memory (MiB) the output may take; a request that would
  /// exceed it is refused before allocation (default half the physical memory).
  vtkSetClampMacro(MaximumMemory, double, 1.0, 1.0e9);
  vtkGetMacro(MaximumMemory, double);
  ///@}

  ///@{
  /// As vtkSubDSurfaceFilter: points with identical coordinates are one vertex (default on),
  /// and point data that differ between them (texture coordinates at seams) are face-varying,
  /// their limit that of OpenSubdiv's FaceVaryingInterpolation mode (default corners-plus1,
  /// vtkSubDSurfaceFilter::FVAR_*); the output is split at such seams, a point per side.
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  vtkSetClampMacro(FaceVaryingInterpolation, int, 0, 5);
  vtkGetMacro(FaceVaryingInterpolation, int);
  ///@}

  ///@{
  /// As vtkSubDSurfaceFilter: 0 none, 1 edge only (default), 2 edge and corner.
  vtkSetClampMacro(BoundaryRule, int, 0, 2);
  vtkGetMacro(BoundaryRule, int);
  /// As vtkSubDSurfaceFilter: 0 uniform (default), 1 Chaikin.
  vtkSetClampMacro(CreaseMethod, int, 0, 1);
  vtkGetMacro(CreaseMethod, int);
  ///@}

  ///@{
  /// The arrays to add (see the class description).
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  vtkSetMacro(ComputeCurvature, bool);
  vtkGetMacro(ComputeCurvature, bool);
  vtkBooleanMacro(ComputeCurvature, bool);
  vtkSetMacro(ComputeDerivatives, bool);
  vtkGetMacro(ComputeDerivatives, bool);
  vtkBooleanMacro(ComputeDerivatives, bool);
  vtkSetMacro(ComputeLocations, bool);
  vtkGetMacro(ComputeLocations, bool);
  vtkBooleanMacro(ComputeLocations, bool);
  ///@}

  /// The locations to evaluate at (optional second input; see the class description).
  void SetLocationsConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

protected:
  vtkSubDLimitFilter();
  ~vtkSubDLimitFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// Passes the requested piece upstream with one layer of ghost cells (plus those asked of the
  /// output) when the mesh is split into several pieces; the locations get the same piece.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// RequestData's work; RequestData runs it and turns running out of memory into an error.
  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  /// Reads the input's polygons and sharp features as the settings ask; false after an error.
  bool ReadCage(vtkPolyData* input, vtkSubDCage& cage);
  /// The tessellation of `faces` the settings ask for; false after an error.
  bool Tessellate(vtkPolyData* input, const vtkSubDCage& cage, const subd::LimitEvaluator& evaluator,
    const std::vector<subd::Index>& faces, vtkSubDLimitSamples& samples);

  int Scheme = CATMULL_CLARK;
  int Resolution = 4;
  int BoundaryRule = 1;
  int CreaseMethod = 0;
  bool ComputeNormals = true;
  bool ComputeCurvature = false;
  bool ComputeDerivatives = false;
  bool ComputeLocations = false;
  bool WeldCoincidentPoints = true;
  int FaceVaryingInterpolation = 2;
  int Tessellation = UNIFORM;
  double Tolerance = 1e-3;
  bool ToleranceIsAbsolute = false;
  int MaximumLevel = 12;
  char* RefineLevelArrayName = nullptr;
  double MaximumMemory;

private:
  vtkSubDLimitFilter(const vtkSubDLimitFilter&) = delete;
  void operator=(const vtkSubDLimitFilter&) = delete;
};

#endif
