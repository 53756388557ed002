# Installs SubD into a scratch prefix, builds Examples/Installed against it with
# find_package(SubD), runs it, and imports the installed Python package.
#   cmake -DBUILD=dir -DSOURCE=dir -DWORK=dir -DGENERATOR=Ninja -DPYTHON=python3
#         -DPYTHON_DESTINATION=lib/python3/dist-packages [-DWITH_PYTHON=ON] -P RunInstalled.cmake
file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")
include("${CMAKE_CURRENT_LIST_DIR}/../CMake/RunStep.cmake")
run("${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${prefix}")
if (NOT EXISTS "${prefix}/bin/subd")
  message(FATAL_ERROR "subd was not installed")
endif ()
run("${prefix}/bin/subd" --levels 1 -o "${WORK}/cube.vtp")
if (NOT EXISTS "${WORK}/cube.vtp")
  message(FATAL_ERROR "the installed subd wrote no cube.vtp")
endif ()
run("${CMAKE_COMMAND}" -S "${SOURCE}/Examples/Installed" -B "${WORK}/build" -G "${GENERATOR}"
  "-DCMAKE_PREFIX_PATH=${prefix}")
run("${CMAKE_COMMAND}" --build "${WORK}/build")
run("${WORK}/build/SmoothSphere")
if (NOT last_output MATCHES "Loop, 2 levels: 64 -> 1024 triangles, normals: yes")
  message(FATAL_ERROR "unexpected output from the installed example")
endif ()
if (WITH_PYTHON)
  set(ENV{PYTHONPATH} "${prefix}/${PYTHON_DESTINATION}")
  file(WRITE "${WORK}/check.py"
    "import subd\nf = subd.vtkSubDCatmullClarkFilter()\nprint(f.GetClassName(), 'Catmull' in f.__doc__)\n")
  run("${PYTHON}" "${WORK}/check.py")
  if (NOT last_output MATCHES "vtkSubDCatmullClarkFilter True")
    message(FATAL_ERROR "the installed Python package does not work")
  endif ()
endif ()
