"""SubD: subdivision surfaces and curves as VTK filters.

Importing this package loads VTK's Python modules it depends on, then the wrapped SubD
classes, e.g. ``subd.vtkSubDCatmullClarkFilter``, and the calls that do a job at once:
``subd.subdivide((points, faces), scheme="loop", levels=3)``, ``subd.read``, ``subd.write``.
"""
from vtkmodules import vtkCommonCore as _vtkCommonCore  # noqa: F401  (registers VTK types)
from .SubDFilters import *  # noqa: F401,F403
from .SubDIO import *  # noqa: F401,F403
# Rendering: VTK's OpenGL and FreeType modules register the classes the scene needs.
from vtkmodules import vtkRenderingOpenGL2 as _vtkRenderingOpenGL2  # noqa: F401
from vtkmodules import vtkRenderingFreeType as _vtkRenderingFreeType  # noqa: F401
from .SubDRendering import *  # noqa: F401,F403

from ._api import (Curve, Mesh, from_meshio, interpolate, limit_surface, make_filter, read,  # noqa: E402
                   refine_curve, subdivide, to_arrays, to_meshio, write)

__all__ = [name for name in dir() if name.startswith("vtkSubD")] + [
    "Curve", "Mesh", "from_meshio", "interpolate", "limit_surface", "make_filter", "read", "refine_curve", "subdivide",
    "to_arrays", "to_meshio", "write"]
