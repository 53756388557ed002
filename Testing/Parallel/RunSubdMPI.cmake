# subd-mpi end to end: a built-in cage made denser (two linear levels, so that each rank owns
# cells beyond the ghost layers), the serial subd output, the same on N ranks with subd-mpi,
# and the pieces compared with it.
#   cmake -DSUBD=... -DSUBD_MPI=... -DCOMPARE=... -DMPIEXEC=... -DRANKS=N -DCAGE=name
#         -DARGS="a|b|..." -DWORK=dir -P RunSubdMPI.cmake
# With -DPVBATCH=... -DEXAMPLE=... -DPLUGIN=... -DSCHEME=... -DLEVELS=..., the N ranks are
# pvbatch running the ParaView example instead of subd-mpi (PYTHONPATH set by the caller).
# With -DEXPECT_WARNING=regex, the parallel run's output must match it, and nothing is compared.
string(REPLACE "|" ";" ARGS "${ARGS}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/../CMake/RunStep.cmake")
run(${SUBD} --builtin ${CAGE} --scheme linear --levels 2 --output "${WORK}/input.vtp")
run(${SUBD} "${WORK}/input.vtp" ${ARGS} --output "${WORK}/serial.vtp")
if (PVBATCH)
  # The same with ParaView: Examples/ParaView/subdivide_in_parallel.py in pvbatch, with the plugin.
  run(${MPIEXEC} --allow-run-as-root --oversubscribe -np ${RANKS} -x PYTHONPATH ${PVBATCH} --symmetric
    ${EXAMPLE} ${PLUGIN} "${WORK}/input.vtp" "${WORK}/pieces.pvtp" ${SCHEME} ${LEVELS})
else ()
  run(${MPIEXEC} --allow-run-as-root --oversubscribe -np ${RANKS} ${SUBD_MPI} ${ARGS} "${WORK}/input.vtp"
    "${WORK}/pieces.pvtp")
endif ()
if (EXPECT_WARNING)
  # A pipeline known to give pieces without ghost cells: the filter must say so.
  if (NOT last_output MATCHES "${EXPECT_WARNING}")
    message(FATAL_ERROR "expected a warning matching '${EXPECT_WARNING}'")
  endif ()
  return()
endif ()
run(${COMPARE} "${WORK}/serial.vtp" "${WORK}/pieces.pvtp")
