# Drives the foldingmeshes command line (TestFoldingCommandLine):
#   cmake -DFOLDINGMESHES=<exe> -DMESH=<mesh> -DWORK_DIR=<dir> -P RunFoldingCommandLine.cmake
# 1. `foldingmeshes roundtrip MESH --outdir WORK_DIR --json --quiet` exits 0 (Hausdorff distance
#    within the root epsilon), writes the .vtm tree and prints JSON with a hausdorff value and
#    a filledAreaRatio within [0, areaRatio];
# 2. `foldingmeshes fold` on a missing file exits 2 (unreadable input);
# 3. `foldingmeshes fold` without a mesh exits 1 (bad command line);
# 4. `foldingmeshes unfold` on a file that is not a .vtm tree exits 2 and says so;
# 4b. `foldingmeshes unfold TREE --original MESH` reports the roundtrip's Hausdorff distance;
# 4c. `--up` takes auto, x, y or z on detect, fold and unfold (exit 0 with z), anything else
#     exits 1 and names the option;
# 4d. out-of-range numbers exit 1 on detect and fold; fold --rotation counts rotation nodes in
#     its JSON; detect --rotation prints the rotation
#     and writes STEM_axis.vtp; --min-faces, --method, --seed and
#     --separate-parts reach the builder; roundtrip --no-stitch --no-close-holes leaves seams open;
# 4e. a triangle referring to a point that does not exist: detect, fold and roundtrip exit 2,
#     unfold --original fails, all with the filters' message;
# 4f. compress writes STEM.fmz (JSON output and bytes, smaller than the .vtm tree), decompress
#     --original gives the mesh back within the root epsilon (proved), unfold reads a .fmz,
#     decompress refuses a .vtm and a 3-byte file (exit 2);
# 4f'. compress folds with its own --min-faces 400 and --rotation-when-axial unless given
#     (JSON foldOptions names what it added), and that file is smaller than the one folded
#     with the fold command's --min-faces (the dino: 3,574 against 4,015 bytes); on AXIAL_MESHES
#     (the queen, the bearing) the rotation rule folds twice, keeps the rotation tree's smaller file (than
#     --no-rotation's) and it decompresses within the root epsilon, to at most 1.1 times the
#     input's faces (the sector's budget levels); compress --search tries
#     six more fold settings and keeps the smallest file (no larger than compress's own),
#     which decompresses within the root epsilon;
# 4g. roundtrip measures its distances through vtkStaticCellLocator by default (JSON
#     distanceLocator "static"); --distance-locator facetree gives the same Hausdorff values;
#     another value, and the option on fold, exit 1 and name it;
# 5. `--help` exits 0 and documents every command and the exit codes; `--version` exits 0.
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
set(out_roundtrip "${out}")
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
  # The area of the faces added to close gaps is a share of the unfolded area.
  string(JSON area ERROR_VARIABLE jsonError GET "${out}" areaRatio)
  string(JSON filled ERROR_VARIABLE jsonError2 GET "${out}" filledAreaRatio)
  if (jsonError OR jsonError2)
    message(FATAL_ERROR "roundtrip JSON has no areaRatio / filledAreaRatio: ${jsonError} ${jsonError2}")
  endif ()
  if (filled LESS 0 OR filled GREATER area)
    message(FATAL_ERROR "roundtrip: filledAreaRatio ${filled} outside [0, areaRatio ${area}]")
  endif ()
endif ()

# unfold --original: the filter's distance to the original equals the roundtrip's measure.
execute_process(COMMAND "${FOLDINGMESHES}" unfold "${WORK_DIR}/${stem}_tree.vtm" --original "${MESH}"
  --outdir "${WORK_DIR}/unfold" --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE uout ERROR_VARIABLE err)
message("unfold --original output:\n${uout}${err}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "unfold --original exited with ${rc}, expected 0")
endif ()
if (CMAKE_VERSION VERSION_GREATER_EQUAL 3.19)
  string(JSON unfoldHausdorff ERROR_VARIABLE jsonError GET "${uout}" hausdorffToOriginalRelative)
  if (jsonError)
    message(FATAL_ERROR "unfold --original JSON has no hausdorffToOriginalRelative: ${jsonError}")
  endif ()
  string(SUBSTRING "${unfoldHausdorff}0000" 0 6 a)
  string(SUBSTRING "${hausdorff}0000" 0 6 b)
  if (NOT unfoldHausdorff GREATER 0 OR NOT a STREQUAL b)
    message(FATAL_ERROR "unfold --original: Hausdorff / diagonal ${unfoldHausdorff}, roundtrip ${hausdorff}")
  endif ()
endif ()

# compress / decompress (issue 18): compress writes STEM.fmz, its JSON names it with its
# size; the .fmz is smaller than the .vtm tree's files; decompress --original gives the mesh
# back within the root epsilon (the proved bound, quantisation included); unfold reads the
# .fmz too; decompress refuses a .vtm and a corrupt .fmz (exit 2).
execute_process(COMMAND "${FOLDINGMESHES}" compress "${MESH}" --outdir "${WORK_DIR}/fmz" --json --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE cout ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "compress exited with ${rc}: ${cout}${err}")
endif ()
string(JSON fmz ERROR_VARIABLE jsonError GET "${cout}" output)
string(JSON fmzBytes ERROR_VARIABLE jsonError2 GET "${cout}" bytes)
if (jsonError OR jsonError2 OR NOT fmz STREQUAL "${WORK_DIR}/fmz/${stem}.fmz" OR NOT EXISTS "${fmz}")
  message(FATAL_ERROR "compress JSON: output '${fmz}' bytes '${fmzBytes}' ${jsonError} ${jsonError2}")
endif ()
# compress proves its file against the mesh (vtkFoldingTreeCompactWriter::SetOriginalData):
# within the root epsilon (+1e-7 of the diagonal, which provedWithin allows).
string(JSON provedWithin ERROR_VARIABLE jsonError GET "${cout}" provedWithin)
string(JSON provedBound ERROR_VARIABLE jsonError2 GET "${cout}" provedBound)
string(JSON proofRetries ERROR_VARIABLE jsonError3 GET "${cout}" proofRetries)
string(JSON compressEpsilon ERROR_VARIABLE jsonError4 GET "${cout}" rootEpsilon)
if (jsonError OR jsonError2 OR jsonError3 OR jsonError4 OR NOT provedWithin STREQUAL "ON"
    OR provedBound LESS 0 OR proofRetries LESS 0)
  message(FATAL_ERROR "compress's proof: within '${provedWithin}', bound '${provedBound}' "
    "(epsilon ${compressEpsilon}), retries '${proofRetries}'")
endif ()
file(SIZE "${fmz}" fmzSize)
file(GLOB_RECURSE treeFiles "${WORK_DIR}/${stem}_tree/*" "${WORK_DIR}/${stem}_tree.vtm")
set(treeSize 0)
foreach (f IN LISTS treeFiles)
  file(SIZE "${f}" s)
  math(EXPR treeSize "${treeSize} + ${s}")
endforeach ()
message("compress: ${fmzSize} bytes (.vtm tree: ${treeSize} bytes)")
if (NOT fmzSize EQUAL fmzBytes OR NOT fmzSize LESS treeSize)
  message(FATAL_ERROR "compress: .fmz ${fmzSize} bytes (JSON ${fmzBytes}), .vtm tree ${treeSize}")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" decompress "${fmz}" --original "${MESH}"
  --outdir "${WORK_DIR}/fmz" --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE dout ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "decompress exited with ${rc}: ${dout}${err}")
endif ()
string(JSON dmesh ERROR_VARIABLE jsonError GET "${dout}" output)
string(JSON bound ERROR_VARIABLE jsonError2 GET "${dout}" hausdorffToOriginalBoundRelative)
if (jsonError OR jsonError2 OR NOT dmesh STREQUAL "${WORK_DIR}/fmz/${stem}.vtp" OR NOT EXISTS "${dmesh}")
  message(FATAL_ERROR "decompress JSON: output '${dmesh}' ${jsonError} ${jsonError2}")
endif ()
string(JSON epsilonFraction GET "${out_roundtrip}" rootEpsilonFraction)
message("decompress: proved Hausdorff / diagonal ${bound} (root epsilon ${epsilonFraction})")
if (bound LESS 0 OR bound GREATER epsilonFraction)
  message(FATAL_ERROR "decompress: proved Hausdorff / diagonal ${bound} above ${epsilonFraction}")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" unfold "${fmz}" --outdir "${WORK_DIR}/fmz" --json --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE uout ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK_DIR}/fmz/${stem}_unfolded.vtp")
  message(FATAL_ERROR "unfold of the .fmz exited with ${rc}: ${err}")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" decompress "${WORK_DIR}/${stem}_tree.vtm"
  --outdir "${WORK_DIR}/fmz" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE err)
if (NOT rc EQUAL 2 OR NOT err MATCHES "not a compact folding-tree")
  message(FATAL_ERROR "decompress of a .vtm: exit ${rc}, '${err}' (expected 2 and a clear error)")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" -E echo_append "FMZ"
  OUTPUT_FILE "${WORK_DIR}/fmz/bad.fmz")
execute_process(COMMAND "${FOLDINGMESHES}" decompress "${WORK_DIR}/fmz/bad.fmz"
  --outdir "${WORK_DIR}/fmz" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE err)
if (NOT rc EQUAL 2)
  message(FATAL_ERROR "decompress of a 3-byte file: exit ${rc} (expected 2): ${err}")
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

file(WRITE "${WORK_DIR}/not_a_tree.vtm" "OFF\n0 0 0\n")
execute_process(COMMAND "${FOLDINGMESHES}" unfold "${WORK_DIR}/not_a_tree.vtm" --outdir "${WORK_DIR}"
  --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("unfold on a file that is not a tree: exit ${rc}: ${err}")
if (NOT rc EQUAL 2 OR NOT err MATCHES "neither a VTK XML multiblock")
  message(FATAL_ERROR "unfold on a non-.vtm file exited with ${rc}, expected 2 and a clear message")
endif ()

# 4e. A triangle referring to a point that does not exist (negative, too large) is invalid
#     input on every command (exit 2 and the filter's message), not a crash.
foreach (id IN ITEMS -100000000 4)
  file(WRITE "${WORK_DIR}/badid${id}.vtk" "# vtk DataFile Version 3.0\nbad\nASCII\n"
    "DATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n"
    "POLYGONS 3 12\n3 0 1 2\n3 0 1 3\n3 0 2 ${id}\n")
  foreach (command IN ITEMS detect fold roundtrip)
    execute_process(COMMAND "${FOLDINGMESHES}" ${command} "${WORK_DIR}/badid${id}.vtk" --quiet
      --outdir "${WORK_DIR}/badid" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if (NOT rc EQUAL 2 OR NOT err MATCHES "a triangle refers to a point that does not exist")
      message(FATAL_ERROR "${command} on a triangle with point id ${id} exited with ${rc}, "
        "expected 2 and a clear message: ${err}")
    endif ()
  endforeach ()
  execute_process(COMMAND "${FOLDINGMESHES}" unfold "${WORK_DIR}/${stem}_tree.vtm" --original
    "${WORK_DIR}/badid${id}.vtk" --quiet --outdir "${WORK_DIR}/badid"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (rc EQUAL 0 OR NOT err MATCHES "a triangle refers to a point that does not exist")
    message(FATAL_ERROR "unfold --original with point id ${id} exited with ${rc}, "
      "expected an error and a clear message: ${err}")
  endif ()
endforeach ()

foreach (command IN ITEMS detect fold unfold)
  set(input "${MESH}")
  if (command STREQUAL "unfold")
    set(input "${WORK_DIR}/${stem}_tree.vtm")
  endif ()
  execute_process(COMMAND "${FOLDINGMESHES}" ${command} "${input}" --up z --quiet
    --outdir "${WORK_DIR}/up_${command}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "${command} --up z exited with ${rc}, expected 0: ${err}")
  endif ()
  execute_process(COMMAND "${FOLDINGMESHES}" ${command} "${input}" --up sideways --quiet
    --outdir "${WORK_DIR}/up_${command}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 1 OR NOT err MATCHES "--up must be auto, x, y or z")
    message(FATAL_ERROR "${command} --up sideways exited with ${rc}, expected 1 and a clear message: ${err}")
  endif ()
endforeach ()

# 4d. Numbers out of a parameter's range are rejected on every command (exit 1, the option
#     named), not clamped; options not given keep the filter's defaults, given ones reach it.
foreach (bad IN ITEMS "detect;--candidates;abc;--candidates needs an integer"
    "detect;--candidates;65;--candidates needs an integer"
    "detect;--tolerance;2;--tolerance needs a number"
    "detect;--seed;1.5;--seed needs an integer"
    "detect;--max-rotation-order;1;--max-rotation-order needs an integer"
    "fold;--min-faces;0;--min-faces needs an integer"
    "fold;--seed;x;--seed needs an integer"
    "fold;--method;fast;--method must be robust or paper"
    "fold;--max-rotation-order;361;--max-rotation-order needs an integer")
  list(GET bad 0 command)
  list(GET bad 1 option)
  list(GET bad 2 value)
  list(GET bad 3 expected)
  execute_process(COMMAND "${FOLDINGMESHES}" ${command} "${MESH}" ${option} ${value} --quiet
    --outdir "${WORK_DIR}/bad" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 1 OR NOT err MATCHES "${expected}")
    message(FATAL_ERROR "${command} ${option} ${value} exited with ${rc}, expected 1 and '${expected}': ${err}")
  endif ()
endforeach ()
# detect --rotation reports the rotation in JSON and writes the axis glyph.
execute_process(COMMAND "${FOLDINGMESHES}" detect "${MESH}" --rotation --max-rotation-order 12
  --json --quiet --outdir "${WORK_DIR}/rotation" RESULT_VARIABLE rc OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "\"rotation\": {\"origin\": \\[[^]]+\\], \"direction\""
    OR NOT out MATCHES "\"order\": [0-9]+, \"found\": (true|false)"
    OR NOT EXISTS "${WORK_DIR}/rotation/${stem}_axis.vtp")
  message(FATAL_ERROR "detect --rotation (exit ${rc}) should print the rotation and write "
    "${stem}_axis.vtp: ${out}${err}")
endif ()
# fold --rotation reaches the builder (the dino has no rotational symmetry: no rotation node,
# the same tree) and the JSON counts rotation nodes.
execute_process(COMMAND "${FOLDINGMESHES}" fold "${MESH}" --rotation --json --quiet
  --outdir "${WORK_DIR}/fold_rotation" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "\"rotations\": 0,")
  message(FATAL_ERROR "fold --rotation on the dino should give no rotation node (exit ${rc}): "
    "${out}${err}")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" fold "${MESH}" --min-faces 1000000000 --json --quiet
  --outdir "${WORK_DIR}/minfaces" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "\"folds\": 0," OR NOT out MATCHES "\"leaves\": 1,")
  message(FATAL_ERROR "fold --min-faces 1e9 should give a single leaf (exit ${rc}): ${out}${err}")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" fold "${MESH}" --method paper --seed 3 --separate-parts
  --json --quiet --outdir "${WORK_DIR}/paper" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "\"compression\": 0\\.[0-9]*[1-9]")
  message(FATAL_ERROR "fold --method paper --seed 3 --separate-parts failed (exit ${rc}): ${out}${err}")
endif ()
if (CMAKE_VERSION VERSION_GREATER_EQUAL 3.19)
  # The paper's single start folds the test mesh differently from the default robust method.
  string(JSON paperStored ERROR_VARIABLE jsonError GET "${out}" storedFaces)
  string(JSON defaultStored ERROR_VARIABLE jsonError2 GET "${out_roundtrip}" storedFaces)
  if (jsonError OR jsonError2 OR paperStored EQUAL defaultStored)
    message(FATAL_ERROR "fold --method paper stored ${paperStored} faces, the default "
      "${defaultStored}: the option did not reach the builder")
  endif ()
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" roundtrip "${MESH}" --no-stitch --no-close-holes --json
  --quiet --outdir "${WORK_DIR}/raw" RESULT_VARIABLE rc OUTPUT_VARIABLE rawOut ERROR_VARIABLE err)
if (CMAKE_VERSION VERSION_GREATER_EQUAL 3.19)
  # The raw union keeps the seams open; the stitched and repaired roundtrip above closes them.
  string(JSON rawOpen ERROR_VARIABLE jsonError GET "${rawOut}" openEdgesAfter)
  string(JSON repairedOpen ERROR_VARIABLE jsonError2 GET "${out_roundtrip}" openEdgesAfter)
  if (jsonError OR jsonError2 OR NOT rawOpen GREATER repairedOpen)
    message(FATAL_ERROR "roundtrip --no-stitch --no-close-holes: ${rawOpen} open edges, "
      "stitched and repaired ${repairedOpen} (exit ${rc}): ${rawOut}${err}")
  endif ()
endif ()

# 4f'. compress's own fold defaults: --min-faces 400 unless the user gives --min-faces, and
# --rotation-when-axial unless the user gives a rotation option.
string(JSON ownOptions ERROR_VARIABLE jsonError GET "${cout}" foldOptions)
if (jsonError OR NOT ownOptions STREQUAL "--min-faces 400 --rotation-when-axial")
  message(FATAL_ERROR "compress JSON foldOptions '${ownOptions}' ${jsonError} (expected '--min-faces 400 --rotation-when-axial')")
endif ()
foreach (given IN ITEMS "--keep;more" "--min-faces;50")
  execute_process(COMMAND "${FOLDINGMESHES}" compress "${MESH}" ${given} --outdir "${WORK_DIR}/given"
    --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE gout ERROR_VARIABLE err)
  string(JSON givenOptions ERROR_VARIABLE jsonError GET "${gout}" foldOptions)
  string(JSON givenBytes ERROR_VARIABLE jsonError2 GET "${gout}" bytes)
  if (given STREQUAL "--keep;more")
    set(expected "--min-faces 400 --rotation-when-axial")
  else ()
    set(expected "--rotation-when-axial")
    set(foldDefaultBytes "${givenBytes}")
  endif ()
  if (NOT rc EQUAL 0 OR jsonError OR jsonError2 OR NOT givenOptions STREQUAL expected)
    message(FATAL_ERROR "compress ${given}: exit ${rc}, foldOptions '${givenOptions}' (expected '${expected}') ${err}")
  endif ()
endforeach ()
message("compress: ${fmzBytes} bytes with its own fold default, ${foldDefaultBytes} with the fold command's")
if (NOT fmzBytes LESS foldDefaultBytes)
  message(FATAL_ERROR "compress's own fold default made ${fmzBytes} bytes, the fold command's ${foldDefaultBytes}")
endif ()

# compress's rotation rule on AXIAL_MESHES ('|'-separated: the queen and the bearing, their second
# moments axially symmetric): rotation nodes, compared with the fold without them (two folds),
# the smaller file kept - the rotation tree's, smaller than --no-rotation's - and it decompresses
# within the root epsilon (proved) to at most 1.1 times the input's faces.
string(REPLACE "|" ";" axialMeshes "${AXIAL_MESHES}")
foreach (AXIAL_MESH IN LISTS axialMeshes)
  if (NOT EXISTS "${AXIAL_MESH}")
    message("no ${AXIAL_MESH}: its compress checks skipped")
    continue()
  endif ()
  get_filename_component(axialStem "${AXIAL_MESH}" NAME_WE)
  foreach (rotation IN ITEMS "" "--no-rotation")
    execute_process(COMMAND "${FOLDINGMESHES}" compress "${AXIAL_MESH}" ${rotation}
      --outdir "${WORK_DIR}/${axialStem}${rotation}" --json --quiet
      RESULT_VARIABLE rc OUTPUT_VARIABLE aout ERROR_VARIABLE err)
    string(JSON axialBytes${rotation} ERROR_VARIABLE jsonError GET "${aout}" bytes)
    string(JSON axialTried${rotation} ERROR_VARIABLE jsonError2 GET "${aout}" foldSettingsTried)
    string(JSON axialOptions${rotation} ERROR_VARIABLE jsonError3 GET "${aout}" foldOptions)
    if (NOT rc EQUAL 0 OR jsonError OR jsonError2 OR jsonError3)
      message(FATAL_ERROR "compress ${AXIAL_MESH} ${rotation}: exit ${rc} ${aout} ${err}")
    endif ()
  endforeach ()
  message("compress ${axialStem}: ${axialBytes} bytes ('${axialOptions}', ${axialTried} folds), "
    "${axialBytes--no-rotation} with --no-rotation ('${axialOptions--no-rotation}')")
  if (NOT axialTried EQUAL 2 OR NOT axialOptions STREQUAL "--min-faces 400 --rotation-when-axial"
      OR NOT axialBytes LESS axialBytes--no-rotation OR NOT axialTried--no-rotation EQUAL 1
      OR NOT axialOptions--no-rotation STREQUAL "--min-faces 400")
    message(FATAL_ERROR "compress's rotation rule on ${axialStem}: see the numbers above")
  endif ()
  execute_process(COMMAND "${FOLDINGMESHES}" decompress "${WORK_DIR}/${axialStem}/${axialStem}.fmz"
    --original "${AXIAL_MESH}" --outdir "${WORK_DIR}/${axialStem}" --json --quiet
    RESULT_VARIABLE rc OUTPUT_VARIABLE dout3 ERROR_VARIABLE err)
  string(JSON axialBound ERROR_VARIABLE jsonError GET "${dout3}" hausdorffToOriginalBoundRelative)
  if (NOT rc EQUAL 0 OR jsonError OR axialBound LESS 0 OR axialBound GREATER epsilonFraction)
    message(FATAL_ERROR "decompress of ${axialStem}.fmz: exit ${rc}, bound ${axialBound} ${err}")
  endif ()
  # The rotation tree's sector, cut along its half-planes, comes back with about the input's
  # faces: its points' budget levels and the bits for its seams let the unfolder thin the k
  # copies as in memory (the queen: 3,191 faces for 3,275, 9,545 with one budget per leaf; the
  # bearing 3,322 for 3,322, 10,981 at the 8 bits of the budgets alone).
  string(JSON axialFaces ERROR_VARIABLE jsonError GET "${dout3}" faces)
  execute_process(COMMAND "${FOLDINGMESHES}" detect "${AXIAL_MESH}" --outdir "${WORK_DIR}/${axialStem}"
    --json --quiet OUTPUT_VARIABLE detectOut ERROR_VARIABLE err)
  string(JSON axialInputFaces ERROR_VARIABLE jsonError4 GET "${detectOut}" faces)
  if (jsonError OR jsonError4)
    message(FATAL_ERROR "decompress / detect of ${axialStem}: no face count: ${dout3} ${detectOut}")
  endif ()
  math(EXPR axialFaceLimit "${axialInputFaces} * 11 / 10")
  message("decompress ${axialStem}.fmz: ${axialFaces} faces for the input's ${axialInputFaces}")
  if (axialFaces GREATER axialFaceLimit)
    message(FATAL_ERROR "decompress of ${axialStem}.fmz: ${axialFaces} faces, more than 1.1 "
      "times the input's ${axialInputFaces}")
  endif ()
endforeach ()

# compress --search: seven fold settings tried, a file no larger than compress's own, and
# it decompresses within the root epsilon (proved).
execute_process(COMMAND "${FOLDINGMESHES}" compress "${MESH}" --search --outdir "${WORK_DIR}/search"
  --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE sout ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "compress --search exited with ${rc}: ${err}")
endif ()
string(JSON searchBytes ERROR_VARIABLE jsonError GET "${sout}" bytes)
string(JSON searchTried ERROR_VARIABLE jsonError2 GET "${sout}" foldSettingsTried)
string(JSON searchOptions ERROR_VARIABLE jsonError3 GET "${sout}" foldOptions)
string(JSON plainBytes GET "${cout}" bytes)
message("compress --search: ${searchBytes} bytes (plain ${plainBytes}), ${searchTried} settings tried, chose '${searchOptions}'")
if (jsonError OR jsonError2 OR jsonError3 OR NOT searchTried EQUAL 7 OR searchBytes GREATER plainBytes)
  message(FATAL_ERROR "compress --search JSON: ${sout} ${jsonError} ${jsonError2} ${jsonError3}")
endif ()
file(GLOB leftovers "${WORK_DIR}/search/*.candidate")
if (leftovers)
  message(FATAL_ERROR "compress --search left ${leftovers} behind")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" decompress "${WORK_DIR}/search/${stem}.fmz" --original "${MESH}"
  --outdir "${WORK_DIR}/search" --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE dout2 ERROR_VARIABLE err)
string(JSON searchBound ERROR_VARIABLE jsonError GET "${dout2}" hausdorffToOriginalBoundRelative)
if (NOT rc EQUAL 0 OR jsonError OR searchBound LESS 0 OR searchBound GREATER epsilonFraction)
  message(FATAL_ERROR "decompress of the --search file: exit ${rc}, bound ${searchBound} (root epsilon ${epsilonFraction}) ${err}")
endif ()

# 4g. The locator behind roundtrip's distances.
string(JSON defaultLocator ERROR_VARIABLE jsonError GET "${out_roundtrip}" distanceLocator)
if (jsonError OR NOT defaultLocator STREQUAL "static")
  message(FATAL_ERROR "roundtrip JSON: distanceLocator '${defaultLocator}' ${jsonError} (expected static)")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" roundtrip "${MESH}" --distance-locator facetree
  --outdir "${WORK_DIR}/facetree" --json --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE tout ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "roundtrip --distance-locator facetree exited with ${rc}: ${err}")
endif ()
foreach (key IN ITEMS distanceLocator hausdorff hausdorffBoundFraction meanDistanceFraction)
  string(JSON withTree ERROR_VARIABLE jsonError GET "${tout}" ${key})
  string(JSON withLocator ERROR_VARIABLE jsonError2 GET "${out_roundtrip}" ${key})
  if (jsonError OR jsonError2)
    message(FATAL_ERROR "roundtrip JSON has no ${key}: ${jsonError} ${jsonError2}")
  endif ()
  if (key STREQUAL "distanceLocator")
    if (NOT withTree STREQUAL "facetree")
      message(FATAL_ERROR "roundtrip --distance-locator facetree: JSON says '${withTree}'")
    endif ()
  elseif (NOT withTree STREQUAL withLocator)
    message(FATAL_ERROR "roundtrip ${key}: ${withTree} with the face tree, ${withLocator} with vtkStaticCellLocator")
  endif ()
endforeach ()
execute_process(COMMAND "${FOLDINGMESHES}" roundtrip "${MESH}" --distance-locator kdtree
  --outdir "${WORK_DIR}/facetree" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE err)
if (NOT rc EQUAL 1 OR NOT err MATCHES "--distance-locator")
  message(FATAL_ERROR "roundtrip --distance-locator kdtree: exit ${rc}, '${err}' (expected 1 naming the option)")
endif ()
execute_process(COMMAND "${FOLDINGMESHES}" fold "${MESH}" --distance-locator static
  --outdir "${WORK_DIR}/facetree" --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE err)
if (NOT rc EQUAL 1 OR NOT err MATCHES "--distance-locator")
  message(FATAL_ERROR "fold --distance-locator: exit ${rc}, '${err}' (expected 1 naming the option)")
endif ()

execute_process(COMMAND "${FOLDINGMESHES}" --help
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "--help exited with ${rc}, expected 0")
endif ()
foreach (text IN ITEMS "detect MESH" "fold MESH" "unfold TREE.vtm" "roundtrip MESH" "compress MESH"
    "decompress FILE.fmz" "--quantization-bits" "exit codes: 0"
    "--tolerance" "--keep" "--max-folds" "--min-area-fraction" "--min-faces" "--seed"
    "--no-stitch" "--up" "--version")
  string(FIND "${out}" "${text}" found)
  if (found EQUAL -1)
    message(FATAL_ERROR "--help does not mention '${text}'")
  endif ()
endforeach ()
execute_process(COMMAND "${FOLDINGMESHES}" --version
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "^foldingmeshes [0-9]+\\.[0-9]+")
  message(FATAL_ERROR "--version exited with ${rc}: ${out}")
endif ()
message("TestFoldingCommandLine passed")
