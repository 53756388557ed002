"""Subdivide a mesh on several MPI ranks with ParaView's pvbatch and SubD's plugin.

    mpirun -np 4 pvbatch --symmetric subdivide_in_parallel.py PLUGIN INPUT OUTPUT.pvtp \
        [SCHEME [LEVELS]]

PLUGIN is SubD.so (build/paraview-plugin/lib/paraview-5.11/plugins/SubD/SubD.so), INPUT any
mesh ParaView reads (.vtp, .vtk, .ply, .stl, .obj, ...), SCHEME one of catmull-clark, loop,
butterfly, doo-sabin, midpoint, sqrt3, linear (default catmull-clark) and LEVELS the number
of levels (default 2). OUTPUT.pvtp gets one piece per rank.

The pipeline: the reader; D3 (vtkPDistributedDataFilter), which splits the mesh into compact
pieces, one per rank, and supplies the layers of ghost cells that the SubD filter asks for
(its scheme's number, see README's "MPI and pieces"); ExtractSurface, back to polygons (crease
lines and their "Sharpness" pass through); the SubD filter, which subdivides its own and the
ghost cells and outputs its own cells' children; the parallel writer. The pieces together
are the serial output.

Why D3 and not RedistributeDataSet with GhostCellsGenerator: in ParaView 5.11 the ghost
cells generator makes no ghost cells for surfaces (polygons), so the pieces' seams would be
subdivided as boundaries.
"""
import sys

import paraview.simple as pvs
from paraview.modules.vtkRemotingCore import vtkProcessModule

FILTERS = {
    "catmull-clark": "SubDCatmullClark", "loop": "SubDLoop", "butterfly": "SubDModifiedButterfly",
    "doo-sabin": "SubDDooSabin", "midpoint": "SubDMidpoint", "sqrt3": "SubDSqrt3",
    "linear": "SubDLinear",
}

if len(sys.argv) < 4 or (len(sys.argv) > 4 and sys.argv[4] not in FILTERS):
    sys.exit(__doc__)
plugin, source, target = sys.argv[1:4]
scheme = sys.argv[4] if len(sys.argv) > 4 else "catmull-clark"
levels = int(sys.argv[5]) if len(sys.argv) > 5 else 2

pvs.LoadPlugin(plugin, remote=False)
reader = pvs.OpenDataFile(source)
if reader is None:
    sys.exit("cannot read %s" % source)
pieces = pvs.D3(Input=reader)
surface = pvs.ExtractSurface(Input=pieces)
subdivided = getattr(pvs, FILTERS[scheme])(Input=surface, NumberOfSubdivisions=levels)
pvs.SaveData(target, proxy=subdivided)

if vtkProcessModule.GetProcessModule().GetPartitionId() == 0:
    print("%s, %d levels: %d pieces written to %s" % (
        scheme, levels, vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions(), target))
