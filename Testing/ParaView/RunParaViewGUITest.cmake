# Runs the ParaView client on a QtTesting XML script and checks the outcome.
#   cmake -DPARAVIEW=<paraview> [-DLAUNCHER=<xvfb-run|-n|N|-a>] -DPLUGIN_DIR=<dir> -DMESH=<file>
#         -DSCRIPT=<xml> -DBASELINE=<png> -DTEST_DIR=<dir> -DEXPECT=<success|missing-plugin>
#         -P RunParaViewGUITest.cmake
# EXPECT=success: playback succeeds and the final view matches BASELINE (exit code 0).
# EXPECT=missing-plugin: PLUGIN_DIR does not hold the plugin; the run must fail, promptly,
# because playback cannot find the "Folding Meshes" menu. This proves the success case
# cannot pass without the plugin and its menu entries.
foreach (var IN ITEMS PARAVIEW PLUGIN_DIR MESH SCRIPT BASELINE TEST_DIR EXPECT)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunParaViewGUITest.cmake: ${var} is not set")
  endif ()
endforeach ()
file(MAKE_DIRECTORY "${TEST_DIR}")
# LAUNCHER: the display launcher ("|"-separated), see CMake/FoldingMeshesDisplay.cmake.
string(REPLACE "|" ";" launcher "${LAUNCHER}")
# --dr: no user settings; --data opens the mesh with the reader for its extension.
execute_process(
  COMMAND ${launcher} "${PARAVIEW}" --dr
          "--data=${MESH}"
          "--plugin-search-paths=${PLUGIN_DIR}" --plugins=FoldingMeshes
          "--test-script=${SCRIPT}" "--test-baseline=${BASELINE}"
          "--test-directory=${TEST_DIR}" --exit
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output
  TIMEOUT 300)
message("${output}")
message("paraview exit: ${result}")
string(FIND "${output}" "Couldn't find object" missing_object)
if (EXPECT STREQUAL "success")
  if (NOT result EQUAL 0 OR NOT missing_object EQUAL -1)
    message(FATAL_ERROR "The ParaView GUI test failed (exit ${result}); see the output above.")
  endif ()
elseif (EXPECT STREQUAL "missing-plugin")
  if (result EQUAL 0)
    message(FATAL_ERROR "ParaView passed the GUI test without the plugin: the test proves nothing.")
  endif ()
  if (NOT output MATCHES "Couldn't find object[^\n]*Folding Meshes")
    message(FATAL_ERROR "Without the plugin ParaView failed (exit ${result}), but not because "
                        "the \"Folding Meshes\" menu is missing.")
  endif ()
  message("ok: without the plugin the GUI test fails at the missing \"Folding Meshes\" menu.")
else ()
  message(FATAL_ERROR "RunParaViewGUITest.cmake: unknown EXPECT '${EXPECT}'")
endif ()
