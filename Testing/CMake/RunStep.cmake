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

# import_installed_subd(python site_dir expected_site checks expected_output): imports `subd`
# from an installed tree with a clean environment (no PYTHONPATH, no LD_LIBRARY_PATH):
# `site_dir` is added as a site directory (its .pth files are read), after checking that
# `expected_site` is one of the interpreter's own; then the Python lines `checks` run and their
# output must match `expected_output`.
function(import_installed_subd python site_dir expected_site checks expected_output)
  string(RANDOM LENGTH 8 tag)
  set(script "${CMAKE_CURRENT_BINARY_DIR}/import-subd-${tag}.py")
  file(WRITE "${script}"
    "import site, sys\n"
    "assert '${expected_site}' in site.getsitepackages(), site.getsitepackages()\n"
    "site.addsitedir(sys.argv[1])\n"
    "import subd\n${checks}\n")
  run(env -u PYTHONPATH -u LD_LIBRARY_PATH "${python}" "${script}" "${site_dir}")
  file(REMOVE "${script}")
  if (NOT last_output MATCHES "${expected_output}")
    message(FATAL_ERROR "the installed Python package does not work")
  endif ()
endfunction()
