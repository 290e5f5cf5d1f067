# Configures and builds a standalone example project (EXAMPLE_DIR) against the FoldingMeshes
# package installed in INSTALL_DIR (find_package(FoldingMeshes)), then runs its program
# EXECUTABLE with EXAMPLE_ARGS ("|"-separated) in WORK_DIR, prefixed by RUN_PREFIX
# ("|"-separated, e.g. xvfb-run|-a), and checks that the files EXPECT_FILES
# ("|"-separated, relative to WORK_DIR) exist and are not empty. Fails on any error.
foreach (var IN ITEMS EXAMPLE_DIR INSTALL_DIR WORK_DIR EXECUTABLE GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunInstalledExample.cmake: ${var} is not set")
  endif ()
endforeach ()
foreach (var IN ITEMS EXAMPLE_ARGS RUN_PREFIX EXPECT_FILES)
  string(REPLACE "|" ";" ${var} "${${var}}")
endforeach ()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${WORK_DIR}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${err}")
  endif ()
endfunction()
run(${CMAKE_COMMAND} -S "${EXAMPLE_DIR}" -B "${WORK_DIR}/build" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${INSTALL_DIR}")
run(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run(${RUN_PREFIX} "${WORK_DIR}/build/${EXECUTABLE}" ${EXAMPLE_ARGS})
foreach (file IN LISTS EXPECT_FILES)
  if (NOT EXISTS "${WORK_DIR}/${file}")
    message(FATAL_ERROR "the example did not write ${file}")
  endif ()
  file(SIZE "${WORK_DIR}/${file}" size)
  if (size EQUAL 0)
    message(FATAL_ERROR "the example wrote an empty ${file}")
  endif ()
  message("wrote ${file} (${size} bytes)")
endforeach ()
