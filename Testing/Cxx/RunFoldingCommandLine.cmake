# Drives the foldingmeshes command line (TestFoldingCommandLine):
#   cmake -DFOLDINGMESHES=<exe> -DMESH=<mesh> -DWORK_DIR=<dir> -P RunFoldingCommandLine.cmake
# 1. `foldingmeshes roundtrip MESH --outdir WORK_DIR --json --quiet` exits 0 (Hausdorff distance
#    within the root epsilon), writes the .vtm tree and prints JSON with a hausdorff value;
# 2. `foldingmeshes fold` on a missing file exits 2 (unreadable input);
# 3. `foldingmeshes fold` without a mesh exits 1 (bad command line).
foreach (var FOLDINGMESHES MESH WORK_DIR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "${var} not set")
  endif ()
endforeach ()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
get_filename_component(stem "${MESH}" NAME_WE)

execute_process(COMMAND "${FOLDINGMESHES}" roundtrip "${MESH}" --outdir "${WORK_DIR}" --json --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("roundtrip output:\n${out}${err}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "roundtrip exited with ${rc}, expected 0")
endif ()
if (NOT EXISTS "${WORK_DIR}/${stem}_tree.vtm")
  message(FATAL_ERROR "roundtrip did not write ${WORK_DIR}/${stem}_tree.vtm")
endif ()
if (NOT EXISTS "${WORK_DIR}/${stem}_unfolded.vtp")
  message(FATAL_ERROR "roundtrip did not write ${WORK_DIR}/${stem}_unfolded.vtp")
endif ()
if (NOT out MATCHES "\"hausdorff\": *[0-9.eE+-]+")
  message(FATAL_ERROR "roundtrip JSON has no numeric \"hausdorff\" value")
endif ()
if (CMAKE_VERSION VERSION_GREATER_EQUAL 3.19)
  string(JSON hausdorff ERROR_VARIABLE jsonError GET "${out}" hausdorffFraction)
  string(JSON epsilon ERROR_VARIABLE jsonError2 GET "${out}" rootEpsilonFraction)
  if (jsonError OR jsonError2)
    message(FATAL_ERROR "roundtrip output is not valid JSON: ${jsonError} ${jsonError2}")
  endif ()
  message("hausdorff / diagonal = ${hausdorff} (root epsilon / diagonal = ${epsilon})")
endif ()

execute_process(COMMAND "${FOLDINGMESHES}" fold "${WORK_DIR}/no_such_mesh.off" --outdir "${WORK_DIR}"
  --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("fold on a missing file: exit ${rc}: ${err}")
if (NOT rc EQUAL 2)
  message(FATAL_ERROR "fold on a missing file exited with ${rc}, expected 2")
endif ()

execute_process(COMMAND "${FOLDINGMESHES}" fold
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 1)
  message(FATAL_ERROR "fold without a mesh exited with ${rc}, expected 1")
endif ()
message("TestFoldingCommandLine passed")
