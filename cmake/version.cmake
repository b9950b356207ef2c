# Writes ind_version.h with the current git commit; run at every build so output files never carry a
# stale commit. configure_file leaves the header untouched (no rebuild) when nothing changed.
execute_process(COMMAND git describe --always --dirty --abbrev=12
  WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE INDENT_GIT_COMMIT
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT INDENT_GIT_COMMIT)
  set(INDENT_GIT_COMMIT "unknown")
endif()
configure_file(${SOURCE_DIR}/include/ind_version.h.in ${OUTPUT} @ONLY)
