# Runs a command and checks its exit code and output.
#   cmake -DCOMMAND=prog -DARGS="arg|arg|..." -DEXPECT_EXIT=0|nonzero [-DEXPECT_OUTPUT=regex]
#         [-DEXPECT_FILE=path] [-DWORKING_DIRECTORY=dir] -P RunAndCheck.cmake
if (DEFINED EXPECT_FILE)
  file(REMOVE "${EXPECT_FILE}")
endif ()
if (NOT DEFINED WORKING_DIRECTORY)
  set(WORKING_DIRECTORY ".")
endif ()
file(MAKE_DIRECTORY "${WORKING_DIRECTORY}")
string(REPLACE "|" ";" ARGS "${ARGS}")
execute_process(COMMAND ${COMMAND} ${ARGS}
  WORKING_DIRECTORY "${WORKING_DIRECTORY}"
  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("exit code: ${code}\nstdout:\n${out}\nstderr:\n${err}")
if (EXPECT_EXIT STREQUAL "nonzero")
  if (code EQUAL 0)
    message(FATAL_ERROR "expected a non-zero exit code")
  endif ()
elseif (NOT code EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "expected exit code ${EXPECT_EXIT}, got ${code}")
endif ()
if (DEFINED EXPECT_OUTPUT AND NOT "${out}${err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}'")
endif ()
if (DEFINED EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "expected output file ${EXPECT_FILE} was not written")
endif ()
