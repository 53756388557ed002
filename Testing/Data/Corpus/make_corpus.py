#!/usr/bin/env python3
"""Writes SubD's corpus of bad and awkward inputs, and the answer each one must get.

    make_corpus.py OUTPUT_DIR

Every entry is a mesh file (or a broken one) plus a line of OUTPUT_DIR/corpus.txt:

    file <TAB> levels <TAB> read <TAB> surface <TAB> curve <TAB> exact <TAB> linear

- `read`: what reading the file through `subd`'s readers gives: `ok`, or `error~REGEX` (the
  message must match REGEX, case-insensitive).
- `surface`: what every surface filter (all seven schemes and the limit tessellation) must give
  at `levels` levels: `ok` (a valid output, no error), `ok~REGEX` (also a warning matching REGEX),
  or `error~REGEX` (an error matching REGEX and an empty output). When the read fails, the filters
  are run on an empty polydata and must give `error~no points`.
- `curve`: the same for the curve filter (Chaikin, cubic B-spline, 4-point).
- `exact`: the same for the exact limit evaluation (Catmull-Clark and Loop limit normals and
  curvature, vtkSubDLimitFilter); `-` when it is `surface`'s answer.
- `linear`: the linear scheme's answer (vtkSubDLinearFilter, its points not projected) where it
  differs from `surface`; `-` when it does not. Its rules read nothing around vertices, so it
  reports non-manifold edges but not a vertex whose faces pinch (a bowtie), which changes
  nothing in its output.

The expectations are written here by hand from the file formats and the filters' documented
rules, not produced by SubD. The files are written in a fixed order from a seeded generator, so
every run gives the same bytes. The test suite (Testing/Filters/TestCorpus.cxx and the `subd`
tests) regenerates the corpus in the build folder; fuzzing adds the inputs that once crashed
(Testing/Data/Corpus/crashes/), which are committed as they are.
"""
import base64
import json
import math
import os
import random
import struct
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else "corpus"
os.makedirs(OUT, exist_ok=True)
rng = random.Random(20261121)
manifest = []


def expect(name, read="ok", surface="ok", curve="ok", levels=2, exact="-", linear="-"):
    manifest.append((name, str(levels), read, surface, curve, exact, linear))


def write_text(name, text):
    with open(os.path.join(OUT, name), "w", newline="\n") as f:
        f.write(text)


def write_bytes(name, data):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def off(points, faces):
    lines = ["OFF", "%d %d 0" % (len(points), len(faces))]
    lines += ["%r %r %r" % tuple(p) for p in points]
    lines += [" ".join(str(x) for x in [len(f)] + list(f)) for f in faces]
    return "\n".join(lines) + "\n"


def legacy_vtk(points, verts=(), lines=(), polys=(), strips=()):
    """ASCII legacy VTK polydata, cells written as given (ids are not checked)."""
    out = ["# vtk DataFile Version 3.0", "SubD corpus", "ASCII", "DATASET POLYDATA",
           "POINTS %d double" % len(points)]
    out += ["%r %r %r" % tuple(p) for p in points]
    for keyword, cells in (("VERTICES", verts), ("LINES", lines), ("POLYGONS", polys),
                           ("TRIANGLE_STRIPS", strips)):
        if cells:
            size = sum(len(c) + 1 for c in cells)
            out.append("%s %d %d" % (keyword, len(cells), size))
            out += [" ".join(str(x) for x in [len(c)] + list(c)) for c in cells]
    return "\n".join(out) + "\n"


CUBE_POINTS = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)]
CUBE_FACES = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]

# --- topology that is legal but awkward: subdivided, non-manifold parts treated as sharp ---
# Three quads on one edge (a "fin"): the edge 0-1 has three faces.
fin_points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, -1, 0), (1, -1, 0), (0, 0, 1), (1, 0, 1)]
write_text("nonmanifold-edge.off", off(fin_points, [(0, 1, 3, 2), (1, 0, 4, 5), (0, 1, 7, 6)]))
expect("nonmanifold-edge.off", surface="ok~non-manifold")

# Two triangles touching at one vertex only (a bowtie).
write_text("bowtie.off", off([(0, 0, 0), (1, 0.5, 0), (1, -0.5, 0), (-1, 0.5, 0), (-1, -0.5, 0)],
                             [(0, 2, 1), (0, 3, 4)]))
expect("bowtie.off", surface="ok~non-manifold", linear="ok")

# Two quads of a strip, the second one flipped: their shared edge runs the same way in both.
write_text("inconsistent-orientation.off",
           off([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0)],
               [(0, 1, 4, 3), (1, 4, 5, 2)]))
expect("inconsistent-orientation.off", surface="ok~non-manifold")

# The cube with one face twice (same winding) and one face twice (opposite winding).
write_text("duplicate-faces.off", off(CUBE_POINTS, CUBE_FACES + [CUBE_FACES[0], CUBE_FACES[1][::-1]]))
expect("duplicate-faces.off", surface="ok~non-manifold")

# --- degenerate faces: kept as OpenSubdiv keeps them, or dropped (or repaired), with a warning ---
# Repeated ids: one consecutive repeat, one vertex repeated elsewhere (kept by Catmull-Clark,
# Loop and linear; collapsed to a triangle and dropped by the others).
write_text("repeated-ids.off", off(CUBE_POINTS, CUBE_FACES + [(0, 1, 1, 3), (0, 3, 0, 5)]))
expect("repeated-ids.off", surface="ok~degenerate|ignored|repeat")

# Faces with two and one corners next to a good cube.
write_text("short-faces.off", off(CUBE_POINTS, CUBE_FACES + [(0, 7), (3,)]))
expect("short-faces.off", surface="ok~degenerate|ignored")
# A face of no corners is not OFF: the reader names it.
write_text("empty-face.off", off(CUBE_POINTS, CUBE_FACES + [()]))
expect("empty-face.off", read="error~face 6 announces 0 vertices")

# Zero area: three collinear points, and a triangle whose three points coincide.
write_text("zero-area.off",
           off(CUBE_POINTS + [(0, 0, 2), (0, 0, 3), (0, 0, 4), (5, 5, 5), (5, 5, 5), (5, 5, 5)],
               CUBE_FACES + [(8, 9, 10), (11, 12, 13)]))
expect("zero-area.off")

# Only degenerate faces: nothing usable remains.
write_text("all-degenerate.off", off(CUBE_POINTS, [(0, 1), (2, 2, 2), (4, 4, 4, 4)]))
expect("all-degenerate.off", surface="error~no usable polygon")

# --- points that no face uses ---
write_text("unused-points.off", off(CUBE_POINTS + [(9, 9, 9), (-9, 0, 0), (0, 7, 0)], CUBE_FACES))
expect("unused-points.off")
# Isolated vertices as vertex cells next to the polygons (mixed with a legacy file).
write_text("isolated-vertices.vtk", legacy_vtk(CUBE_POINTS + [(3, 3, 3), (4, 4, 4)],
                                               verts=[(8,), (9,)], polys=CUBE_FACES))
expect("isolated-vertices.vtk")

# --- coordinates that are not numbers ---
write_text("nan-coordinate.off", off(CUBE_POINTS[:5] + [(float("nan"), 0, 1)] + CUBE_POINTS[6:], CUBE_FACES))
expect("nan-coordinate.off", surface="error~point 5 .*non-finite", curve="error~point 5 .*non-finite")
write_text("inf-coordinate.off", off(CUBE_POINTS[:2] + [(0, float("inf"), 0)] + CUBE_POINTS[3:], CUBE_FACES))
expect("inf-coordinate.off", surface="error~point 2 .*non-finite", curve="error~point 2 .*non-finite")

# --- extreme sizes ---
# A cone whose apex has valence 1000, closed by a 1000-sided polygon.
n = 1000
ring = [(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0) for k in range(n)]
cone_faces = [(k, (k + 1) % n, n) for k in range(n)] + [tuple(range(n - 1, -1, -1))]
write_text("valence-1000.off", off(ring + [(0.0, 0.0, 1.0)], cone_faces))
# The exact limit is evaluated near vertices of at most 256 faces (its cost grows with the
# cube of the valence): beyond, a clear error (the Loop tessellation names the 1000-gon first).
expect("valence-1000.off", levels=1, exact="error~faces around it|sides;|needs triangles")

# One polygon of 100 000 sides (an open disk bounded by a circle).
n = 100000
write_text("polygon-100k.off",
           off([(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0) for k in range(n)],
               [tuple(range(n))]))
expect("polygon-100k.off", levels=1, exact="error~faces around it|sides;|needs triangles")

# A level count whose output could not be held: refused before anything is allocated.
write_text("cube.off", off(CUBE_POINTS, CUBE_FACES))
expect("cube.off", levels=30, surface="error~refusing", curve="ok")

# --- cell kinds other than polygons ---
expect_no_polygons = "error~no polygons"
write_text("empty-polydata.vtk", legacy_vtk([]))
expect("empty-polydata.vtk", read="error~no points")
write_text("verts-only.vtk", legacy_vtk(CUBE_POINTS, verts=[(k,) for k in range(8)]))
expect("verts-only.vtk", surface=expect_no_polygons, curve="ok~no lines")
write_text("lines-only.vtk", legacy_vtk(CUBE_POINTS, lines=[(0, 1, 3, 2), (4, 5), (6, 7, 5)]))
expect("lines-only.vtk", surface=expect_no_polygons)
write_text("strips.vtk", legacy_vtk([(x, y, 0.0) for y in (0.0, 1.0) for x in range(5)],
                                    strips=[(0, 5, 1, 6, 2, 7, 3, 8, 4, 9)]))
expect("strips.vtk", curve="ok~no lines")
write_text("mixed-cells.vtk",
           legacy_vtk(CUBE_POINTS + [(2, 0, 0), (3, 0, 0), (2, 1, 0), (3, 1, 0), (4, 0.5, 0)],
                      verts=[(8,)], lines=[(8, 9, 11), (0, 7)], polys=CUBE_FACES[:5] + [(8, 9, 12, 11, 10)],
                      strips=[(1, 3, 5, 7)]))
expect("mixed-cells.vtk")

# --- ids that name no point (a hand-made polydata; the legacy reader does not check them) ---
write_text("out-of-range-ids.vtk", legacy_vtk(CUBE_POINTS, polys=CUBE_FACES[:5] + [(1, 3, 99, 5)]))
expect("out-of-range-ids.vtk", surface="error~not exist|outside", curve="error~cell 5 .*outside")
write_text("negative-ids.vtk", legacy_vtk(CUBE_POINTS, polys=CUBE_FACES[:5] + [(1, 3, -7, 5)],
                                          lines=[(0, 1), (2, -1)]))
expect("negative-ids.vtk", surface="error~not exist|outside", curve="error~cell 1 .*outside")

# --- broken files, for every format subd reads ---
# A valid cube in each format; the broken ones are cut or corrupted copies.
obj = "".join("v %r %r %r\n" % p for p in CUBE_POINTS) + "".join(
    "f " + " ".join(str(i + 1) for i in f) + "\n" for f in CUBE_FACES)
ply = ("ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
       "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
       + "".join("%r %r %r\n" % p for p in CUBE_POINTS)
       + "".join("4 " + " ".join(map(str, f)) + "\n" for f in CUBE_FACES))
stl = "solid cube\n" + "".join(
    "facet normal 0 0 0\nouter loop\n" + "".join("vertex %r %r %r\n" % CUBE_POINTS[i] for i in tri)
    + "endloop\nendfacet\n" for f in CUBE_FACES for tri in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))) + "endsolid cube\n"
vtp = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
       "<PolyData>\n<Piece NumberOfPoints=\"8\" NumberOfPolys=\"6\">\n<Points>\n"
       '<DataArray type="Float64" NumberOfComponents="3" format="ascii">\n'
       + " ".join("%r %r %r" % p for p in CUBE_POINTS) + "\n</DataArray>\n</Points>\n<Polys>\n"
       '<DataArray type="Int64" Name="connectivity" format="ascii">\n'
       + " ".join(str(i) for f in CUBE_FACES for i in f) + "\n</DataArray>\n"
       '<DataArray type="Int64" Name="offsets" format="ascii">\n'
       + " ".join(str(4 * (k + 1)) for k in range(6)) + "\n</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n")
valid = {"off": off(CUBE_POINTS, CUBE_FACES), "obj": obj, "ply": ply, "stl": stl, "vtp": vtp,
         "vtk": legacy_vtk(CUBE_POINTS, polys=CUBE_FACES)}
for ext, text in sorted(valid.items()):
    write_text("valid." + ext, text)
    expect("valid." + ext)
    # Cut in the middle of the point list (STL: of the triangles): a clear read error.
    cut = (text.index("\nf ") + 1 if ext == "obj" else
           text.index("facet", len(text) // 2) if ext == "stl" else
           text.index("0.0 1.0 1.0"))
    write_text("truncated." + ext, text[:cut])
    if ext == "obj":
        # OBJ has no counts: a cut before the faces leaves a valid cloud of points.
        expect("truncated.obj", surface="error~no polygons", curve="ok~no lines")
    elif ext == "stl":
        # ASCII STL has no counts either: whole facets before the cut are a valid mesh, the
        # missing "endsolid" is an error.
        expect("truncated.stl", read="error~.")
    else:
        expect("truncated." + ext, read="error~.")
    write_bytes("garbage." + ext, bytes(rng.randrange(256) for _ in range(3000)))
    expect("garbage." + ext, read="error~.")

# Headers that promise far more than the file holds: refused, not allocated.
write_text("lying-count.off", "OFF\n2000000000 2000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
expect("lying-count.off", read="error~.")
write_text("lying-count.ply", ply.replace("element vertex 8", "element vertex 2000000000"))
expect("lying-count.ply", read="error~.")
write_text("lying-count.vtk", legacy_vtk(CUBE_POINTS, polys=CUBE_FACES).replace("POINTS 8", "POINTS 2000000000"))
expect("lying-count.vtk", read="error~.")
write_text("lying-count.vtp", vtp.replace('NumberOfPoints="8"', 'NumberOfPoints="2000000000"'))
expect("lying-count.vtp", read="error~.")
# Binary STL: an 80-byte header and a count of 2^31 - 1 triangles, followed by one.
write_bytes("lying-count.stl", b"binary STL".ljust(80, b" ") + (2**31 - 1).to_bytes(4, "little") + bytes(50))
expect("lying-count.stl", read="error~.")
# OBJ faces naming vertices that do not exist (1-based, and relative past the start).
write_text("obj-bad-index.obj", obj + "f 1 2 42\nf -1 -2 -30\n")
expect("obj-bad-index.obj", read="error~.")

# Binary layouts (big-endian legacy, both PLY byte orders) and the inconsistencies only they
# can hold; also seeds that let the fuzzer reach the binary readers.
def legacy_binary(points, faces, cells_values=None):
    values = cells_values if cells_values is not None else [v for f in faces for v in [len(f)] + list(f)]
    return (b"# vtk DataFile Version 3.0\nSubD corpus\nBINARY\nDATASET POLYDATA\n"
            + b"POINTS %d float\n" % len(points) + struct.pack(">%df" % (3 * len(points)), *[c for p in points for c in p])
            + b"\nPOLYGONS %d %d\n" % (len(faces), len(values)) + struct.pack(">%di" % len(values), *values) + b"\n")


write_bytes("valid-binary.vtk", legacy_binary(CUBE_POINTS, CUBE_FACES))
expect("valid-binary.vtk")
# The first cell claims 9 points: the cells no longer add up to the section's 30 values.
write_bytes("binary-cell-count-mismatch.vtk",
            legacy_binary(CUBE_POINTS, CUBE_FACES, [9] + [v for f in CUBE_FACES for v in [len(f)] + list(f)][1:]))
expect("binary-cell-count-mismatch.vtk", read="error~runs past|use")
write_text("legacy-v5-decreasing-offsets.vtk",
           "# vtk DataFile Version 5.1\nSubD corpus\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n"
           "0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 3 6\nOFFSETS vtktypeint64\n0 4 3\n"
           "CONNECTIVITY vtktypeint64\n0 1 2 3 0 2\n")
expect("legacy-v5-decreasing-offsets.vtk", read="error~offsets")


def ply_binary(points, faces, order, extra=""):
    fmt = "<" if order == "little" else ">"
    header = ("ply\nformat binary_%s_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              "property float z\n%selement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (order, len(points), extra, len(faces))).encode()
    body = b"".join(struct.pack(fmt + "3f", *p) + (struct.pack(fmt + "f", 0.5) if extra else b"") for p in points)
    body += b"".join(struct.pack(fmt + "B%di" % len(f), len(f), *f) for f in faces)
    return header + body


write_bytes("valid-little-endian.ply", ply_binary(CUBE_POINTS, CUBE_FACES, "little"))
expect("valid-little-endian.ply")
write_bytes("valid-big-endian-quality.ply", ply_binary(CUBE_POINTS, CUBE_FACES, "big", "property float quality\n"))
expect("valid-big-endian-quality.ply")
write_bytes("ply-index-out-of-range.ply", ply_binary(CUBE_POINTS, CUBE_FACES[:5] + [(0, 1, 8, 3)], "little"))
expect("ply-index-out-of-range.ply", read="error~uses vertex 8")

# glTF: the cube as triangles in one primitive, as a .gltf with its buffer in a data URI and as
# a .glb; then the structural faults VTK 9.1's glTF reader would crash on or read past.
def gltf_cube(edit=None, uri=True):
    tris = [t for f in CUBE_FACES for t in ((f[0], f[1], f[2]), (f[0], f[2], f[3]))]
    data = struct.pack("<24f", *[c for p in CUBE_POINTS for c in p]) + struct.pack("<36I", *[i for t in tris for i in t])
    doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
           "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "buffers": [{"byteLength": len(data)}],
           "bufferViews": [{"buffer": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 144}],
           "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                          "min": [0, 0, 0], "max": [1, 1, 1]},
                         {"bufferView": 1, "componentType": 5125, "count": 36, "type": "SCALAR"}]}
    if uri:
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    if edit:
        edit(doc)
    return doc, data


def glb(doc, data):
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data += bytes(-len(data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


write_text("valid.gltf", json.dumps(gltf_cube()[0]))
expect("valid.gltf")
write_bytes("valid.glb", glb(*gltf_cube(uri=False)))
expect("valid.glb")
write_text("truncated.gltf", json.dumps(gltf_cube()[0])[:200])
expect("truncated.gltf", read="error~json")
write_bytes("truncated.glb", glb(*gltf_cube(uri=False))[:300])
expect("truncated.glb", read="error~longer than the file")
write_bytes("garbage.gltf", bytes(rng.randrange(256) for _ in range(3000)))
expect("garbage.gltf", read="error~.")
gltf_faults = {
    "accessor-out-of-range": (lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=5), "accessors\\[5\\]"),
    "missing-buffer-file": (lambda d: d["buffers"][0].update(uri="no-such-file.bin"), "cannot open"),
    "short-buffer": (lambda d: d["buffers"][0].update(byteLength=100), "outside its buffer"),
    "accessor-past-view": (lambda d: d["accessors"][1].update(count=99), "past the end"),
    "node-cycle": (lambda d: d["nodes"].append({"children": [1]}) or d["nodes"][0].update(children=[1]), "own ancestor"),
    "no-position": (lambda d: d["meshes"][0]["primitives"][0].update(attributes={}), "no position"),
    "version-1": (lambda d: d["asset"].update(version="1.0"), "2\\.0"),
    # Values whose sums would overflow 64 bits in the byte-range checks.
    "huge-count": (lambda d: d["accessors"][1].update(count=2**62), "larger than"),
    "huge-offset": (lambda d: d["bufferViews"][1].update(byteOffset=2**64 - 8), "larger than|malformed"),
}
for name, (edit, message) in sorted(gltf_faults.items()):
    write_text("gltf-" + name + ".gltf", json.dumps(gltf_cube(edit)[0]))
    expect("gltf-" + name + ".gltf", read="error~" + message)
# An index past the points: the file's structure is sound, the faces are not.
write_bytes("gltf-index-out-of-range.glb",
            glb(*gltf_cube(uri=False))[:-4] + struct.pack("<I", 40))
expect("gltf-index-out-of-range.glb", surface="error~not exist|outside", curve="error~cell 11 .*outside")

# --- seeds for the fuzz targets (Testing/Fuzz) ---
# FuzzReaders: a format byte (the index in its list of extensions), then the file.
reader_formats = [".off", ".obj", ".ply", ".stl", ".vtk", ".vtp"]
os.makedirs(os.path.join(OUT, "fuzz-readers"), exist_ok=True)
for name, *_ in manifest:
    ext = os.path.splitext(name)[1]
    path = os.path.join(OUT, name)
    if ext in reader_formats and os.path.getsize(path) < 100000:
        with open(path, "rb") as f:
            write_bytes(os.path.join("fuzz-readers", name), bytes([reader_formats.index(ext)]) + f.read())
# FuzzFilters: recipes (SubDFuzzSupport.h, MeshFromBytes) of a closed cube for every choice of
# filter, and of an open pair of quads with a crease line.
os.makedirs(os.path.join(OUT, "fuzz-filters"), exist_ok=True)
cube_recipe = [7] + [0] * 8 + [0, 6] + [b for f in CUBE_FACES for b in [3] + list(f)]
for choice in range(9):
    write_bytes(os.path.join("fuzz-filters", "cube-%d" % choice), bytes([choice, 0x02, 1] + cube_recipe + [0]))
    write_bytes(os.path.join("fuzz-filters", "creased-quads-%d" % choice),
                bytes([choice, 0x61, 1, 6, 0, 0, 0, 0, 0, 0, 0, 2, 3, 0, 1, 4, 3, 3, 1, 2, 5, 4, 0x19, 0, 1, 4, 48]))

with open(os.path.join(OUT, "corpus.txt"), "w", newline="\n") as f:
    f.write("# file\tlevels\tread\tsurface\tcurve\texact\tlinear (see make_corpus.py)\n")
    for row in manifest:
        f.write("\t".join(row) + "\n")
print("make_corpus: %d entries in %s" % (len(manifest), OUT))
