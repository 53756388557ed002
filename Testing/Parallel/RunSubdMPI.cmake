# subd-mpi end to end: a built-in cage made denser (two linear levels, so that each rank owns
# cells beyond the ghost layers; its creases come along), the serial subd output, the same
# options on N ranks with subd-mpi, and the pieces compared with it (ComparePieceFiles: the
# same point-data arrays, and the values of those not in COMPARE_ARGS' --presence-only).
#   cmake -DSUBD=... -DSUBD_MPI=... -DCOMPARE=... -DMPIEXEC=... -DRANKS=N -DCAGE=name
#         -DARGS="a|b|..." -DWORK=dir [-DINPUT_EXT=obj] [-DCOMPARE_ARGS="a|b|..."] -P RunSubdMPI.cmake
# CAGE: a built-in cage's name, or the absolute path of a cage file. INPUT_EXT: the input
# file's format (default vtp; obj carries the creases as OpenSubdiv's tags).
# With -DPVBATCH=... -DEXAMPLE=... -DPLUGIN=... -DSCHEME=... -DLEVELS=..., the N ranks are
# pvbatch running the ParaView example instead of subd-mpi (PYTHONPATH set by the caller).
# With -DEXPECT_WARNING=regex, the parallel run's output must match it, and nothing is compared.
string(REPLACE "|" ";" ARGS "${ARGS}")
string(REPLACE "|" ";" COMPARE_ARGS "${COMPARE_ARGS}")
if (NOT INPUT_EXT)
  set(INPUT_EXT vtp)
endif ()
set(input "${WORK}/input.${INPUT_EXT}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/../CMake/RunStep.cmake")
if (IS_ABSOLUTE "${CAGE}")
  set(cage "${CAGE}")
else ()
  set(cage --builtin ${CAGE})
endif ()
run(${SUBD} ${cage} --scheme linear --levels 2 --output "${input}")
run(${SUBD} "${input}" ${ARGS} --output "${WORK}/serial.vtp")
if (PVBATCH)
  # The same with ParaView: Examples/ParaView/subdivide_in_parallel.py in pvbatch, with the plugin.
  run(${MPIEXEC} --allow-run-as-root --oversubscribe -np ${RANKS} -x PYTHONPATH ${PVBATCH} --symmetric
    ${EXAMPLE} ${PLUGIN} "${input}" "${WORK}/pieces.pvtp" ${SCHEME} ${LEVELS})
else ()
  # subd-mpi takes subd's options as they are; its pieces hold exactly the serial arrays.
  run(${MPIEXEC} --allow-run-as-root --oversubscribe -np ${RANKS} ${SUBD_MPI} "${input}" ${ARGS}
    --output "${WORK}/pieces.pvtp")
  list(PREPEND COMPARE_ARGS --same-arrays)
endif ()
if (EXPECT_WARNING)
  # A pipeline known to give pieces without ghost cells: the filter must say so.
  if (NOT last_output MATCHES "${EXPECT_WARNING}")
    message(FATAL_ERROR "expected a warning matching '${EXPECT_WARNING}'")
  endif ()
  return()
endif ()
run(${COMPARE} "${WORK}/serial.vtp" "${WORK}/pieces.pvtp" ${COMPARE_ARGS})
