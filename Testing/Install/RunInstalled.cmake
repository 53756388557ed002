# Installs SubD into a scratch prefix, builds Examples/Installed against it with
# find_package(SubD), runs it, and imports the installed Python package.
#   cmake -DBUILD=dir -DSOURCE=dir -DWORK=dir -DGENERATOR=Ninja -DPYTHON=python3
#         -DPYTHON_DESTINATION=lib/python3/dist-packages -DSITE_DESTINATION=lib/python3.11/dist-packages
#         [-DWITH_PYTHON=ON]
#         [-DPVBATCH=pvbatch -DPARAVIEW_PYTHONPATH=dir] -P RunInstalled.cmake
# With PVBATCH, the installed ParaView plugin is loaded in pvbatch and runs a filter.
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
  # The install leaves a subd.pth in the directory the interpreter searches under /usr/local
  # (SITE_DESTINATION there): with that directory a site directory, `import subd` works with
  # no PYTHONPATH and no LD_LIBRARY_PATH (the modules find the libraries by their RUNPATH).
  import_installed_subd("${PYTHON}" "${prefix}/${SITE_DESTINATION}" "/usr/local/${SITE_DESTINATION}"
    "f = subd.vtkSubDCatmullClarkFilter()\nprint(f.GetClassName(), 'Catmull' in f.__doc__)"
    "vtkSubDCatmullClarkFilter True")
  # Staged for /usr/local (DESTDIR, as packagers install): the .pth names the final place,
  # and the package is there under the stage.
  set(stage "${WORK}/stage")
  run(env "DESTDIR=${stage}" "${CMAKE_COMMAND}" --install "${BUILD}" --prefix /usr/local)
  file(READ "${stage}/usr/local/${SITE_DESTINATION}/subd.pth" pth)
  if (NOT pth STREQUAL "/usr/local/${PYTHON_DESTINATION}\n")
    message(FATAL_ERROR "subd.pth names '${pth}', not /usr/local/${PYTHON_DESTINATION}")
  endif ()
  import_installed_subd("${PYTHON}" "${stage}/usr/local/${PYTHON_DESTINATION}" "/usr/local/${SITE_DESTINATION}"
    "print(subd.__file__)" "${stage}/usr/local/${PYTHON_DESTINATION}/subd/__init__.py")
endif ()
if (PVBATCH)
  set(plugin "${prefix}/lib/paraview-5.11/plugins/SubD/SubD.so")
  if (NOT EXISTS "${plugin}")
    message(FATAL_ERROR "the ParaView plugin was not installed")
  endif ()
  set(ENV{PYTHONPATH} "${PARAVIEW_PYTHONPATH}")
  file(WRITE "${WORK}/check_plugin.py" "import paraview.simple as pvs
pvs.LoadPlugin('${plugin}', remote=False)
sphere = pvs.Sphere()
sphere.UpdatePipeline()
f = pvs.SubDLoop(Input=sphere, NumberOfSubdivisions=1)
f.UpdatePipeline()
print('faces', f.GetDataInformation().GetNumberOfCells(), 'of', 4 * sphere.GetDataInformation().GetNumberOfCells())
")
  run("${PVBATCH}" "${WORK}/check_plugin.py")
  if (NOT last_output MATCHES "faces ([0-9]+) of ([0-9]+)" OR NOT CMAKE_MATCH_1 STREQUAL CMAKE_MATCH_2)
    message(FATAL_ERROR "the installed ParaView plugin does not work")
  endif ()
endif ()
