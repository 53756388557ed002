"""One call per job: subdivide, read and write meshes given as vtkPolyData or numpy arrays.

The option names and defaults are those of the ``subd`` program (docs/cli.md); each call
configures the matching VTK filter (``vtkSubDCatmullClarkFilter``, ...) and runs it.
"""
import collections
import numbers
import os
import re
import warnings

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

from . import SubDFilters as _filters
from . import SubDIO as _io

Mesh = collections.namedtuple("Mesh", "points faces creases point_data cell_data")
Mesh.__doc__ = """A mesh as arrays, as subdivide returns it for arrays in.

points: (N, 3) float64. faces: (F, k) int64 when every face has k corners, else a pair
(offsets, connectivity) (face f is connectivity[offsets[f]:offsets[f + 1]]). creases: (E, 3)
float64 rows (i, j, sharpness), the crease edges (pass them back in to refine further).
point_data, cell_data: dicts of name -> array (cell_data per face)."""

Curve = collections.namedtuple("Curve", "points polylines point_data")
Curve.__doc__ = """Polylines as arrays, as refine_curve returns them for arrays in: points (N, 3)
float64, polylines a list of int64 index arrays, point_data a dict of name -> array."""

SURFACE_SCHEMES = {
    "catmull-clark": _filters.vtkSubDCatmullClarkFilter,
    "loop": _filters.vtkSubDLoopFilter,
    "butterfly": _filters.vtkSubDButterflyFilter,
    "doo-sabin": _filters.vtkSubDDooSabinFilter,
    "midpoint": _filters.vtkSubDMidpointFilter,
    "sqrt3": _filters.vtkSubDSqrt3Filter,
    "linear": _filters.vtkSubDLinearFilter,
}
BOUNDARY_RULES = ("none", "edge-only", "edge-and-corner")
CREASE_METHODS = ("uniform", "chaikin")


def subdivide(mesh, scheme="catmull-clark", levels=2, boundary="edge-only", crease_method="uniform",
              creases=None, corners=None, holes=None, feature_angle=None, limit=False, normals=False,
              curvature=False, tension=None, weld=True, fvar_interpolation="corners-plus1",
              smooth_triangles=False, collapse_repeated_corners=False):
    """Subdivides a polygon mesh; returns the result as the input came (vtkPolyData or Mesh).

    mesh: a vtkPolyData, or a pair (points, faces): points an (N, 3) array-like, faces a list
    of index sequences or an (F, k) integer array.
    scheme: catmull-clark, loop, butterfly, doo-sabin, midpoint, sqrt3 or linear.
    levels: subdivision steps (0..30).
    boundary: none, edge-only or edge-and-corner (the boundary interpolation rule).
    crease_method: uniform or chaikin (how semi-sharp creases decay).
    creases: [(i, j, sharpness), ...] or an (E, 3) array: sharp edges (10 = infinitely sharp).
    corners: {vertex: sharpness} or a (K, 2) array: sharp vertices.
    holes: face ids that are holes.
    feature_angle: edges whose faces meet at more than this many degrees become creases.
    limit: move the output points to the limit surface.
    normals, curvature: add the exact limit normals / curvature arrays (catmull-clark, loop).
    tension: butterfly's tension w in [-0.0625, 0.0625].
    weld: make points at one position one vertex (texture seams), as the filters do.
    fvar_interpolation: none, corners-only, corners-plus1, corners-plus2, boundaries or all:
        how texture coordinates split at seams are refined.
    smooth_triangles: catmull-clark: OpenSubdiv's smooth rule for triangles.
    collapse_repeated_corners: collapse polygons that name a point twice.

    Raises TypeError or ValueError for bad arguments and RuntimeError with the filter's
    message when the filter fails; its warnings become RuntimeWarnings.
    """
    polydata, as_arrays = _to_polydata(mesh)
    _add_sharp_features(polydata, creases, corners, holes)
    options = dict(levels=levels, boundary=boundary, crease_method=crease_method, feature_angle=feature_angle,
                   limit=limit, normals=normals, curvature=curvature, tension=tension, weld=weld,
                   fvar_interpolation=fvar_interpolation, smooth_triangles=smooth_triangles,
                   collapse_repeated_corners=collapse_repeated_corners)
    output = _run(make_filter(scheme, **options), polydata)
    return to_arrays(output) if as_arrays else output


def make_filter(scheme="catmull-clark", levels=2, boundary="edge-only", crease_method="uniform",
                feature_angle=None, limit=False, normals=False, curvature=False, tension=None, weld=True,
                fvar_interpolation="corners-plus1", smooth_triangles=False, collapse_repeated_corners=False):
    """The surface filter subdivide runs, configured (the same options, checked alike)."""
    if scheme not in SURFACE_SCHEMES:
        raise ValueError("scheme %r is not one of %s" % (scheme, ", ".join(SURFACE_SCHEMES)))
    filter_ = SURFACE_SCHEMES[scheme]()
    filter_.SetNumberOfSubdivisions(_integer_in("levels", levels, 0, 30))
    filter_.SetBoundaryRule(_choice("boundary", boundary, BOUNDARY_RULES))
    filter_.SetCreaseMethod(_choice("crease_method", crease_method, CREASE_METHODS))
    if feature_angle is not None:
        angle = _number("feature_angle", feature_angle)
        if not 0.0 < angle < 180.0:
            raise ValueError("feature_angle must be in (0, 180) degrees, not %r" % feature_angle)
        filter_.SetAutomaticCreases(True)
        filter_.SetFeatureAngle(angle)
    filter_.SetProjectToLimit(bool(limit))
    filter_.SetComputeLimitNormals(bool(normals))
    filter_.SetComputeCurvature(bool(curvature))
    filter_.SetWeldCoincidentPoints(bool(weld))
    filter_.SetCollapseRepeatedCorners(bool(collapse_repeated_corners))
    filter_.SetFaceVaryingInterpolation(_fvar_mode(fvar_interpolation))
    if tension is not None:
        if scheme != "butterfly":
            raise ValueError("tension applies to the butterfly scheme, not to %s" % scheme)
        w = _number("tension", tension)
        if not -0.0625 <= w <= 0.0625:
            raise ValueError("tension must be in [-0.0625, 0.0625], not %r" % tension)
        filter_.SetTension(w)
    if smooth_triangles:
        if scheme != "catmull-clark":
            raise ValueError("smooth_triangles applies to catmull-clark, not to %s" % scheme)
        filter_.SetSmoothTriangles(True)
    return filter_


LIMIT_SCHEMES = ("catmull-clark", "loop")
INTERPOLATING_SCHEMES = ("catmull-clark", "loop", "doo-sabin")
CURVE_SCHEMES = ("chaikin", "bspline", "four-point")


def limit_surface(mesh, scheme="catmull-clark", resolution=4, samples=None, boundary="edge-only",
                  crease_method="uniform", creases=None, corners=None, holes=None, normals=True,
                  curvature=False, derivatives=False, tolerance=None, tolerance_is_absolute=False,
                  refine_levels=None, max_level=12, locations=False, weld=True,
                  fvar_interpolation="corners-plus1"):
    """The exact limit surface of a cage (vtkSubDLimitFilter), tessellated or sampled.

    Without samples: a watertight tessellation with `resolution` segments per face edge
    (quads for catmull-clark, triangles for loop), each cell with "FaceId", its cage face; or
    tolerance: triangles within that distance of the limit surface (a fraction of the cage's
    bounding-box diagonal, or in its units with tolerance_is_absolute), refined only where the
    surface curves, crack-free; or refine_levels: per cage face, the level it is refined to
    (the uniform tessellation at resolution 2^level there), crack-free where levels meet. Both
    go at most max_level deep. locations: add the "FaceId", "FaceUV", "SubFace" point data each
    point was evaluated at. weld, fvar_interpolation: as for subdivide (texture coordinates
    split at seams follow the face-varying limit; the output is split there again).
    samples: (face_ids, uv): the limit at those (face, u, v), as points (a Mesh with no faces,
    or a vtkPolyData of vertices); uv in the unit square of a quad, the unit triangle of a
    triangle. normals, curvature, derivatives: "Normals", the curvature arrays, "dPdu"/"dPdv".
    Other options as for subdivide.
    """
    polydata, as_arrays = _to_polydata(mesh)
    _add_sharp_features(polydata, creases, corners, holes)
    filter_ = _filters.vtkSubDLimitFilter()
    filter_.SetScheme(_choice("scheme", scheme, LIMIT_SCHEMES))
    filter_.SetResolution(_integer_in("resolution", resolution, 1, 1024))
    filter_.SetBoundaryRule(_choice("boundary", boundary, BOUNDARY_RULES))
    filter_.SetCreaseMethod(_choice("crease_method", crease_method, CREASE_METHODS))
    filter_.SetComputeNormals(bool(normals))
    filter_.SetComputeCurvature(bool(curvature))
    filter_.SetComputeDerivatives(bool(derivatives))
    filter_.SetComputeLocations(bool(locations))
    filter_.SetWeldCoincidentPoints(bool(weld))
    filter_.SetFaceVaryingInterpolation(_fvar_mode(fvar_interpolation))
    filter_.SetMaximumLevel(_integer_in("max_level", max_level, 0, 24))
    if sum(x is not None for x in (samples, tolerance, refine_levels)) > 1:
        raise ValueError("give at most one of samples, tolerance and refine_levels")
    if tolerance is not None:
        tolerance = _number("tolerance", tolerance)
        if not (np.isfinite(tolerance) and tolerance > 0):
            raise ValueError("tolerance must be a positive number, not %r" % tolerance)
        filter_.SetTessellationToAdaptive()
        filter_.SetTolerance(tolerance)
        filter_.SetToleranceIsAbsolute(bool(tolerance_is_absolute))
    if refine_levels is not None:
        levels = np.asarray(refine_levels)
        faces = polydata.GetNumberOfPolys()
        if levels.shape != (faces,) or not np.issubdtype(levels.dtype, np.integer):
            raise ValueError("refine_levels must be one integer per face (%d), not %s %s"
                             % (faces, levels.dtype, levels.shape))
        cell_levels = np.zeros(polydata.GetNumberOfCells(), np.int32)
        cell_levels[polydata.GetNumberOfVerts() + polydata.GetNumberOfLines():][:faces] = levels
        polydata.GetCellData().AddArray(_named(cell_levels, "RefineLevel"))
        filter_.SetTessellationToSelective()
    if samples is not None:
        filter_.SetInputData(1, _locations(samples))
    output = _run(filter_, polydata)
    return to_arrays(output) if as_arrays else output


def interpolate(mesh, scheme="catmull-clark", targets=None, levels=None, boundary="edge-only",
                crease_method="uniform", creases=None, corners=None, holes=None):
    """A cage whose limit surface passes through the mesh's vertices (vtkSubDInterpolateFilter).

    scheme: catmull-clark, loop or doo-sabin. targets: the vertex ids to pass through (default:
    all); the others keep their positions. levels: instead of the cage, its surface refined
    that many levels. Other options as for subdivide. A system that has no unique solution is
    a RuntimeError naming the cause.
    """
    polydata, as_arrays = _to_polydata(mesh)
    _add_sharp_features(polydata, creases, corners, holes)
    filter_ = _filters.vtkSubDInterpolateFilter()
    filter_.SetScheme(_choice("scheme", scheme, INTERPOLATING_SCHEMES))
    filter_.SetBoundaryRule(_choice("boundary", boundary, BOUNDARY_RULES))
    filter_.SetCreaseMethod(_choice("crease_method", crease_method, CREASE_METHODS))
    if targets is not None:
        ids = np.asarray(list(targets), dtype=np.int64)
        if ids.size and (ids.min() < 0 or ids.max() >= polydata.GetNumberOfPoints()):
            raise ValueError("targets must be point ids in [0, %d)" % polydata.GetNumberOfPoints())
        tags = np.zeros(polydata.GetNumberOfPoints(), np.uint8)
        tags[ids] = 1
        polydata.GetPointData().AddArray(_named(tags, "Interpolate"))
    if levels is not None:
        filter_.SetOutputRefinedSurface(True)
        filter_.SetNumberOfSubdivisions(_integer_in("levels", levels, 1, 8))
    output = _run(filter_, polydata)
    return to_arrays(output) if as_arrays else output


def refine_curve(curve, scheme="bspline", levels=2, tension=None, closed=False, corners=None, limit=False,
                 tangents=False):
    """Refines polylines (vtkSubDCurveFilter): Chaikin, the cubic B-spline or the 4-point scheme.

    curve: a vtkPolyData with lines, or a pair (points, polylines): points (N, 3), polylines a
    list of index sequences (or None: one polyline through every point in order).
    tension: the 4-point scheme's w in [0, 0.125] (default 1/16). closed: every polyline is
    closed. corners: {vertex: sharpness} or (K, 2) rows: sharp vertices (10 keeps a sharp tip).
    limit: project to the limit curve. tangents: add the unit limit "Tangents".
    Returns a vtkPolyData, or a Curve of arrays for arrays in.
    """
    polydata, as_arrays = _curve_polydata(curve)
    if corners is not None:
        _add_corners(polydata, corners)
    filter_ = _filters.vtkSubDCurveFilter()
    filter_.SetScheme(_choice("scheme", scheme, CURVE_SCHEMES))
    filter_.SetNumberOfSubdivisions(_integer_in("levels", levels, 0, 30))
    if tension is not None:
        if scheme != "four-point":
            raise ValueError("tension applies to the four-point scheme, not to %s" % scheme)
        w = _number("tension", tension)
        if not 0.0 <= w <= 0.125:
            raise ValueError("tension must be in [0, 0.125], not %r" % tension)
        filter_.SetTension(w)
    filter_.SetClosed(bool(closed))
    filter_.SetProjectToLimit(bool(limit))
    filter_.SetComputeTangents(bool(tangents))
    output = _run(filter_, polydata)
    if not as_arrays:
        return output
    lines = output.GetLines()
    offsets = numpy_support.vtk_to_numpy(lines.GetOffsetsArray()).astype(np.int64)
    connectivity = numpy_support.vtk_to_numpy(lines.GetConnectivityArray()).astype(np.int64)
    points = numpy_support.vtk_to_numpy(output.GetPoints().GetData()).astype(np.float64)
    polylines = [connectivity[offsets[k]:offsets[k + 1]] for k in range(len(offsets) - 1)]
    return Curve(points, polylines, dict(_arrays(output.GetPointData())))


def read(path):
    """The mesh in `path` (.vtp .vtk .obj .ply .stl .off .gltf .glb) as a vtkPolyData."""
    reader = _reader_for(os.fspath(path))
    reader.SetFileName(os.fspath(path))
    output = _run(reader, None)
    if output.GetNumberOfPoints() == 0:
        raise RuntimeError("%s holds no points" % path)
    return output


def write(mesh, path):
    """Writes `mesh` (a vtkPolyData, a Mesh, a Curve or a (points, faces) pair) to `path`, the
    format chosen by its extension (.vtp .vtk .obj .ply .stl .off .gltf)."""
    if isinstance(mesh, Curve):
        polydata = _curve_polydata((mesh.points, mesh.polylines))[0]
        for name, values in mesh.point_data.items():
            polydata.GetPointData().AddArray(_named(values, name))
    else:
        polydata = _to_polydata(mesh)[0]
    writer = _writer_for(os.fspath(path))
    writer.SetFileName(os.fspath(path))
    if _extension(os.fspath(path)) == ".stl":  # STL holds triangles only
        from vtkmodules.vtkFiltersCore import vtkTriangleFilter
        triangles = vtkTriangleFilter()
        triangles.SetInputData(polydata)
        triangles.Update()
        polydata = triangles.GetOutput()
    writer.SetInputData(polydata)
    errors = _observe(writer)
    if writer.Write() != 1 or errors:
        raise RuntimeError("cannot write %s: %s" % (path, "".join(errors) or "the writer failed"))


def to_arrays(polydata):
    """A vtkPolyData's polygons, crease lines and data as a Mesh of numpy arrays."""
    points = numpy_support.vtk_to_numpy(polydata.GetPoints().GetData()).astype(np.float64)
    polys = polydata.GetPolys()
    offsets = numpy_support.vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64)
    connectivity = numpy_support.vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64)
    sizes = np.diff(offsets)
    faces = (connectivity.reshape(-1, int(sizes[0])) if len(sizes) and np.all(sizes == sizes[0])
             else (offsets, connectivity))
    first_poly = polydata.GetNumberOfVerts() + polydata.GetNumberOfLines()
    point_data = {name: array for name, array in _arrays(polydata.GetPointData())}
    cell_data = {name: array[first_poly:first_poly + polys.GetNumberOfCells()]
                 for name, array in _arrays(polydata.GetCellData())}
    return Mesh(points, faces, _crease_rows(polydata), point_data, cell_data)


def from_meshio(mesh):
    """A Mesh of a meshio.Mesh's polygons (its triangle, quad and polygon blocks, in order)
    and point data, ready for subdivide: every format meshio reads works. Other blocks
    (lines, volumes) are left out with a RuntimeWarning naming them."""
    faces, skipped = [], []
    for block in mesh.cells:
        if block.type in ("triangle", "quad") or block.type.startswith("polygon"):
            faces.extend(np.asarray(block.data, dtype=np.int64))
        else:
            skipped.append(block.type)
    if skipped:
        warnings.warn("from_meshio: blocks that are not polygons left out: %s" % ", ".join(skipped),
                      RuntimeWarning, stacklevel=2)
    points = np.asarray(mesh.points, dtype=np.float64)
    if points.ndim == 2 and points.shape[1] == 2:
        points = np.column_stack([points, np.zeros(len(points))])
    offsets, connectivity = _faces(faces, len(points))
    sizes = np.diff(offsets)
    faces_out = (connectivity.reshape(-1, int(sizes[0])) if len(sizes) and np.all(sizes == sizes[0])
                 else (offsets, connectivity))
    point_data = {name: np.asarray(values) for name, values in mesh.point_data.items()}
    return Mesh(_points(points), faces_out, np.zeros((0, 3)), point_data, {})


def to_meshio(mesh):
    """A meshio.Mesh of a mesh (vtkPolyData, Mesh or (points, faces)): its faces in blocks by
    corner count (triangle, quad, polygon) and its point data; write it with meshio.write."""
    import meshio

    arrays = mesh if isinstance(mesh, Mesh) else to_arrays(_to_polydata(mesh)[0])
    offsets, connectivity = (arrays.faces if isinstance(arrays.faces, tuple)
                             else (np.arange(0, arrays.faces.size + 1, arrays.faces.shape[1]), arrays.faces.ravel()))
    sizes = np.diff(offsets)
    cells = []
    for size in sorted(set(sizes.tolist())):
        rows = np.flatnonzero(sizes == size)
        block = connectivity[offsets[rows][:, None] + np.arange(size)]
        cells.append(({3: "triangle", 4: "quad"}.get(size, "polygon"), block))
    return meshio.Mesh(arrays.points, cells, point_data=dict(arrays.point_data))


# --- arguments ---

def _integer_in(name, value, lowest, highest):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError("%s must be an integer, not %s" % (name, type(value).__name__))
    if not lowest <= value <= highest:
        raise ValueError("%s must be in %d..%d, not %d" % (name, lowest, highest, value))
    return int(value)


def _fvar_mode(value):
    mode = _filters.vtkSubDSurfaceFilter.FaceVaryingInterpolationFromName(str(value))
    if mode < 0:
        raise ValueError("fvar_interpolation %r is not one of none, corners-only, corners-plus1, corners-plus2, "
                         "boundaries, all" % (value,))
    return mode


def _number(name, value):
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError("%s must be a number, not %s" % (name, type(value).__name__))
    return float(value)


def _choice(name, value, choices):
    if value not in choices:
        raise ValueError("%s %r is not one of %s" % (name, value, ", ".join(choices)))
    return choices.index(value)


# --- input ---

def _to_polydata(mesh):
    """(a vtkPolyData the caller may change, whether the input was arrays)"""
    if isinstance(mesh, vtkPolyData):
        copy = vtkPolyData()
        copy.ShallowCopy(mesh)
        return copy, False
    if isinstance(mesh, Mesh):
        # A result passed back in: its creases and data come along.
        polydata = _to_polydata(_as_pair(mesh))[0]
        for name, values in mesh.point_data.items():
            polydata.GetPointData().AddArray(_named(values, name))
        for name, values in mesh.cell_data.items():
            polydata.GetCellData().AddArray(_named(values, name))
        _add_creases(polydata, np.asarray(mesh.creases, dtype=np.float64))
        return polydata, True
    if not isinstance(mesh, (tuple, list)) or len(mesh) != 2:
        raise TypeError("mesh must be a vtkPolyData or a (points, faces) pair, not %s" % type(mesh).__name__)
    points = _points(mesh[0])
    offsets, connectivity = _faces(mesh[1], len(points))
    polydata = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(points, deep=1))
    polydata.SetPoints(vtk_points)
    cells = vtkCellArray()
    cells.SetData(numpy_support.numpy_to_vtkIdTypeArray(offsets, deep=1),
                  numpy_support.numpy_to_vtkIdTypeArray(connectivity, deep=1))
    polydata.SetPolys(cells)
    return polydata, True


def _points(values):
    points = np.asarray(values, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise ValueError("points must be an (N, 3) array, not of shape %s" % (points.shape,))
    return points


def _curve_polydata(curve):
    if isinstance(curve, vtkPolyData):
        copy = vtkPolyData()
        copy.ShallowCopy(curve)
        return copy, False
    if not isinstance(curve, (tuple, list)) or len(curve) != 2:
        raise TypeError("curve must be a vtkPolyData or a (points, polylines) pair, not %s" % type(curve).__name__)
    points = _points(curve[0])
    polylines = [np.arange(len(points))] if curve[1] is None else [np.asarray(line) for line in curve[1]]
    lines = vtkCellArray()
    for k, line in enumerate(polylines):
        if line.ndim != 1 or len(line) < 2 or not np.issubdtype(line.dtype, np.integer):
            raise ValueError("polyline %d must be a sequence of 2 or more point ids" % k)
        if line.min() < 0 or line.max() >= len(points):
            raise ValueError("polyline %d names a point outside [0, %d)" % (k, len(points)))
        lines.InsertNextCell(len(line), [int(i) for i in line])
    polydata = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(points, deep=1))
    polydata.SetPoints(vtk_points)
    polydata.SetLines(lines)
    return polydata, True


def _locations(samples):
    """The second input of vtkSubDLimitFilter: points with "FaceId" and "FaceUV"."""
    if not isinstance(samples, (tuple, list)) or len(samples) != 2:
        raise TypeError("samples must be a pair (face_ids, uv)")
    faces = np.asarray(samples[0], dtype=np.int64).ravel()
    uv = np.asarray(samples[1], dtype=np.float64)
    if uv.shape != (len(faces), 2):
        raise ValueError("samples' uv must be a (%d, 2) array, not of shape %s" % (len(faces), uv.shape))
    locations = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetNumberOfPoints(len(faces))
    locations.SetPoints(vtk_points)
    locations.GetPointData().AddArray(_named(faces, "FaceId"))
    locations.GetPointData().AddArray(_named(uv, "FaceUV"))
    return locations


def _as_pair(mesh):
    faces = mesh.faces
    if isinstance(faces, tuple):
        offsets, connectivity = faces
        faces = [connectivity[offsets[f]:offsets[f + 1]] for f in range(len(offsets) - 1)]
    return mesh.points, faces


def _faces(faces, num_points):
    """Offsets and connectivity (int64) of faces given as an (F, k) array or sequences."""
    if isinstance(faces, np.ndarray) and faces.ndim == 2:
        if not np.issubdtype(faces.dtype, np.integer):
            raise TypeError("faces must hold integers, not %s" % faces.dtype)
        connectivity = faces.astype(np.int64).ravel()
        offsets = np.arange(0, connectivity.size + 1, max(faces.shape[1], 1), dtype=np.int64)[:len(faces) + 1]
    else:
        try:
            lists = [np.asarray(face) for face in faces]
        except TypeError:
            raise TypeError("faces must be a list of index sequences or an (F, k) array") from None
        for f, face in enumerate(lists):
            if face.ndim != 1 or (face.size and not np.issubdtype(face.dtype, np.integer)):
                raise TypeError("face %d is not a sequence of integers" % f)
        sizes = np.array([face.size for face in lists], dtype=np.int64)
        offsets = np.concatenate(([0], np.cumsum(sizes))).astype(np.int64)
        connectivity = (np.concatenate(lists).astype(np.int64) if lists else np.zeros(0, np.int64))
    sizes = np.diff(offsets)
    if np.any(sizes < 3):
        short = int(np.argmax(sizes < 3))
        raise ValueError("face %d has %d corners: a polygon needs 3 or more" % (short, sizes[short]))
    bad = np.flatnonzero((connectivity < 0) | (connectivity >= num_points))
    if bad.size:
        face = int(np.searchsorted(offsets, bad[0], side="right") - 1)
        raise ValueError("face %d names point %d, and there are %d points" % (face, connectivity[bad[0]], num_points))
    return offsets, connectivity


def _add_sharp_features(polydata, creases, corners, holes):
    if creases is not None:
        _add_creases(polydata, np.asarray(creases, dtype=np.float64))
    if corners is not None:
        _add_corners(polydata, corners)
    if holes is not None:
        _add_holes(polydata, holes)


def _add_creases(polydata, rows):
    if rows.size == 0:
        return
    if rows.ndim != 2 or rows.shape[1] != 3:
        raise ValueError("creases must be (i, j, sharpness) rows, not of shape %s" % (rows.shape,))
    ends = rows[:, :2]
    if np.any(ends != np.round(ends)) or np.any(ends < 0) or np.any(ends >= polydata.GetNumberOfPoints()):
        raise ValueError("crease ends must be point ids in [0, %d)" % polydata.GetNumberOfPoints())
    if np.any(rows[:, 2] < 0) or not np.all(np.isfinite(rows[:, 2])):
        raise ValueError("crease sharpness must be finite and >= 0")
    # Lines come before polygons in VTK's cell order: cell arrays get the lines' rows there.
    at = polydata.GetNumberOfVerts() + polydata.GetNumberOfLines()
    lines = vtkCellArray()
    lines.DeepCopy(polydata.GetLines())
    for i, j in ends.astype(np.int64):
        lines.InsertNextCell(2, (int(i), int(j)))
    cell_data = polydata.GetCellData()
    arrays = list(_arrays(cell_data))
    polydata.SetLines(lines)
    for name, values in arrays:
        padded = np.insert(values, at, np.zeros((len(rows),) + values.shape[1:], values.dtype), axis=0)
        cell_data.RemoveArray(name)
        cell_data.AddArray(_named(padded, name))
    sharpness = cell_data.GetArray("Sharpness")
    values = (numpy_support.vtk_to_numpy(sharpness).astype(np.float32) if sharpness is not None
              else np.zeros(polydata.GetNumberOfCells(), np.float32))
    values[at:at + len(rows)] = rows[:, 2]
    cell_data.RemoveArray("Sharpness")
    cell_data.AddArray(_named(values, "Sharpness"))


def _add_corners(polydata, corners):
    rows = np.asarray(list(corners.items()) if isinstance(corners, dict) else corners, dtype=np.float64)
    if rows.size == 0:
        return
    if rows.ndim != 2 or rows.shape[1] != 2:
        raise ValueError("corners must be {vertex: sharpness} or (vertex, sharpness) rows")
    n = polydata.GetNumberOfPoints()
    if np.any(rows[:, 0] != np.round(rows[:, 0])) or np.any(rows[:, 0] < 0) or np.any(rows[:, 0] >= n):
        raise ValueError("corner vertices must be point ids in [0, %d)" % n)
    existing = polydata.GetPointData().GetArray("CornerSharpness")
    values = (numpy_support.vtk_to_numpy(existing).astype(np.float32).copy() if existing is not None
              else np.zeros(n, np.float32))
    values[rows[:, 0].astype(np.int64)] = rows[:, 1]
    polydata.GetPointData().RemoveArray("CornerSharpness")
    polydata.GetPointData().AddArray(_named(values, "CornerSharpness"))


def _add_holes(polydata, holes):
    ids = np.asarray(list(holes), dtype=np.int64)
    num_polys = polydata.GetNumberOfPolys()
    if ids.size and (ids.min() < 0 or ids.max() >= num_polys):
        raise ValueError("holes must be face ids in [0, %d)" % num_polys)
    values = np.zeros(polydata.GetNumberOfCells(), np.uint8)
    values[polydata.GetNumberOfVerts() + polydata.GetNumberOfLines() + ids] = 1
    hole = vtkUnsignedCharArray()
    hole.DeepCopy(numpy_support.numpy_to_vtk(values, deep=1))
    hole.SetName("Hole")
    polydata.GetCellData().RemoveArray("Hole")
    polydata.GetCellData().AddArray(hole)


# --- running and output ---

def _message(text):
    """A VTK message without its "Error: In file, line N" line and its "vtkClass (0x...): "."""
    lines = str(text).strip().split("\n")
    if len(lines) > 1 and ", line " in lines[0]:
        lines = lines[1:]
    return re.sub(r"^\w+ \(0x[0-9a-fA-F]+\): ", "", "\n".join(lines)).strip()


def _observe(algorithm):
    """The list the algorithm's error messages go to; its warnings become RuntimeWarnings."""
    errors = []

    def on_error(obj, event, message):
        errors.append(_message(message))

    def on_warning(obj, event, message):
        warnings.warn(_message(message), RuntimeWarning, stacklevel=4)

    on_error.CallDataType = "string0"  # VTK passes the message as call data
    on_warning.CallDataType = "string0"
    algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    algorithm.AddObserver(vtkCommand.WarningEvent, on_warning)
    return errors


def _run(algorithm, polydata):
    errors = _observe(algorithm)
    if polydata is not None:
        algorithm.SetInputData(polydata)
    algorithm.Update()
    if errors:
        raise RuntimeError("; ".join(errors))
    output = vtkPolyData()
    output.ShallowCopy(algorithm.GetOutputDataObject(0))
    return output


def _arrays(data):
    for a in range(data.GetNumberOfArrays()):
        array = data.GetArray(a)
        if array is not None and array.GetName():
            yield array.GetName(), numpy_support.vtk_to_numpy(array).copy()


def _named(values, name):
    array = numpy_support.numpy_to_vtk(np.ascontiguousarray(values), deep=1)
    array.SetName(name)
    return array


def _crease_rows(polydata):
    """(i, j, sharpness) per segment of the output's crease lines."""
    sharpness = polydata.GetCellData().GetArray("Sharpness")
    rows = []
    lines = polydata.GetLines()
    offsets = numpy_support.vtk_to_numpy(lines.GetOffsetsArray())
    connectivity = numpy_support.vtk_to_numpy(lines.GetConnectivityArray())
    first = polydata.GetNumberOfVerts()
    for c in range(lines.GetNumberOfCells()):
        s = sharpness.GetValue(first + c) if sharpness is not None else 10.0
        ids = connectivity[offsets[c]:offsets[c + 1]]
        rows.extend((ids[k], ids[k + 1], s) for k in range(len(ids) - 1))
    return np.array(rows, dtype=np.float64).reshape(-1, 3)


# --- files ---

_READERS = {".vtk": lambda: _io.vtkSubDLegacyReader(), ".obj": lambda: _io.vtkSubDOBJReader(),
            ".ply": lambda: _io.vtkSubDPLYReader(), ".off": lambda: _io.vtkSubDOFFReader(),
            ".gltf": lambda: _io.vtkSubDGLTFReader(), ".glb": lambda: _io.vtkSubDGLTFReader()}
_WRITERS = {".obj": lambda: _io.vtkSubDOBJWriter(), ".ply": lambda: _io.vtkSubDPLYWriter(),
            ".off": lambda: _io.vtkSubDOFFWriter(), ".gltf": lambda: _io.vtkSubDGLTFWriter()}


def _extension(path):
    return os.path.splitext(path)[1].lower()


def _reader_for(path):
    ext = _extension(path)
    if not os.path.isfile(path):
        raise FileNotFoundError("cannot open %s" % path)
    if ext == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        return vtkXMLPolyDataReader()
    if ext == ".stl":
        from vtkmodules.vtkIOGeometry import vtkSTLReader
        return vtkSTLReader()
    if ext not in _READERS:
        raise ValueError("%s: unknown file type %r (.vtp .vtk .obj .ply .stl .off .gltf .glb)" % (path, ext))
    return _READERS[ext]()


def _writer_for(path):
    ext = _extension(path)
    if ext == ".vtp":
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        return vtkXMLPolyDataWriter()
    if ext == ".vtk":
        from vtkmodules.vtkIOLegacy import vtkPolyDataWriter
        writer = vtkPolyDataWriter()
        writer.SetFileTypeToBinary()
        return writer
    if ext == ".stl":
        from vtkmodules.vtkIOGeometry import vtkSTLWriter
        return vtkSTLWriter()
    if ext not in _WRITERS:
        raise ValueError("%s: unknown output type %r (.vtp .vtk .obj .ply .stl .off .gltf)" % (path, ext))
    return _WRITERS[ext]()
