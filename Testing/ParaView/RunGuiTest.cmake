# Runs the ParaView GUI on a script under Xvfb and checks the marker file it writes.
file(REMOVE "${MARKER}")
set(ENV{EXACTMAT_PLUGIN} "${PLUGIN}")
set(ENV{EXACTMAT_MARKER} "${MARKER}")
execute_process(
  COMMAND "${XVFB_RUN}" -a "${PARAVIEW}" "--script=${SCRIPT}" --exit
  RESULT_VARIABLE result
  TIMEOUT 300)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "paraview exited with ${result}")
endif ()
if (NOT EXISTS "${MARKER}")
  message(FATAL_ERROR "the GUI script did not run (no ${MARKER})")
endif ()
file(READ "${MARKER}" content)
if (NOT content STREQUAL "cells 10\n")
  message(FATAL_ERROR "unexpected output from the GUI: ${content}")
endif ()
message(STATUS "ExactMAT plugin loaded in the ParaView GUI: ${content}")
