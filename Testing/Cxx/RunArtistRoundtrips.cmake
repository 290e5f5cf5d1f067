# TestArtistRoundtrips (issue 21): artist-like meshes (GenerateArtistMeshes: many separate parts,
# open, flipped and duplicated parts, large triangles) folded and unfolded by
# `foldingmeshes roundtrip` at the default options. Each must come back within its proved bound
# ("withinBound": true) and, where the input was closed, closed. The dense chair is the case
# where the final weld's chained same-copy pairs once collapsed whole open parts (0.123 of the
# diagonal); figure_deformed the one where the builder's verification must build again (its
# first tree is proved 1.03 epsilon away: a near miss, rebuilt at 0.943 epsilon). All 21 meshes
# (rack_deformed came back with open seams with its trees before 2026-12-05; its tree since
# comes back closed). The exactly symmetric chairs, rack and biplane, whose symmetry maps
# separate parts onto each other (a leg onto the other leg), must fold to at most 60% of their
# faces (before whole parts joined the symmetric region, 2026-12-05, the chairs and the biplane
# did not fold at all). The distances are measured through the core's face tree
# (--distance-locator facetree): the same values as roundtrip's default vtkStaticCellLocator
# (TestFoldingCommandLine compares them), which takes 25x longer here (the dense chair's
# measure 1.8 s against 46 s) and would take this test past its timeout.
#   cmake -DGENERATOR=<GenerateArtistMeshes> -DFOLDINGMESHES=<foldingmeshes> -DWORK_DIR=<dir>
#         -P RunArtistRoundtrips.cmake
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${GENERATOR}" "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_QUIET)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "GenerateArtistMeshes failed (${rc})")
endif ()
set(failures 0)
foreach (mesh IN ITEMS chair_dense_exact chair_dense_moved chair_dense_deformed chair_exact
    chair_moved chair_deformed bench_slats_exact bench_slats_moved bench_slats_deformed
    rack_exact rack_moved rack_deformed soup_exact soup_moved soup_deformed figure_exact
    figure_moved figure_deformed biplane_exact biplane_moved biplane_deformed)
  execute_process(
    COMMAND "${FOLDINGMESHES}" roundtrip "${WORK_DIR}/${mesh}.ply" --json --distance-locator facetree
            --outdir "${WORK_DIR}/out"
    RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err)
  string(JSON within ERROR_VARIABLE jsonError GET "${json}" withinBound)
  string(JSON bound ERROR_VARIABLE jsonError GET "${json}" hausdorffBoundFraction)
  string(JSON openBefore ERROR_VARIABLE jsonError GET "${json}" openEdgesBefore)
  string(JSON openAfter ERROR_VARIABLE jsonError GET "${json}" openEdgesAfter)
  string(JSON stored ERROR_VARIABLE jsonError GET "${json}" storedFaces)
  string(JSON faces ERROR_VARIABLE jsonError GET "${json}" originalFaces)
  set(folds ON)
  if (mesh MATCHES "^(chair|chair_dense|rack|biplane)_exact$")
    if (NOT stored MATCHES "^[0-9]+$" OR NOT faces MATCHES "^[0-9]+$")
      set(folds OFF)
    else ()
      math(EXPR limit "${faces} * 6 / 10")
      if (stored GREATER limit)
        set(folds OFF)
      endif ()
    endif ()
  endif ()
  if (NOT within STREQUAL "ON")
    message("FAIL ${mesh}: not within the proved bound (${within}, bound ${bound} of the diagonal, exit ${rc}) ${err}")
    math(EXPR failures "${failures} + 1")
  elseif (NOT folds)
    message("FAIL ${mesh}: symmetric parts, but ${stored} of ${faces} faces stored (at most 60% expected)")
    math(EXPR failures "${failures} + 1")
  elseif (openBefore STREQUAL "0" AND NOT openAfter STREQUAL "0")
    message("FAIL ${mesh}: closed input, ${openAfter} open edges after the round trip")
    math(EXPR failures "${failures} + 1")
  else ()
    message("ok   ${mesh}: ${stored} of ${faces} faces stored, bound ${bound} of the diagonal, open edges ${openBefore} -> ${openAfter}")
  endif ()
endforeach ()
if (failures GREATER 0)
  message(FATAL_ERROR "TestArtistRoundtrips: ${failures} mesh(es) failed")
endif ()
message("TestArtistRoundtrips passed")
