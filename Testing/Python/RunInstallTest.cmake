# Installs the build into a scratch prefix and imports the Python package from there only.
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE result OUTPUT_QUIET)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result})")
endif ()
set(ENV{PYTHONPATH} "${PREFIX}/${PYTHON_DESTINATION}")
execute_process(
  COMMAND "${PYTHON}" -c
    "import exactmat, os; from exactmat import vtkNURBSSource; s = vtkNURBSSource(); s.SetShapeName('star'); s.Update(); n = s.GetOutput().GetNumberOfCells(); assert n == 10, n; assert exactmat.__file__.startswith(os.environ['PYTHONPATH']), exactmat.__file__; print('installed package OK', exactmat.__file__)"
  RESULT_VARIABLE result)
if (NOT result EQUAL 0)
  message(FATAL_ERROR "importing the installed package failed")
endif ()
if (NOT EXISTS "${PREFIX}/lib/paraview-plugins/ExactMAT/ExactMAT.so")
  message(FATAL_ERROR "the plugin was not installed")
endif ()
