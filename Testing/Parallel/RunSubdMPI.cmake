# subd-mpi end to end: a built-in cage made denser (two linear levels, so that each rank owns
# cells beyond the ghost layers), the serial subd output, the same on N ranks with subd-mpi,
# and the pieces compared with it.
#   cmake -DSUBD=... -DSUBD_MPI=... -DCOMPARE=... -DMPIEXEC=... -DRANKS=N -DCAGE=name
#         -DARGS="a|b|..." -DWORK=dir -P RunSubdMPI.cmake
string(REPLACE "|" ";" ARGS "${ARGS}")
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/../CMake/RunStep.cmake")
run(${SUBD} --builtin ${CAGE} --scheme linear --levels 2 --output "${WORK}/input.vtp")
run(${SUBD} "${WORK}/input.vtp" ${ARGS} --output "${WORK}/serial.vtp")
run(${MPIEXEC} --allow-run-as-root --oversubscribe -np ${RANKS} ${SUBD_MPI} ${ARGS} "${WORK}/input.vtp"
  "${WORK}/pieces.pvtp")
run(${COMPARE} "${WORK}/serial.vtp" "${WORK}/pieces.pvtp")
