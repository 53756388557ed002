"""subd's one-call Python API (subd.subdivide, read, write) against the VTK filters it runs.

Run by ctest through pytest (Testing/Python/CMakeLists.txt).
"""
import collections

import numpy as np
import pytest
import subd
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

CUBE_POINTS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
                       dtype=np.float64) + 0.01 * np.sin(np.arange(24)).reshape(8, 3)
CUBE_FACES = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
CUBE_TRIANGLES = [[f[0], f[1], f[2]] for f in CUBE_FACES] + [[f[0], f[2], f[3]] for f in CUBE_FACES]
TRIANGLE_SCHEMES = ("loop", "butterfly", "sqrt3")


def cage_faces(scheme):
    return CUBE_TRIANGLES if scheme in TRIANGLE_SCHEMES else CUBE_FACES


def polydata_by_hand(points, faces):
    """A vtkPolyData built cell by cell, independently of subd's conversion."""
    mesh = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for p in points:
        vtk_points.InsertNextPoint(*p)
    cells = vtkCellArray()
    for face in faces:
        cells.InsertNextCell(len(face), list(face))
    mesh.SetPoints(vtk_points)
    mesh.SetPolys(cells)
    return mesh


def run_filter(filter_, mesh):
    filter_.SetInputData(mesh)
    filter_.Update()
    return filter_.GetOutput()


def arrays_of(polydata):
    points = numpy_support.vtk_to_numpy(polydata.GetPoints().GetData())
    connectivity = numpy_support.vtk_to_numpy(polydata.GetPolys().GetConnectivityArray())
    offsets = numpy_support.vtk_to_numpy(polydata.GetPolys().GetOffsetsArray())
    return points, offsets, connectivity


def flat_faces(faces):
    if isinstance(faces, tuple):
        return faces
    return np.arange(0, faces.size + 1, faces.shape[1]), faces.ravel()


@pytest.mark.parametrize("scheme", list(subd._api.SURFACE_SCHEMES))
def test_every_scheme_gives_the_filters_output_bit_for_bit(scheme):
    faces = cage_faces(scheme)
    result = subd.subdivide((CUBE_POINTS, faces), scheme=scheme, levels=2)
    filter_ = subd._api.SURFACE_SCHEMES[scheme]()
    filter_.SetNumberOfSubdivisions(2)
    expected = run_filter(filter_, polydata_by_hand(CUBE_POINTS, faces))
    points, offsets, connectivity = arrays_of(expected)
    assert np.array_equal(result.points, points)
    got_offsets, got_connectivity = flat_faces(result.faces)
    assert np.array_equal(got_offsets, offsets)
    assert np.array_equal(got_connectivity, connectivity)


def test_polydata_in_gives_polydata_out_as_arrays_do():
    out = subd.subdivide(polydata_by_hand(CUBE_POINTS, CUBE_FACES), scheme="doo-sabin", levels=2)
    assert isinstance(out, vtkPolyData)
    arrays = subd.subdivide((CUBE_POINTS, CUBE_FACES), scheme="doo-sabin", levels=2)
    points, offsets, connectivity = arrays_of(out)
    assert np.array_equal(points, arrays.points)
    assert np.array_equal(connectivity, flat_faces(arrays.faces)[1])


def test_mixed_faces_come_back_as_offsets_and_connectivity():
    out = subd.subdivide((CUBE_POINTS, CUBE_FACES), scheme="doo-sabin", levels=1)
    assert isinstance(out.faces, tuple)  # quads and triangles
    offsets, connectivity = out.faces
    assert offsets[-1] == len(connectivity) and set(np.diff(offsets)) == {3, 4}


def test_sharp_features_by_arrays_equal_those_of_a_file(tmp_path):
    obj = tmp_path / "tagged.obj"
    obj.write_text("".join("v %r %r %r\n" % tuple(p) for p in CUBE_POINTS)
                   + "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in CUBE_FACES)
                   + "t crease 3/1/0 4 5 6 2.5\nt corner 1/1/0 0 10\nt hole 1/0/0 1\n")
    from_file = subd.to_arrays(subd.subdivide(subd.read(obj), levels=2, crease_method="chaikin"))
    by_arrays = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=2, crease_method="chaikin",
                               creases=[(4, 5, 2.5), (5, 6, 2.5)], corners={0: 10}, holes=[1])
    assert np.array_equal(by_arrays.points, from_file.points)
    assert np.array_equal(flat_faces(by_arrays.faces)[1], flat_faces(from_file.faces)[1])
    assert np.array_equal(by_arrays.creases, from_file.creases)
    assert len(by_arrays.creases) == 8  # two edges, each split twice, sharpness 0.5 left
    assert np.allclose(by_arrays.creases[:, 2], 0.5)


def test_a_result_passed_back_in_continues_the_refinement():
    creases = [(0, 1, 10), (1, 2, 10)]
    once = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=1, creases=creases)
    twice = subd.subdivide(once, levels=1)
    direct = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=2, creases=creases)
    assert np.allclose(twice.points, direct.points, rtol=0, atol=1e-12)


def test_limit_normals_and_curvature():
    plain = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=2)
    limit = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=2, limit=True, normals=True, curvature=True)
    assert np.max(np.abs(limit.points - plain.points)) > 1e-3  # moved to the limit surface
    normals = limit.point_data["Normals"]
    assert normals.shape == limit.points.shape
    assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)
    for name in ("Mean_Curvature", "Gauss_Curvature", "Maximum_Curvature", "Minimum_Curvature"):
        assert limit.point_data[name].shape == (len(limit.points),)
    # A convex closed surface: positive mean curvature everywhere (vtkCurvatures' sign).
    assert np.all(limit.point_data["Mean_Curvature"] > 0)


@pytest.mark.parametrize("mesh, options, error, message", [
    ((CUBE_POINTS, CUBE_FACES), dict(scheme="nope"), ValueError, "scheme 'nope' is not one of"),
    ((CUBE_POINTS, CUBE_FACES), dict(levels=2.5), TypeError, "levels must be an integer"),
    ((CUBE_POINTS, CUBE_FACES), dict(levels=-1), ValueError, "levels must be in 0..30"),
    ((CUBE_POINTS, CUBE_FACES), dict(boundary="open"), ValueError, "boundary 'open' is not one of"),
    ((CUBE_POINTS, CUBE_FACES), dict(crease_method="smooth"), ValueError, "crease_method 'smooth'"),
    ((CUBE_POINTS, CUBE_FACES), dict(tension=0.01), ValueError, "tension applies to the butterfly"),
    ((CUBE_POINTS, CUBE_TRIANGLES), dict(scheme="butterfly", tension=1.0), ValueError, "tension must be in"),
    ((CUBE_POINTS, CUBE_FACES), dict(fvar_interpolation="smooth"), ValueError, "fvar_interpolation 'smooth'"),
    ((CUBE_POINTS, CUBE_FACES), dict(feature_angle=200), ValueError, "feature_angle must be in"),
    ((CUBE_POINTS, CUBE_FACES), dict(scheme="loop", smooth_triangles=True), ValueError, "applies to catmull-clark"),
    ((CUBE_POINTS, CUBE_FACES), dict(creases=[(0, 99, 1)]), ValueError, "crease ends must be point ids"),
    ((CUBE_POINTS, CUBE_FACES), dict(creases=[(0, 1)]), ValueError, "creases must be"),
    ((CUBE_POINTS, CUBE_FACES), dict(corners={42: 1}), ValueError, "corner vertices must be"),
    ((CUBE_POINTS, CUBE_FACES), dict(holes=[6]), ValueError, "holes must be face ids"),
    ((CUBE_POINTS[:, :2], CUBE_FACES), {}, ValueError, "points must be an \\(N, 3\\) array"),
    ((CUBE_POINTS, [[0, 1, 8]]), {}, ValueError, "face 0 names point 8, and there are 8 points"),
    ((CUBE_POINTS, [[0, 1]]), {}, ValueError, "face 0 has 2 corners"),
    ((CUBE_POINTS, [[0.5, 1, 2]]), {}, TypeError, "face 0 is not a sequence of integers"),
    ("cube.obj", {}, TypeError, "mesh must be a vtkPolyData or a \\(points, faces\\) pair"),
])
def test_bad_arguments_raise_with_the_reason(mesh, options, error, message):
    with pytest.raises(error, match=message):
        subd.subdivide(mesh, **options)


def test_a_filter_error_raises_runtime_error_with_its_message():
    points = CUBE_POINTS.copy()
    points[3, 1] = np.nan
    with pytest.raises(RuntimeError, match="non-finite"):
        subd.subdivide((points, CUBE_FACES))


def test_filter_warnings_become_runtime_warnings():
    with pytest.warns(RuntimeWarning, match="^6 polygon\\(s\\) with more than 3 corners were split into triangles"):
        subd.subdivide((CUBE_POINTS, CUBE_FACES), scheme="butterfly", levels=1)


@pytest.mark.parametrize("extension", [".vtp", ".vtk", ".obj", ".ply", ".off", ".stl", ".gltf"])
def test_every_format_round_trips(tmp_path, extension):
    result = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=1)
    path = tmp_path / ("cube" + extension)
    subd.write(result, path)
    back = subd.to_arrays(subd.read(path))
    # (STL and glTF hold floats; the other formats give the points back exactly.)
    tolerance = 1e-6 if extension in (".stl", ".gltf") else 0.0
    distances = np.linalg.norm(result.points[:, None, :] - back.points[None, :, :], axis=2)
    assert np.all(distances.min(axis=1) <= tolerance)
    assert np.all(distances.min(axis=0) <= tolerance)
    assert len(np.unique(back.points, axis=0)) == len(result.points)


def test_reading_errors():
    with pytest.raises(FileNotFoundError):
        subd.read("/no/such/file.obj")
    with pytest.raises(ValueError, match="unknown file type"):
        subd.read(__file__)


def test_limit_surface_is_the_filters_and_its_samples_are_the_limit_points():
    tessellation = subd.limit_surface((CUBE_POINTS, CUBE_FACES), resolution=4, curvature=True)
    filter_ = subd.vtkSubDLimitFilter()
    filter_.SetResolution(4)
    filter_.SetComputeCurvature(True)
    points, offsets, connectivity = arrays_of(run_filter(filter_, polydata_by_hand(CUBE_POINTS, CUBE_FACES)))
    assert np.array_equal(tessellation.points, points)
    assert np.array_equal(flat_faces(tessellation.faces)[1], connectivity)
    assert tessellation.cell_data["FaceId"].shape == (len(offsets) - 1,)
    # At (u, v) = (0, 0) of face f, the limit point of its first corner, which the limit masks
    # of the refinement give too (another evaluation of the same surface).
    corners = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=0, limit=True).points
    samples = subd.limit_surface((CUBE_POINTS, CUBE_FACES), samples=(range(6), np.zeros((6, 2))))
    expected = corners[[face[0] for face in CUBE_FACES]]
    assert np.allclose(samples.points, expected, rtol=0, atol=1e-12)


def test_adaptive_and_selective_limit_tessellations_are_the_filters():
    adaptive = subd.limit_surface((CUBE_POINTS, CUBE_FACES), tolerance=1e-3, locations=True)
    filter_ = subd.vtkSubDLimitFilter()
    filter_.SetTessellationToAdaptive()
    filter_.SetTolerance(1e-3)
    points, offsets, connectivity = arrays_of(run_filter(filter_, polydata_by_hand(CUBE_POINTS, CUBE_FACES)))
    assert np.array_equal(adaptive.points, points)
    assert np.array_equal(flat_faces(adaptive.faces)[1], connectivity)
    assert adaptive.point_data["FaceUV"].shape == (len(points), 2)
    edges = collections.Counter()
    for face in np.asarray(adaptive.faces):
        for k in range(3):
            edges[tuple(sorted((face[k], face[(k + 1) % 3])))] += 1
    assert set(edges.values()) == {2}, "watertight"
    # Every face at level 2: the uniform tessellation at resolution 4, point for point.
    selective = subd.limit_surface((CUBE_POINTS, CUBE_FACES), refine_levels=[2] * 6)
    uniform = subd.limit_surface((CUBE_POINTS, CUBE_FACES), resolution=4)
    assert len(selective.points) == len(uniform.points)
    assert np.allclose(np.sort(selective.points, axis=0), np.sort(uniform.points, axis=0), rtol=0, atol=1e-12)


@pytest.mark.parametrize("bad, error", [
    (dict(tolerance=0), ValueError), (dict(tolerance=-1e-3), ValueError), (dict(tolerance=float("nan")), ValueError),
    (dict(tolerance="fine"), TypeError), (dict(tolerance=1e-3, refine_levels=[1] * 6), ValueError),
    (dict(refine_levels=[1] * 5), ValueError), (dict(refine_levels=[0.5] * 6), ValueError),
    (dict(tolerance=1e-3, max_level=25), ValueError)])
def test_bad_tessellation_requests(bad, error):
    with pytest.raises(error):
        subd.limit_surface((CUBE_POINTS, CUBE_FACES), **bad)


def test_an_interpolating_cage_has_its_limit_points_on_the_targets():
    targets = subd.subdivide((CUBE_POINTS, CUBE_FACES), levels=1)
    cage = subd.interpolate((targets.points, targets.faces))
    limit = subd.subdivide((cage.points, cage.faces), levels=0, limit=True)
    assert np.allclose(limit.points, targets.points, rtol=0, atol=1e-9)
    assert np.max(np.abs(cage.points - targets.points)) > 1e-3  # the cage moved
    some = subd.interpolate((targets.points, targets.faces), targets=[0, 1, 2])
    assert np.array_equal(some.points[3:], targets.points[3:])  # the others keep their place
    with pytest.raises(ValueError, match="targets must be point ids"):
        subd.interpolate((targets.points, targets.faces), targets=[99])


def test_refine_curve_is_the_curve_filters():
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 1]], dtype=np.float64)
    for scheme, index in (("chaikin", 0), ("bspline", 1), ("four-point", 2)):
        refined, lines, _ = subd.refine_curve((points, [[0, 1, 2, 3]]), scheme=scheme, levels=3, closed=True)
        filter_ = subd.vtkSubDCurveFilter()
        filter_.SetScheme(index)
        filter_.SetNumberOfSubdivisions(3)
        filter_.SetClosed(True)
        curve = vtkPolyData()
        curve.SetPoints(polydata_by_hand(points, []).GetPoints())
        cells = vtkCellArray()
        cells.InsertNextCell(4, [0, 1, 2, 3])
        curve.SetLines(cells)
        expected = run_filter(filter_, curve)
        assert np.array_equal(refined, numpy_support.vtk_to_numpy(expected.GetPoints().GetData())), scheme
        assert len(lines) == 1
    with pytest.raises(ValueError, match="tension applies to the four-point"):
        subd.refine_curve((points, None), tension=0.1)
    with pytest.raises(ValueError, match="polyline 0 names a point outside"):
        subd.refine_curve((points, [[0, 7]]))


def test_meshio_formats_go_through_from_and_to_meshio(tmp_path):
    import meshio  # python3-meshio (scripts/setup)
    result = subd.subdivide((CUBE_POINTS, CUBE_FACES), scheme="doo-sabin", levels=1)  # triangles and quads
    path = tmp_path / "ds.vtu"
    meshio.write(path, subd.to_meshio(result))
    back = subd.from_meshio(meshio.read(path))
    assert np.array_equal(back.points, result.points)
    offsets, _ = back.faces
    assert sorted(np.diff(offsets)) == sorted(np.diff(result.faces[0]))
    # The same surface, whatever the order of its faces.
    again = subd.subdivide(back, levels=1)
    direct = subd.subdivide(result, levels=1)
    assert np.allclose(np.sort(again.points, axis=0), np.sort(direct.points, axis=0), rtol=0, atol=1e-12)


def test_the_option_names_are_the_programs():
    """The schemes, boundary rules and crease methods by the names `subd --help` gives them."""
    import os
    import re
    import subprocess

    # (Without the sanitizer build's preload, which is for the Python process only.)
    environment = {name: value for name, value in os.environ.items() if name != "LD_PRELOAD"}
    help_run = subprocess.run([os.environ["SUBD_EXECUTABLE"], "--help"], capture_output=True, text=True,
                              env=environment)
    assert help_run.returncode == 0, help_run.stderr
    text = help_run.stdout
    scheme_list = text[text.index("\n  --scheme NAME"):text.index("\n  --levels N")]
    schemes = re.findall(r"^ {23}([a-z0-9-]+): ", scheme_list, re.M)
    surfaces = [name for name in schemes if name not in subd._api.CURVE_SCHEMES]
    assert surfaces == list(subd._api.SURFACE_SCHEMES)
    assert [name for name in schemes if name in subd._api.CURVE_SCHEMES] == list(subd._api.CURVE_SCHEMES)
    for rule in subd._api.BOUNDARY_RULES:
        assert re.search(r"^ {23}%s: " % rule, text, re.M), rule
    assert "--crease-method" in text and all(method in text for method in subd._api.CREASE_METHODS)
