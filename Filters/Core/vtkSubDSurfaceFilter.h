/**
 * @class   vtkSubDSurfaceFilter
 * @brief   base class of SubD's subdivision surface filters
 *
 * vtkSubDSurfaceFilter does everything a subdivision surface filter needs except choosing
 * the rules: a subclass names its scheme (CreateScheme) and exposes the scheme's own
 * options; this class
 *
 * - reads the input's polygons (any size; triangle strips are split into triangles) straight
 *   from its offsets/connectivity arrays, screens them (faces with fewer than three corners
 *   or two distinct points are dropped with one warning; out-of-range point ids are an
 *   error), and for triangle-only schemes splits larger polygons into triangles by ear
 *   clipping, which is correct for concave polygons too (one warning),
 * - keeps a polygon that names a point at several corners (a quad 4 3 5 5 closing a pole) as
 *   OpenSubdiv does, in the schemes that OpenSubdiv has (Catmull-Clark, Loop and the linear
 *   scheme; see CollapseRepeatedCorners); the other schemes collapse the repeats; one
 *   warning counts such polygons,
 * - welds points with identical coordinates (WeldCoincidentPoints), so that a mesh split at
 *   its texture seams by VTK's readers is subdivided whole; point data that differ across
 *   such points are face-varying (FaceVaryingInterpolation, OpenSubdiv's rules) and the
 *   output is split again at the seams (docs/face-varying.md),
 * - builds the kernel topology, tagging non-manifold edges and vertices, which are then
 *   subdivided as infinitely sharp (OpenSubdiv's behaviour) after one warning,
 * - refines NumberOfSubdivisions levels, or reuses the stencils of the previous execution when
 *   the connectivity and options did not change (only the points are re-evaluated),
 * - applies the stencils, in parallel with vtkSMPTools, to the points and to every point-data
 *   array (integer arrays are rounded and clamped to their type's range, so negative weights
 *   can never wrap a colour; arrays flagged as normals are re-normalized),
 * - gives every output face the cell data of the input cell it comes from, and optionally a
 *   vtkIdTypeArray "ParentCellId" naming that cell,
 * - writes the output faces directly into offsets/connectivity arrays,
 * - reports progress per level and inside long loops, and honours AbortExecute.
 *
 * Bad input never crashes: an empty input, input without polygons, NaN or infinite
 * coordinates and out-of-range point ids each give an error message naming the problem and
 * an empty output. A request whose predicted peak memory exceeds MaximumMemory (MiB) is
 * refused with a message before anything large is allocated.
 *
 * Sharp features (DeRose, Kass, Truong, "Subdivision Surfaces in Character Animation",
 * SIGGRAPH 1998), read from the input:
 *
 * - crease edges: the segments of the input's Lines (lines or polylines) that are edges of
 *   the surface, with their sharpness in the cell-data array "Sharpness" on OpenSubdiv's
 *   scale (0 smooth, 10 or more infinitely sharp, fractional values allowed; lines without
 *   the array are infinitely sharp). Segments that are not surface edges are passed through
 *   unchanged (with a warning); sharpness on a boundary edge changes nothing, since
 *   boundary edges are infinitely sharp already. A negative or NaN sharpness is an error
 *   naming the cell;
 * - vertex sharpness: the point-data array "CornerSharpness" (a sharp vertex is a corner);
 * - holes: faces whose cell-data array "Hole" is non-zero shape their neighbours but are
 *   not output (as in OpenSubdiv);
 * - AutomaticCreases: edges whose faces meet at more than FeatureAngle become infinitely
 *   sharp.
 *
 * Semi-sharp values lose one unit per level (CreaseMethod Uniform), or are first averaged
 * along the crease (Chaikin); where one reaches zero the rules blend (OpenSubdiv's
 * transitional rules). Catmull-Clark and Loop follow OpenSubdiv exactly; see each scheme's
 * filter for what the other schemes do with creases. The output carries the refined
 * crease edges as 2-point lines (with "Sharpness" decayed by the levels applied) and the
 * decayed "CornerSharpness", so running a filter N times with one level gives the same
 * surface as running it once with N levels (except with holes or BOUNDARY_NONE, whose
 * hole faces are not output, so the next filter cannot see them). Output line cells come
 * before the faces (VTK's cell order); their other cell-data values are zero.
 *
 * Distributed meshes (VTK's pieces and ghost cells: MPI runs with pvbatch or pvserver,
 * vtkExtractPolyDataPiece, parallel readers): asked for one of several pieces, the filter asks
 * upstream for GetRequiredGhostLevels() layers of ghost cells, subdivides its own and the ghost
 * faces together and outputs only the children of its own faces, so that the pieces' outputs
 * together are the serial output. Points on a seam between pieces appear in every piece that
 * uses them; a crease line along a seam is output by one piece only (vtkSubDPieces.h). Asked
 * for ghost levels itself, it asks upstream
 * for that many more and also outputs the children of the first layers of ghost faces, marked
 * in "vtkGhostType" (DUPLICATECELL; points on no own face DUPLICATEPOINT). Doo-Sabin and the
 * midpoint scheme make faces from faces of two pieces: every piece numbers its faces alike
 * (by global cell id, else by their points' coordinates) to agree on which one outputs such
 * a face (vtkSubDPieces.h). A piece without polygons gives an empty output, no error; a piece
 * that came without any ghost cell gets a warning (its seams would be subdivided as boundaries).
 *
 * BoundaryRule has OpenSubdiv's meanings (Sdc::Options::VtxBoundaryInterpolation):
 * None (faces at the boundary become holes that shape the surface but are not output),
 * EdgeOnly (default: boundary edges are sharp creases) and EdgeAndCorner (also pins corners,
 * the vertices with a single face).
 *
 * @sa vtkSubDCatmullClarkFilter
 */
#ifndef vtkSubDSurfaceFilter_h
#define vtkSubDSurfaceFilter_h

#include "SubDFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // MakeOutputFaces

#include <functional> // EvaluationProgress
#include <utility>    // InterpolatePointData
#include <vector>     // AddTangentMaskNormals

namespace subd
{
class Scheme;
class MeshTopology;
struct BaseTags;
}
class vtkCellArray;
class vtkDataArray;
class vtkPointData;
class vtkSubDPointDataInterpolation;
struct vtkSubDFeatureArrayNames;
struct vtkSubDPieceRequest;

class SUBDFILTERS_EXPORT vtkSubDSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkSubDSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BoundaryRules
  {
    BOUNDARY_NONE = 0,
    BOUNDARY_EDGE_ONLY = 1,
    BOUNDARY_EDGE_AND_CORNER = 2
  };

  ///@{
  /**
   * Number of subdivision levels applied (default 1). 0 copies the cleaned input polygons.
   */
  vtkSetClampMacro(NumberOfSubdivisions, int, 0, 30);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  ///@{
  /**
   * Boundary interpolation (default BOUNDARY_EDGE_ONLY), with OpenSubdiv's meanings.
   */
  vtkSetClampMacro(BoundaryRule, int, BOUNDARY_NONE, BOUNDARY_EDGE_AND_CORNER);
  vtkGetMacro(BoundaryRule, int);
  void SetBoundaryRuleToNone() { this->SetBoundaryRule(BOUNDARY_NONE); }
  void SetBoundaryRuleToEdgeOnly() { this->SetBoundaryRule(BOUNDARY_EDGE_ONLY); }
  void SetBoundaryRuleToEdgeAndCorner() { this->SetBoundaryRule(BOUNDARY_EDGE_AND_CORNER); }
  const char* GetBoundaryRuleAsString();
  ///@}

  enum CreaseMethods
  {
    CREASE_UNIFORM = 0,
    CREASE_CHAIKIN = 1
  };

  ///@{
  /**
   * How semi-sharp creases decay from level to level (default CREASE_UNIFORM, one unit per
   * level; CREASE_CHAIKIN first averages each half edge's sharpness with the crease's
   * other edges at its end, OpenSubdiv's Chaikin creasing method).
   */
  vtkSetClampMacro(CreaseMethod, int, CREASE_UNIFORM, CREASE_CHAIKIN);
  vtkGetMacro(CreaseMethod, int);
  void SetCreaseMethodToUniform() { this->SetCreaseMethod(CREASE_UNIFORM); }
  void SetCreaseMethodToChaikin() { this->SetCreaseMethod(CREASE_CHAIKIN); }
  const char* GetCreaseMethodAsString();
  ///@}

  ///@{
  /**
   * Make every edge whose two faces meet at a dihedral angle above FeatureAngle (degrees,
   * default 30) an infinitely sharp crease (default off). The creases then depend on the
   * point positions, so cached stencils are not reused while it is on.
   */
  vtkSetMacro(AutomaticCreases, bool);
  vtkGetMacro(AutomaticCreases, bool);
  vtkBooleanMacro(AutomaticCreases, bool);
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /**
   * What to do with a polygon that names a point at several corners (a quad 4 3 5 5, or
   * 81 81 81 82 left by welding). Off (default): Catmull-Clark, Loop (triangles; larger
   * polygons are collapsed before they are triangulated) and the linear scheme keep it as
   * OpenSubdiv does: the face keeps its corners, an edge from a point to itself is an edge of
   * its own and every edge and point involved is non-manifold, hence infinitely sharp, so the
   * repeated point stays a corner of the surface; the output then equals OpenSubdiv's. On:
   * consecutive repeats are removed first (4 3 5 5 becomes the triangle 4 3 5), the surface is
   * smooth there, and a polygon that still repeats a point is dropped. Doo-Sabin, the midpoint
   * scheme, sqrt(3) and butterfly always collapse. Either way one warning counts the
   * polygons.
   */
  vtkSetMacro(CollapseRepeatedCorners, bool);
  vtkGetMacro(CollapseRepeatedCorners, bool);
  vtkBooleanMacro(CollapseRepeatedCorners, bool);
  ///@}

  ///@{
  /**
   * Make input points with identical coordinates one vertex (default on). VTK's readers of
   * textured meshes (vtkOBJReader, vtkGLTFReader) split the points along every texture seam,
   * which would otherwise be subdivided as a cut: a crease along each seam. Point-data arrays
   * whose values differ between such points (texture coordinates, normals) are face-varying:
   * Catmull-Clark, Loop and the linear scheme refine them as OpenSubdiv refines face-varying
   * data, with FaceVaryingInterpolation, and the output is split again where the input was,
   * so textures map as before; the other arrays stay vertex data. Doo-Sabin, the midpoint
   * scheme, sqrt(3) and butterfly weld only points whose data agree too (their seams stay
   * boundaries).
   */
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  ///@}

  /// OpenSubdiv's FVarLinearInterpolation: what stays linear in face-varying data.
  enum FaceVaryingInterpolations
  {
    FVAR_LINEAR_NONE = 0,
    FVAR_LINEAR_CORNERS_ONLY = 1,
    FVAR_LINEAR_CORNERS_PLUS1 = 2,
    FVAR_LINEAR_CORNERS_PLUS2 = 3,
    FVAR_LINEAR_BOUNDARIES = 4,
    FVAR_LINEAR_ALL = 5
  };

  ///@{
  /**
   * How face-varying data (see WeldCoincidentPoints) is interpolated, with OpenSubdiv's (and
   * USD's) meanings: NONE smooth everywhere; CORNERS_ONLY keeps the corners of each region
   * (a value with one face); CORNERS_PLUS1 (default, USD's) also where three or more regions
   * meet; CORNERS_PLUS2 also the ends of seams inside the surface and concave corners;
   * BOUNDARIES keeps seams and boundaries linear; ALL is linear everywhere.
   */
  vtkSetClampMacro(FaceVaryingInterpolation, int, FVAR_LINEAR_NONE, FVAR_LINEAR_ALL);
  vtkGetMacro(FaceVaryingInterpolation, int);
  /// The mode's name as OpenSubdiv's and USD's users write it ("corners-plus1", ...).
  static const char* GetFaceVaryingInterpolationName(int mode);
  /// The mode of that name, or -1 for any other.
  static int FaceVaryingInterpolationFromName(const char* name);
  ///@}

  ///@{
  /**
   * Precision of the output points: vtkAlgorithm::DEFAULT_PRECISION (that of the input
   * points), SINGLE_PRECISION or DOUBLE_PRECISION. Computation is always in double.
   */
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /**
   * Move the output points to the limit surface (default off): after the levels, each
   * vertex is replaced by the point of the limit surface it converges to, by the scheme's
   * limit masks. Every point-data array is projected with the same masks.
   * - Catmull-Clark and Loop: with their crease, corner and boundary rules, matching
   *   OpenSubdiv's PrimvarRefiner::Limit (SubDLimitRules.h). Catmull-Clark needs quads:
   *   with polygons other than quads, ask for at least one level.
   * - sqrt(3): Kobbelt's limit mask, the cubic B-spline's along boundaries and creases
   *   (SubDSqrt3Limit.h).
   * - Doo-Sabin and midpoint, which do not keep vertices: the centroid of the vertex's
   *   V-face, a point of the limit surface; along creases and boundaries the point of the
   *   crease's limit curve (SubDDualLimit.h).
   * - Linear and butterfly interpolate: their vertices are on the limit already.
   * Where a scheme has no closed form (darts of sqrt(3), Doo-Sabin and midpoint), the
   * filter reports an error naming the vertex.
   */
  vtkSetMacro(ProjectToLimit, bool);
  vtkGetMacro(ProjectToLimit, bool);
  vtkBooleanMacro(ProjectToLimit, bool);
  ///@}

  ///@{
  /**
   * Add the exact normals of the limit surface as the point-data array "Normals" (default
   * off): at each output point, the normal of the limit surface at the point its vertex
   * converges to (where ProjectToLimit puts it), from the limit tangents, not by averaging
   * face normals.
   * - Catmull-Clark and Loop: first derivatives of the regular B-spline or box-spline
   *   patches, and at extraordinary vertices, darts, creases and corners the eigenvectors
   *   of the subdivision matrix (SubDLimitEvaluator.h). On a crease or at a corner the
   *   surface has one normal per side: the point gets their normalized mean.
   * - sqrt(3), Doo-Sabin and midpoint at smooth vertices (no crease or boundary edge): the
   *   Fourier tangent masks of the ring that one step maps onto itself (SubDRingTangents.h).
   *   At other vertices these schemes have no published tangent masks: an error names the
   *   vertex.
   * - Linear and butterfly: not available (an error).
   * The input's normals (its active normals, or an array named "Normals") are then not
   * interpolated: the limit normals replace them.
   */
  vtkSetMacro(ComputeLimitNormals, bool);
  vtkGetMacro(ComputeLimitNormals, bool);
  vtkBooleanMacro(ComputeLimitNormals, bool);
  ///@}

  ///@{
  /**
   * Add the curvature of the limit surface at each output point's limit point (default off),
   * from the exact first and second derivatives of the limit surface: "Mean_Curvature",
   * "Gauss_Curvature", "Maximum_Curvature", "Minimum_Curvature" (vtkCurvatures' names; a
   * convex closed surface has positive curvature) and the unit principal directions
   * "Maximum_Curvature_Direction", "Minimum_Curvature_Direction". At an extraordinary vertex,
   * where curvature is in general not defined, the values are those at the centre of the
   * vertex's sub-face 2^-10 across in one of its faces (SubDLimitEvaluator.h); on a crease,
   * the mean of both sides. Catmull-Clark and Loop only.
   */
  vtkSetMacro(ComputeCurvature, bool);
  vtkGetMacro(ComputeCurvature, bool);
  vtkBooleanMacro(ComputeCurvature, bool);
  ///@}

  ///@{
  /**
   * Add a vtkIdTypeArray "ParentCellId" to the output cell data, naming for each output face
   * the input cell it descends from (default off).
   */
  vtkSetMacro(GenerateParentCellIds, bool);
  vtkGetMacro(GenerateParentCellIds, bool);
  vtkBooleanMacro(GenerateParentCellIds, bool);
  ///@}

  ///@{
  /**
   * Refuse requests whose predicted peak memory is more than this many MiB (default: half the
   * physical memory), with an error naming the estimate, before allocating anything. The
   * prediction (SubDMemoryEstimate.h) follows the refinement level by level and errs on the
   * safe side.
   */
  vtkSetClampMacro(MaximumMemory, double, 1.0, 1.0e9);
  vtkGetMacro(MaximumMemory, double);
  ///@}

  ///@{
  /**
   * The arrays the sharp features are read from, and written to in the output: the cell-data
   * array of the crease lines' sharpness (default "Sharpness"), the point-data array of the
   * vertex sharpness (default "CornerSharpness") and the cell-data array marking hole faces
   * (default "Hole"). An empty name (or nullptr) reads no such array.
   */
  vtkSetStringMacro(SharpnessArrayName);
  vtkGetStringMacro(SharpnessArrayName);
  vtkSetStringMacro(CornerSharpnessArrayName);
  vtkGetStringMacro(CornerSharpnessArrayName);
  vtkSetStringMacro(HoleArrayName);
  vtkGetStringMacro(HoleArrayName);
  ///@}

  /**
   * Layers of ghost cells a piece of a distributed mesh needs around its own cells for its
   * children to be those of the whole mesh, at the current NumberOfSubdivisions (0 for none):
   * how far the stencils of all levels together reach, in cells. 1 for the schemes whose
   * stencils read a point's 1-ring (Catmull-Clark, Loop, linear, Doo-Sabin, midpoint); see
   * the other filters for theirs. Requested upstream by RequestUpdateExtent, plus the ghost
 * levels asked of the output.
   */
  virtual int GetRequiredGhostLevels() { return this->NumberOfSubdivisions > 0 ? 1 : 0; }

  /**
   * Number of times the stencils were rebuilt (not reused from the previous execution).
   * Lets applications and tests verify that point-only changes are cheap.
   */
  vtkGetMacro(NumberOfStencilBuilds, int);

protected:
  vtkSubDSurfaceFilter();
  ~vtkSubDSurfaceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Passes the requested piece upstream, with GetRequiredGhostLevels() ghost levels (plus those
  /// asked of the output) when the mesh is split into several pieces.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// RequestData's work, a recipe of the steps below; RequestData runs it and turns running
  /// out of memory into an error.
  int Execute(vtkInformation*, vtkInformationVector**, vtkInformationVector*);

  /// The subclass's scheme; called when the stencils must be (re)built. `allTriangles` tells
  /// whether every (screened) input face is a triangle.
  virtual subd::Scheme* NewScheme(bool allTriangles) = 0;

  /// Adds the limit normals and curvature arrays (ComputeLimitNormals, ComputeCurvature) of the
  /// output points; false (with an error message) if evaluation failed.
  bool AddLimitGeometry(const double* basePoints, vtkPointData* outPD);
  vtkSmartPointer<vtkCellArray> MakeOutputFaces();
  /// SharpnessArrayName, CornerSharpnessArrayName and HoleArrayName, for vtkSubDSharpFeatures.
  vtkSubDFeatureArrayNames GetFeatureArrayNames() const;
  /// The normals from the scheme's tangent masks (schemes LimitEvaluator does not handle).
  void AddTangentMaskNormals(const std::vector<double>& control, vtkIdType numOut, vtkPointData* outPD);

  /// True for schemes that make faces from several faces (the edge and vertex faces of
  /// Doo-Sabin and the midpoint scheme): their pieces must number faces alike to agree on
  /// which of them outputs such a face.
  virtual bool MakesFacesFromSeveralFaces() { return false; }

  /// True for schemes defined on triangles only; polygons are then triangulated first (ear
  /// clipping, correct for concave polygons), with one warning, instead of being refused.
  virtual bool RequiresTriangles() { return false; }

  /// True for schemes that refine a polygon repeating a point as OpenSubdiv does
  /// (CollapseRepeatedCorners); the others have it collapsed.
  virtual bool KeepsRepeatedCorners() { return false; }

  /// True for schemes that refine face-varying data (WeldCoincidentPoints): their child faces
  /// are their parents' split corner for corner, so a channel's faces follow the mesh's.
  virtual bool RefinesFaceVaryingData() { return false; }

  int NumberOfSubdivisions = 1;
  int BoundaryRule = BOUNDARY_EDGE_ONLY;
  int CreaseMethod = CREASE_UNIFORM;
  bool AutomaticCreases = false;
  double FeatureAngle = 30.0;
  bool CollapseRepeatedCorners = false;
  bool WeldCoincidentPoints = true;
  int FaceVaryingInterpolation = FVAR_LINEAR_CORNERS_PLUS1;
  int OutputPointsPrecision = DEFAULT_PRECISION;
  bool GenerateParentCellIds = false;
  bool ProjectToLimit = false;
  char* SharpnessArrayName = nullptr;
  char* CornerSharpnessArrayName = nullptr;
  char* HoleArrayName = nullptr;
  bool ComputeLimitNormals = false;
  bool ComputeCurvature = false;
  double MaximumMemory; // half the physical memory (vtkSubDMemoryBudget.h)
  int NumberOfStencilBuilds = 0;

private:
  vtkSubDSurfaceFilter(const vtkSubDSurfaceFilter&) = delete;
  void operator=(const vtkSubDSurfaceFilter&) = delete;

  /// How a step ended: an abort (AbortExecute) is not a failure.
  enum class Status
  {
    Done,
    Failed,
    Aborted
  };
  struct vtkInputMesh;
  /// Input mesh: the points checked, the polygons screened (and triangulated where the scheme
  /// needs triangles), each kept face's input cell, ghost faces, sharp features.
  bool ReadInputMesh(vtkPolyData* input, const vtkSubDPieceRequest& request, vtkInputMesh& mesh);
  bool ReadInputPoints(vtkPolyData* input);
  bool ScreenInputFaces(vtkPolyData* input, vtkInputMesh& mesh);
  /// Whether the cached refinement fits this input (only its points or data changed).
  bool CanReuseRefinement(const vtkInputMesh& mesh, int outputGhostLevels);
  /// Refinement: topology, size guard, base tags, the levels, limit tables; cached.
  Status BuildRefinement(vtkPolyData* input, vtkInputMesh& mesh, int outputGhostLevels);
  /// The size guard: refuses (with an error) a refinement whose output or peak memory would
  /// be too large; `fullFinest`: the finest level keeps its full topology.
  bool FitsTheMemoryBudget(
    const subd::Scheme& scheme, const subd::MeshTopology& topology, vtkPointData* inPD, bool fullFinest);
  void ReadBaseTags(
    vtkPolyData* input, const vtkInputMesh& mesh, const subd::MeshTopology& topology, subd::BaseTags& tags);
  bool AddLimitTables();
  /// Output mesh: points, point data, sharp features, faces, cell data.
  Status WriteOutput(vtkPolyData* input, const vtkInputMesh& mesh, bool reuse, vtkPolyData* output);
  Status WritePoints(vtkPolyData* input, vtkSubDPointDataInterpolation& interpolation, vtkPolyData* output);
  /// Whether point-data array `a` is left out for the limit normals (ComputeLimitNormals).
  bool IsReplacedByLimitNormals(vtkPointData* inPD, int a) const;
  bool InterpolatePointData(vtkPolyData* input, vtkSubDPointDataInterpolation& interpolation, vtkPolyData* output,
    std::vector<std::pair<vtkDataArray*, vtkDataArray*>>& interpolated);
  void AddCellData(
    vtkPolyData* input, const vtkInputMesh& mesh, const std::vector<float>& lineSharpness, vtkPolyData* output);
  /// The progress of evaluating the points (step 0) or the point-data array step - 1.
  std::function<bool(double)> EvaluationProgress(vtkPolyData* input, int step);

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
