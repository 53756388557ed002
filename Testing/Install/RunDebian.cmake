# Makes the Debian package of the build (cpack -G DEB), checks its declared dependencies,
# unpacks it into a scratch root and runs what it holds from there: subd, and the Python
# package imported with no PYTHONPATH or LD_LIBRARY_PATH (its directory is where Debian's
# python3 looks, relocated under the root).
#   cmake -DBUILD=dir -DWORK=dir -DPYTHON=python3 -DCPACK=cpack -P RunDebian.cmake
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/../CMake/RunStep.cmake")
run("${CPACK}" -G DEB --config "${BUILD}/CPackConfig.cmake" -B "${WORK}")
file(GLOB debs "${WORK}/subd_*.deb")
list(LENGTH debs count)
if (NOT count EQUAL 1)
  message(FATAL_ERROR "expected one subd_*.deb in ${WORK}, found '${debs}'")
endif ()
run(dpkg-deb -f "${debs}" Depends)
foreach (package IN ITEMS libvtk9.1 python3-vtk9 python3-numpy libqt5)
  if (NOT last_output MATCHES "${package}")
    message(FATAL_ERROR "the package does not depend on ${package}: ${last_output}")
  endif ()
endforeach ()
set(root "${WORK}/root")
run(dpkg-deb -x "${debs}" "${root}")
run(env -u LD_LIBRARY_PATH "${root}/usr/bin/subd" --levels 1 -o "${WORK}/cube.vtp")
import_installed_subd("${PYTHON}" "${root}/usr/lib/python3/dist-packages" "/usr/lib/python3/dist-packages"
  "mesh = subd.subdivide(([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1, 2, 3]]), levels=2)\nprint('faces', len(mesh.faces), subd.__file__)"
  "faces 16 .*/root/usr/lib/python3/dist-packages/subd/__init__.py")
