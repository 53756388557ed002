# The step runner of the test scripts (included by them): run(command args...) runs a
# command, echoes it with its output, fails the script when it fails, and leaves its output in
# `last_output` for the caller to check.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ ${ARGN}\n${out}${err}")
  if (NOT code EQUAL 0)
    message(FATAL_ERROR "failed with exit code ${code}")
  endif ()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction()
