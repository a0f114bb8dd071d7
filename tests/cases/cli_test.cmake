# Runs the built `lexel` binary on good and bad case files and checks output and exit codes.
# Invoked by ctest with -DLEXEL=... -DCASES=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
include("${CMAKE_CURRENT_LIST_DIR}/check_html_links.cmake")

include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")

set(good "${CASES}/flatland/single_plane.json")

# Help and version.
expect_run(0 "lexel: choose the light projection" "" --help)
expect_run(0 "^lexel [0-9]+\\.[0-9]+\\.[0-9]+" "" --version)

# A good case: table, JSON and CSV.
expect_run(0 "optimal-l1.*optimal-l2-newton.*plane-optimal" "^$" run "${good}")
expect_run(0 "^\\{\n  \"case\": \"single_plane\"" "^$" run "${good}" --format json --method optimal-l1 --method psm)
string(JSON method0 GET "${lastStdout}" methods 0 method)
string(JSON method1 GET "${lastStdout}" methods 1 method)
string(JSON angle GET "${lastStdout}" methods 0 lexel_plane_deg)
string(JSON visible GET "${lastStdout}" pixels_visible)
if(NOT method0 STREQUAL "optimal-l1" OR NOT method1 STREQUAL "psm" OR visible LESS 1)
    message(FATAL_ERROR "unexpected JSON document:\n${lastStdout}")
endif()
expect_run(0 "^case,method,lexel_plane_deg,.*\nsingle_plane,normal," "^$" run "${good}" --format csv --method normal)
expect_run(0 "\"cases\": \\[" "" run "${good}" "${CASES}/flatland/simple_geometry.json" --format json --method normal)

# --out writes the three files per case and index.html, whose every link resolves.
expect_run(0 "" "wrote index.html and 3 files" run "${good}" --method normal --out "${WORK}/out")
foreach(ext json csv md)
    if(NOT EXISTS "${WORK}/out/single_plane.${ext}")
        message(FATAL_ERROR "missing ${WORK}/out/single_plane.${ext}")
    endif()
endforeach()
check_html_links("${WORK}/out/index.html")
if(NOT htmlLinks EQUAL 3)
    message(FATAL_ERROR "${WORK}/out/index.html: ${htmlLinks} links, expected 3")
endif()
# A name with HTML's and URLs' special characters: escaped in the text, encoded in the links.
file(READ "${good}" goodText)
string(REPLACE "\"single_plane\"" "\"odd <i>name & \\\"quoted\\\", 50%\"" oddText "${goodText}")
file(WRITE "${WORK}/odd.json" "${oddText}")
expect_run(0 "" "wrote index.html and 3 files" run "${WORK}/odd.json" --method normal --out "${WORK}/odd")
check_html_links("${WORK}/odd/index.html")
file(READ "${WORK}/odd/index.html" page)
if(NOT htmlLinks EQUAL 3 OR page MATCHES "<i>name" OR NOT page MATCHES "odd &lt;i&gt;name &amp; &quot;quoted&quot;, 50%"
   OR NOT page MATCHES "href=\"odd%20%3Ci%3Ename%20%26%20%22quoted%22%2C%2050%25\\.json\"")
    message(FATAL_ERROR "${WORK}/odd/index.html: the name is not escaped or encoded:\n${page}")
endif()
# The link checker itself fails on a missing file, an anchor without its id, a link out of the
# directory, and a page cut short.
file(MAKE_DIRECTORY "${WORK}/badhtml")
file(WRITE "${WORK}/badhtml/there.png" "")
set(head "<!DOCTYPE html>\n<html lang=\"en\">\n<body>")
set(tail "</body>\n</html>\n")
foreach(bad "no such file|<img src=\"there.png\"><img src=\"missing.png\">"
            "names no id|<a href=\"#nowhere\">x</a>"
            "leaves the output|<a href=\"../there.png\">x</a>"
            "leaves the output|<img src=\"https://example.org/x.png\">"
            "not a whole|<img src=\"there.png\">")
    string(REPLACE "|" ";" bad "${bad}")
    list(GET bad 0 why)
    list(GET bad 1 content)
    if(why STREQUAL "not a whole")
        file(WRITE "${WORK}/badhtml/index.html" "${head}${content}")
    else()
        file(WRITE "${WORK}/badhtml/index.html" "${head}${content}${tail}")
    endif()
    execute_process(COMMAND "${CMAKE_COMMAND}" -DHTML=${WORK}/badhtml/index.html
                            -P "${CMAKE_CURRENT_LIST_DIR}/check_html_links.cmake"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    # CMake wraps a long message at word boundaries (where depends on the paths' lengths).
    string(REGEX REPLACE "[ \n]+" " " err "${err}")
    if(code EQUAL 0 OR NOT err MATCHES "${why}")
        message(FATAL_ERROR "the HTML checker passed a page with ${content} (${code}): ${err}")
    endif()
endforeach()
file(WRITE "${WORK}/badhtml/index.html" "${head}<img src=\"there.png\">${tail}")
check_html_links("${WORK}/badhtml/index.html" ALL_IMAGES)

# --help lists every method with one line.
expect_run(0 "\nFlatland methods \\(default: all\\):\n  optimal-l1 +exact L1 optimum[^\n]*\n.*\n  split-dp +[^\n]+\n\n3D methods \\(default: all, and a case's own \"methods\", cases/README\\.md\\):\n  optimal +Algorithm 1 from every baseline's start[^\n]*\n.*\n  tsm +Martin & Tan 2004[^\n]*\n.*\n  vsm-dynamic +[^\n]+\n\n3D methods run only when named \\(--method\\):\n  optimal-refined-h +optimal-h, [^\n]+\n.*\n  optimal-oracle +bound: [^\n]+\n+$"
           "^$" run --help)
expect_run(0 "\n3D methods \\(default: all, and a case's own \"methods\", cases/README\\.md\\):\n  optimal +[^\n]+\n.*\n  optimal-report +Algorithm 1 as published[^\n]*\n.*\n  vsm +virtual shadow map[^\n]*\n  vsm-dynamic +[^\n]+\n\n3D methods run only when named \\(--method\\):\n.*\n  optimal-oracle +[^\n]+\n+$"
           "^$" sweep --help)

# Bad input: one line naming the field and the reason, exit 2, no output files.
expect_run(2 "^$" "^lexel: error: .*bad_fov.json: /camera/fov_deg: must be in \\(0, 180\\), got 190\n$"
           run "${DATA}/bad_fov.json" --out "${WORK}/bad")
expect_run(2 "^$" "bad_syntax.json:4:[0-9]+: invalid JSON" run "${DATA}/bad_syntax.json" --out "${WORK}/bad")
expect_run(2 "^$" "/camera/zoom: unknown key" run "${DATA}/unknown_key.json" --out "${WORK}/bad")
expect_run(2 "^$" "no camera pixel sees any geometry" run "${DATA}/no_visible.json" --out "${WORK}/bad")
# A camera and a second decision pass whose memory would pass the budget are refused
# before anything is allocated, with the estimate, in one line.
file(READ "${good}" goodText)
string(REPLACE "\"pixels\": 1000" "\"pixels\": 100000000" bigText "${goodText}")
string(REPLACE "\"decision_pixels\": 100" "\"decision_pixels\": 90000000" bigText "${bigText}")
file(WRITE "${WORK}/big/single_plane.json" "${bigText}")
expect_run(2 "^$" "^lexel: error: [^\n]*big/single_plane.json: /camera/pixels: needs about 8.35 GiB \\(100000000 camera pixels and 90000000 decision pixels in a second pass, [^\n]*\\), above lexel's memory budget of 8 GiB\n$"
           run "${WORK}/big/single_plane.json")
expect_run(2 "^$" "/light/position: the light lies on segment 0 of polyline 0 \\(/geometry/0/0\\)" run "${DATA}/light_on_segment.json" --out "${WORK}/bad")
expect_run(2 "^$" "no lexel plane has them all in front" run "${DATA}/wide_sweep.json" --out "${WORK}/bad")
expect_run(2 "^$" "zero-length segment" run "${DATA}/zero_segment.json" --out "${WORK}/bad")
expect_run(2 "^$" "the camera is inside the closed polyline" run "${DATA}/camera_inside.json" --out "${WORK}/bad")
expect_run(2 "^$" "/light/position/0: must be a number, got null" run "${DATA}/nan_light.json" --out "${WORK}/bad")
# A bad second case stops the run before anything is written.
expect_run(2 "^$" "fov_deg" run "${good}" "${DATA}/bad_fov.json" --out "${WORK}/bad")
expect_run(2 "" "unknown flatland method 'nope'" run "${good}" --method nope --out "${WORK}/bad")
expect_run(2 "^$" "^lexel: error: --format: xml not in \\{table,json,csv\\}\n$" run "${good}" --format xml)
expect_run(2 "^$" "^lexel: error: [^\n]*\n$" run "${WORK}/does_not_exist.json")
if(EXISTS "${WORK}/bad")
    message(FATAL_ERROR "a failed run left ${WORK}/bad behind")
endif()

# ---- Names are file stems; no output replaces another or an input ----
# A name that would leave --out, hide a NUL, or not fit a file name: exit 2, one line naming
# /name, nothing written anywhere.
file(READ "${good}" goodText)
string(REPEAT "n" 300 longName)
foreach(bad "dotdot|../escaped|contains '/'"
            "absolute|${WORK}/names/absolute_escape|contains '/'"
            "nul|a\\u0000b|contains the control character U\\+0000"
            "long|${longName}|300 bytes, at most 100")
    string(REPLACE "|" ";" bad "${bad}")
    list(GET bad 0 file)
    list(GET bad 1 name)
    list(GET bad 2 reason)
    string(REPLACE "\"single_plane\"" "\"${name}\"" text "${goodText}")
    file(WRITE "${WORK}/names/${file}.json" "${text}")
    expect_run(2 "^$" "^lexel: error: [^\n]*${file}.json: /name: not a safe file stem: ${reason}\n$"
               run "${WORK}/names/${file}.json" --method normal --out "${WORK}/names/out")
    expect_run(2 "^$" "^lexel: error: [^\n]*${file}.json: /name: not a safe file stem: ${reason}\n$"
               lowres "${WORK}/names/${file}.json" --out "${WORK}/names/out")
endforeach()
# tables with such a case among its four: refused at loading, before any figure is drawn.
foreach(f single_plane simple_geometry light_from_top projection_aliasing)
    file(COPY "${CASES}/flatland/${f}.json" DESTINATION "${WORK}/names_tables")
endforeach()
string(REPLACE "\"single_plane\"" "\"../escaped\"" text "${goodText}")
file(WRITE "${WORK}/names_tables/single_plane.json" "${text}")
expect_run(2 "^$" "^lexel: error: [^\n]*single_plane.json: /name: not a safe file stem: contains '/'\n$"
           tables --cases "${WORK}/names_tables" --out "${WORK}/names/out")
file(GLOB written "${WORK}/names/*" "${WORK}/names/out")
list(LENGTH written nWritten)
if(NOT nWritten EQUAL 4 OR EXISTS "${WORK}/names/out" OR EXISTS "${WORK}/names/escaped.json")
    message(FATAL_ERROR "a refused name wrote files: ${written}")
endif()
file(READ "${DATA}/spatial_small.json" smallText)
string(REPLACE "\"spatial_small\"" "\"../escaped3d\"" text "${smallText}")
file(WRITE "${WORK}/names/dotdot3d.json" "${text}")
expect_run(2 "^$" "^lexel: error: [^\n]*dotdot3d.json: /name: not a safe file stem: contains '/'\n$"
           run "${WORK}/names/dotdot3d.json" --out "${WORK}/names/out")
# Two cases of one name in one run would overwrite each other's reports.
file(WRITE "${WORK}/dup/copy.json" "${goodText}")
expect_run(2 "^$" "^lexel: error: --out: [^\n]*single_plane.json and [^\n]*copy.json are both named 'single_plane' \\(their outputs would overwrite each other\\)\n$"
           run "${good}" "${WORK}/dup/copy.json" --method normal --out "${WORK}/dup/out")
expect_run(0 "" "" run "${good}" "${WORK}/dup/copy.json" --method normal)  # without --out: fine
# --out in the case's own folder would replace the case file with its report.
file(WRITE "${WORK}/self/single_plane.json" "${goodText}")
file(WRITE "${WORK}/self/lowres_single_plane.md" "${goodText}")
file(WRITE "${WORK}/self/spatial_small.json" "${smallText}")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*single_plane.json would overwrite the case file [^\n]*self/single_plane.json\n$"
           run "${WORK}/self/single_plane.json" --method normal --out "${WORK}/self")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*lowres_single_plane.md would overwrite the case file [^\n]*\n$"
           lowres "${WORK}/self/lowres_single_plane.md" --out "${WORK}/self")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*spatial_small.json would overwrite the case file [^\n]*\n$"
           run "${WORK}/self/spatial_small.json" --method focused --out "${WORK}/self")
file(WRITE "${WORK}/self/sweep.json" "${smallText}")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*sweep.json would overwrite the case file [^\n]*self/sweep.json\n$"
           sweep "${WORK}/self/sweep.json" --lights 1 --method focused --out "${WORK}/self")
# index.html is an output of run and sweep too: a case file of that name is kept.
file(WRITE "${WORK}/selfhtml/flat/index.html" "${goodText}")
file(WRITE "${WORK}/selfhtml/3d/index.html" "${smallText}")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*index.html would overwrite the case file [^\n]*flat/index.html\n$"
           run "${WORK}/selfhtml/flat/index.html" --method normal --out "${WORK}/selfhtml/flat")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*index.html would overwrite the case file [^\n]*3d/index.html\n$"
           run "${WORK}/selfhtml/3d/index.html" --method focused --out "${WORK}/selfhtml/3d")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*index.html would overwrite the case file [^\n]*3d/index.html\n$"
           sweep "${WORK}/selfhtml/3d/index.html" --lights 1 --method focused --out "${WORK}/selfhtml/3d")
file(GLOB_RECURSE written "${WORK}/selfhtml/*")
if(NOT written STREQUAL "${WORK}/selfhtml/3d/index.html;${WORK}/selfhtml/flat/index.html")
    message(FATAL_ERROR "a refused --out changed ${WORK}/selfhtml: ${written}")
endif()
file(GLOB written "${WORK}/self/*")
file(READ "${WORK}/self/single_plane.json" kept)
list(LENGTH written nWritten)
if(NOT nWritten EQUAL 4 OR NOT kept STREQUAL goodText)
    message(FATAL_ERROR "a refused --out changed ${WORK}/self: ${written}")
endif()
if(EXISTS "${WORK}/dup/out")
    message(FATAL_ERROR "a refused run wrote ${WORK}/dup/out")
endif()

# ---- Never nan in any format ----
# The projection_aliasing plank without its floor: 5 and 10 decision pixels miss it, so the
# low-resolution study's extra error is undefined there: "n/a" in text, empty in lowres.csv.
file(MAKE_DIRECTORY "${WORK}/undecidable")
foreach(f single_plane simple_geometry light_from_top)
    file(COPY "${CASES}/flatland/${f}.json" DESTINATION "${WORK}/undecidable")
endforeach()
file(READ "${DATA}/lowres_undecidable.json" text)
file(WRITE "${WORK}/undecidable/projection_aliasing.json" "${text}")
expect_run(0 "\n5 +n/a +n/a +n/a\n10 +n/a +n/a +n/a\n20 " "^$"
           lowres "${WORK}/undecidable/projection_aliasing.json")
expect_run(0 "" "^$" tables --cases "${WORK}/undecidable" --out "${WORK}/undecidable/out")
file(READ "${WORK}/undecidable/out/lowres.csv" csv)
if(NOT csv MATCHES "\nprojection_aliasing,5,,,\nprojection_aliasing,10,,,\nprojection_aliasing,20,[-0-9]")
    message(FATAL_ERROR "lowres.csv: expected empty fields at K = 5 and 10:\n${csv}")
endif()
foreach(f lowres.csv tables.csv tables.md)
    file(READ "${WORK}/undecidable/out/${f}" text)
    string(TOLOWER "${text}" text)
    if(text MATCHES "(^|[^a-z])-?nan([^a-z]|$)")
        message(FATAL_ERROR "${WORK}/undecidable/out/${f} prints nan:\n${text}")
    endif()
endforeach()

# ---- Every command-line error is one line, exit 2 ----
set(oneLine "^lexel: error: [^\n]+\n$")
expect_run(2 "^$" "^lexel: error: cases: File does not exist: [^\n]*does_not_exist.json\n$"
           run "${WORK}/does_not_exist.json")
expect_run(2 "^$" "${oneLine}" run "${WORK}")  # a directory as the case
expect_run(2 "^$" "${oneLine}" sweep "${DATA}/spatial_small.json" --lights 0)
expect_run(2 "^$" "${oneLine}" timing "${DATA}/spatial_small.json" --frames 0)
expect_run(2 "^$" "^lexel: error: [^\n]*--frobnicate[^\n]*\n$" run "${good}" --frobnicate)
expect_run(2 "^$" "${oneLine}" run "${good}" --format xml)
expect_run(2 "^$" "${oneLine}" run)
expect_run(2 "^$" "${oneLine}")
expect_run(2 "^$" "${oneLine}" nope)
expect_run(0 "Case files" "^$" run --help)

# ---- A stdout that cannot be written is a failed run (exit 1, one line) ----
if(EXISTS /dev/full)
    execute_process(COMMAND "${LEXEL}" run "${good}" --method normal OUTPUT_FILE /dev/full
                    RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 1 OR NOT err STREQUAL "lexel: error: cannot write to standard output\n")
        message(FATAL_ERROR "lexel run > /dev/full: exit ${code}, stderr '${err}'")
    endif()
endif()

# ---- A run with --out leaves all its files or none ----
# A successful run leaves no staging directory (nor *.partial) beside or inside --out.
file(GLOB leftovers "${WORK}/.lexel-staging-*" "${WORK}/out/.lexel-staging-*" "${WORK}/out/*partial*")
if(leftovers)
    message(FATAL_ERROR "a successful run left ${leftovers}")
endif()
# An --out that cannot hold files is bad input, refused before anything is computed (stdout stays
# empty) and without a file written.
file(WRITE "${WORK}/outfile/plain" "x")
expect_run(2 "^$" "^lexel: error: --out: [^\n]*outfile/plain: not a directory\n$"
           lowres "${good}" --out "${WORK}/outfile/plain")
expect_run(2 "^$" "^lexel: error: --out: [^\n]*outfile/plain/sub: cannot create the directory \\(Not a directory\\)\n$"
           run "${good}" --out "${WORK}/outfile/plain/sub")
expect_run(2 "^$" "^lexel: error: --out: [^\n]*outfile/plain: not a directory\n$"
           tables --out "${WORK}/outfile/plain")
file(GLOB_RECURSE written LIST_DIRECTORIES true "${WORK}/outfile/*")
if(NOT written STREQUAL "${WORK}/outfile/plain")
    message(FATAL_ERROR "a refused --out wrote: ${written}")
endif()
# A full disk, made real by a file size limit: write(2) fails with EFBIG where a full disk fails
# with ENOSPC (root included). Before, lowres published a cut-off lowres_<case>.md and PNG under
# their final names; now the run fails (exit 1, one line), publishes nothing and keeps the old
# files of an existing --out.
file(WRITE "${WORK}/full/old/lowres_single_plane.md" "old")
foreach(dir new old)
    execute_process(COMMAND sh -c "ulimit -f 1; trap '' XFSZ; exec \"$0\" \"$@\""
                            "${LEXEL}" lowres "${good}" --out "${WORK}/full/${dir}"
                    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    if(NOT code EQUAL 1 OR NOT err MATCHES "^lexel: error: [^\n]*full/${dir}/lowres_single_plane\\.(md|png): [^\n]+\n$")
        message(FATAL_ERROR "lowres --out into a full disk: exit ${code}, stderr '${err}'")
    endif()
endforeach()
file(GLOB_RECURSE written LIST_DIRECTORIES true "${WORK}/full/*")
file(READ "${WORK}/full/old/lowres_single_plane.md" kept)
if(NOT written STREQUAL "${WORK}/full/old;${WORK}/full/old/lowres_single_plane.md" OR NOT kept STREQUAL "old")
    message(FATAL_ERROR "a run that failed to write left: ${written}")
endif()
# 3D images are written by OpenImageIO, which reports no error for a PNG cut short (it returned
# success for a 2048-byte errors.png); the check before publishing finds it.
execute_process(COMMAND sh -c "ulimit -f 4; trap '' XFSZ; exec \"$0\" \"$@\""
                        "${LEXEL}" run "${DATA}/spatial_small.json" --method focused --no-map-truth
                        --out "${WORK}/full/images"
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 1 OR NOT err MATCHES "^lexel: error: [^\n]*full/images/spatial_small_light0_focused_[a-z]+\\.png: [^\n]+\n$")
    message(FATAL_ERROR "run --out into a full disk: exit ${code}, stderr '${err}'")
endif()
file(GLOB_RECURSE written LIST_DIRECTORIES true "${WORK}/full/*")
if(NOT written STREQUAL "${WORK}/full/old;${WORK}/full/old/lowres_single_plane.md")
    message(FATAL_ERROR "a 3D run that failed to write left: ${written}")
endif()
# Eight runs at once into one --out, existing or not: none fails (before, all wrote one
# <file>.partial and 5 of 20 runs failed), and only the two files remain.
file(MAKE_DIRECTORY "${WORK}/together/existing")
foreach(dir existing absent)
    execute_process(COMMAND sh -c "pids=''; for i in 1 2 3 4 5 6 7 8; do \"$0\" lowres \"$1\" --out \"$2\" > /dev/null & pids=\"$pids $!\"; done; failed=0; for p in $pids; do wait $p || failed=$((failed + 1)); done; echo $failed"
                            "${LEXEL}" "${good}" "${WORK}/together/${dir}"
                    OUTPUT_VARIABLE failed ERROR_VARIABLE err)
    file(GLOB_RECURSE written LIST_DIRECTORIES true RELATIVE "${WORK}/together/${dir}" "${WORK}/together/${dir}/*")
    if(NOT failed STREQUAL "0\n" OR NOT err STREQUAL "" OR NOT written STREQUAL "lowres_single_plane.md;lowres_single_plane.png")
        message(FATAL_ERROR "8 concurrent runs into ${dir}: ${failed} failed: ${err}; left ${written}")
    endif()
endforeach()
file(GLOB leftovers "${WORK}/together/.lexel-staging-*")
if(leftovers)
    message(FATAL_ERROR "concurrent runs left ${leftovers}")
endif()

# ---- Fit-thesis never writes over the thesis cases it reads ----
# An installed layout in WORK (<prefix>/bin/lexel reads <prefix>/share/lexel/cases), so that the
# test cannot touch the source tree's cases/flatland even if the guard failed.
set(prefix "${WORK}/installed")
file(COPY "${LEXEL}" DESTINATION "${prefix}/bin")
file(COPY "${CASES}/published" "${CASES}/flatland" DESTINATION "${prefix}/share/lexel/cases")
get_filename_component(exeName "${LEXEL}" NAME)
set(sourceLexel "${LEXEL}")
set(LEXEL "${prefix}/bin/${exeName}")
set(shipped "${prefix}/share/lexel/cases/flatland")
file(GLOB_RECURSE casesBefore LIST_DIRECTORIES true "${shipped}/*")
file(SHA256 "${shipped}/single_plane.json" shaBefore)
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*flatland/single_plane.json would overwrite the case file [^\n]*flatland/single_plane.json\n$"
           fit-thesis --case single_plane --samples 0 --starts 0 --out "${shipped}")
expect_run(2 "^$" "^lexel: error: --out: writing [^\n]*flatland/[a-z_]+.json would overwrite the case file [^\n]*flatland/[a-z_]+.json\n$"
           fit-thesis --samples 0 --starts 0 --out "${shipped}/")
file(GLOB_RECURSE casesAfter LIST_DIRECTORIES true "${shipped}/*")
file(SHA256 "${shipped}/single_plane.json" shaAfter)
if(NOT casesAfter STREQUAL casesBefore OR NOT shaAfter STREQUAL shaBefore)
    message(FATAL_ERROR "a refused fit-thesis changed ${shipped}: ${casesAfter}")
endif()
set(LEXEL "${sourceLexel}")

# ---- 3D cases: lexel run and lexel sweep on a small floor-and-box scene ----
set(small "${DATA}/spatial_small.json")
set(methods3d optimal optimal-refined optimal-h focused-tight lispsm-tight lispsm-engine psm-tight
    plane-optimal normal optimal-report focused lispsm psm optimal-shear rtw rtw-lagrange logpsm pssm
    sdsm sdsm-snap sdsm-rect zp-lispsm fp-lispsm sdsm-optimal tsm tsm-report vsm vsm-dynamic)
set(partitioned3d pssm sdsm sdsm-snap sdsm-rect zp-lispsm fp-lispsm sdsm-optimal)

# Asserts that a JSON value is a non-negative integer (string(JSON) reads numbers as text).
function(expect_count json what)
    if(NOT json MATCHES "^[0-9]+$")
        message(FATAL_ERROR "${what}: expected an integer >= 0, got '${json}'")
    endif()
endfunction()

# The table lists every method, in the registry's order.
expect_run(0 "^light 0: point \\(8, 8, 2\\)[^\n]*\n  the report's focused 4000² truth map disagrees with the rays on [0-9]+ pixels?[^\n]*\n[^\n]*\nmethod +misclassified +shadow +light +uncovered[^\n]*\n-+\noptimal [^\n]*\noptimal-refined [^\n]*\noptimal-h [^\n]*\nfocused-tight [^\n]*\nlispsm-tight [^\n]*\nlispsm-engine [^\n]*\npsm-tight [^\n]*\nplane-optimal [^\n]*\nnormal [^\n]*\noptimal-report [^\n]*\nfocused [^\n]*\nlispsm [^\n]*\npsm [^\n]*\noptimal-shear [^\n]*\nrtw [^\n]*\nrtw-lagrange [^\n]*\nlogpsm [^\n]*\npssm [^\n]*\nsdsm [^\n]*\nsdsm-snap [^\n]*\nsdsm-rect [^\n]*\nzp-lispsm [^\n]*\nfp-lispsm [^\n]*\nsdsm-optimal [^\n]*\ntsm [^\n]*\ntsm-report [^\n]*\nvsm [^\n]*\nvsm-dynamic "
           "^$" run "${small}")
expect_run(0 "^\\{\n  \"case\": \"spatial_small\"" "^$" run "${small}" --format json)
string(JSON nLights LENGTH "${lastStdout}" lights)
string(JSON nMethods LENGTH "${lastStdout}" lights 0 methods)
string(JSON method0 GET "${lastStdout}" lights 0 methods 0 method)
string(JSON wrong0 GET "${lastStdout}" lights 0 methods 0 misclassified)
string(JSON receivers GET "${lastStdout}" lights 0 receiver_pixels)
if(NOT nLights EQUAL 1 OR NOT nMethods EQUAL 28 OR NOT method0 STREQUAL "optimal" OR receivers LESS 1)
    message(FATAL_ERROR "unexpected 3D JSON document:\n${lastStdout}")
endif()
math(EXPR last "${nMethods} - 1")
foreach(k RANGE ${last})
    string(JSON m GET "${lastStdout}" lights 0 methods ${k} method)
    list(GET methods3d ${k} want)
    string(JSON wrong GET "${lastStdout}" lights 0 methods ${k} misclassified)
    if(NOT m STREQUAL want)
        message(FATAL_ERROR "3D JSON: method ${k} is '${m}', expected '${want}'")
    endif()
    expect_count("${wrong}" "lights/0/methods/${k}/misclassified")
endforeach()
expect_run(0 "^light,method,misclassified,false_shadow,false_light,h,ms,uncovered,mean_footprint,max_footprint,maps,max_perspective_aliasing,storage_factor,pages_requested,pages_resident,pages_dropped\n0,optimal,[0-9]+,[0-9]+,[0-9]+,[^\n]*,1,[0-9.e+-]+,[0-9.e+-]+,,,\n0,normal,[^\n]*,1,[0-9.e+-]+,[0-9.e+-]+,,,\n$"
           "^$" run "${small}" --format csv --method optimal --method normal --no-map-truth)
# A virtual shadow map's maps are its resident pages, and it says how many it asked for and
# dropped (the small case's 128² budget: 64 pages of 16²).
expect_run(0 "^light,method,[^\n]*\n0,vsm,[0-9]+,[0-9]+,[0-9]+,[^\n]*,[0-9.e+-]+,[0-9]+,[0-9]+,[0-9]+\n$"
           "^$" run "${small}" --format csv --method vsm --no-map-truth)

# --out writes the report and three images per light and method (a partitioned method: a map
# image per cascade; fp-lispsm has 3 face wedges here): 21 single maps × 3 (vsm and vsm-dynamic:
# frame, errors and the page pool) + 6 × 6 + 5 = 104.
expect_run(0 "^light 0" "^lexel: wrote 104 images, index.html and spatial_small.json/.csv to [^\n]*\n$"
           run "${small}" --out "${WORK}/out3d")
# index.html shows every image and links both data files (before: 154 loose PNGs, no index).
check_html_links("${WORK}/out3d/index.html" ALL_IMAGES)
file(READ "${WORK}/out3d/index.html" page)
if(NOT htmlLinks GREATER 155 OR NOT page MATCHES "href=\"spatial_small\\.json\"" OR NOT page MATCHES "href=\"spatial_small\\.csv\""
   OR NOT page MATCHES "<h2 id=\"light0\">Light 0: point \\(8, 8, 2\\)</h2>" OR NOT page MATCHES "<dt>misclassified</dt>")
    message(FATAL_ERROR "${WORK}/out3d/index.html: ${htmlLinks} links:\n${page}")
endif()
foreach(file spatial_small.json spatial_small.csv)
    if(NOT EXISTS "${WORK}/out3d/${file}")
        message(FATAL_ERROR "missing ${WORK}/out3d/${file}")
    endif()
endforeach()
foreach(method ${methods3d})
    set(kinds frame errors map)
    if(method IN_LIST partitioned3d)
        set(kinds frame errors map0 map1 map2)
    endif()
    foreach(kind ${kinds})
        if(NOT EXISTS "${WORK}/out3d/spatial_small_light0_${method}_${kind}.png")
            message(FATAL_ERROR "missing ${WORK}/out3d/spatial_small_light0_${method}_${kind}.png")
        endif()
    endforeach()
endforeach()
file(GLOB leftovers "${WORK}/out3d/*partial*")
if(leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
endif()
file(READ "${WORK}/out3d/spatial_small.json" written)
string(JSON method0 GET "${written}" lights 0 methods 0 method)
if(NOT method0 STREQUAL "optimal")
    message(FATAL_ERROR "unexpected ${WORK}/out3d/spatial_small.json:\n${written}")
endif()

# Progress on a terminal (before: lexel run on a 3D case was silent for 30-40 s): `script` gives
# lexel a pseudo-terminal; the bar appears at once with "estimating" and ends with every step
# done. Without a terminal (every other test here) stderr stays empty.
find_program(SCRIPT_PROGRAM script)
if(SCRIPT_PROGRAM)
    foreach(command "run;run spatial_small;2/2 steps"
                    "timing;timing;3/3 frames")
        list(GET command 0 subcommand)
        list(GET command 1 label)
        list(GET command 2 done)
        if(subcommand STREQUAL "run")
            set(args "--method optimal --method focused --no-map-truth")
        else()
            set(args "--frames 2 --lights 1")
        endif()
        execute_process(COMMAND "${SCRIPT_PROGRAM}" -qec "'${LEXEL}' ${subcommand} '${small}' ${args} > /dev/null" /dev/null
                        RESULT_VARIABLE code OUTPUT_VARIABLE tty ERROR_VARIABLE err)
        if(NOT code EQUAL 0 OR NOT tty MATCHES "${label} \\[\\.+\\] 0/[0-9]+ [a-z]+, 0 s elapsed, estimating the time left"
           OR NOT tty MATCHES "${label} \\[#+\\] ${done}, [0-9]+ s elapsed")
            message(FATAL_ERROR "lexel ${subcommand} on a terminal: exit ${code}, no progress bar:\n${tty}${err}")
        endif()
    endforeach()
endif()

# The camera-path study kept its evaluator past the pose's scene it referenced (before: with one
# method the walkthrough's hysteresis re-render read a destroyed scene and asked for a map of
# garbage size: "cannot create std::vector larger than max_size()").
expect_run(0 "\ncamera path, light 1: P changed in 2 of 8 poses [^\n]*\n" "^$"
           run "${CASES}/spatial/walkthrough.json" --method optimal --no-map-truth)

# lexel sweep: Table 1 as published and the fair comparison, as JSON, Markdown, CSV and text.
set(reportMethods optimal-report focused lispsm plane-optimal normal psm tsm-report)
set(fairMethods optimal optimal-refined optimal-h focused-tight lispsm-tight lispsm-engine psm-tight
    plane-optimal normal optimal-shear rtw rtw-lagrange logpsm tsm)
expect_run(0 "^\\{\n  \"case\": \"spatial_small\"" "^$" sweep "${small}" --lights 3 --format json)
string(JSON sweepCase GET "${lastStdout}" case)
string(JSON sweepLights GET "${lastStdout}" lights)
string(JSON reference GET "${lastStdout}" report_table reference)
string(JSON nWorst LENGTH "${lastStdout}" report_table worst_10_percent)
if(NOT sweepCase STREQUAL "spatial_small" OR NOT sweepLights EQUAL 3 OR NOT nWorst EQUAL 0
   OR NOT reference STREQUAL "optimal-report")
    message(FATAL_ERROR "unexpected sweep JSON document:\n${lastStdout}")
endif()
foreach(table report fair)
    string(JSON n LENGTH "${lastStdout}" ${table}_table methods)
    math(EXPR last "${n} - 1")
    foreach(k RANGE ${last})
        string(JSON m GET "${lastStdout}" ${table}_table methods ${k} method)
        list(GET ${table}Methods ${k} want)
        if(NOT m STREQUAL want)
            message(FATAL_ERROR "sweep JSON: ${table} method ${k} is '${m}', expected '${want}'")
        endif()
        foreach(key mean_misclassified mean_h mean_ms percent_lights_beating_reference)
            string(JSON type TYPE "${lastStdout}" ${table}_table methods ${k} ${key})
            string(JSON value GET "${lastStdout}" ${table}_table methods ${k} ${key})
            if(NOT type STREQUAL "NUMBER" OR value LESS 0)
                message(FATAL_ERROR "sweep JSON: ${table}_table/methods/${k}/${key} is ${type} '${value}'")
            endif()
        endforeach()
    endforeach()
endforeach()
# Worst-10% rows only from 20 lights (below, 10% is one or two lights).
expect_run(0 "^\\{\n  \"case\": \"spatial_small\"" "^$" sweep "${small}" --lights 20 --format json
           --methods optimal-report --methods focused)
string(JSON nWorst LENGTH "${lastStdout}" report_table worst_10_percent)
string(JSON ranked GET "${lastStdout}" report_table worst_10_percent 1 ranked_by)
if(NOT nWorst EQUAL 2 OR NOT ranked STREQUAL "focused")
    message(FATAL_ERROR "sweep JSON: worst_10_percent: ${nWorst} rows, the second ranked by '${ranked}'")
endif()
expect_run(0 "\nworst 10% by optimal-report [^\n]*\n  published \\(report\\) +304839 \\(0\\) +403529 \\(\\+32\\.37%\\)\nworst 10% by focused "
           "^$" sweep "${small}" --lights 20 --methods optimal-report --methods focused)
# The Markdown says what each table is; the report's published rows are labelled as its own
# counts.
expect_run(0 "^## Table 1 as published [^\n]*spatial_small, 3 point lights[^\n]*\n\nThe report's experiment [^\n]*\n\n\\| lights \\| optimal-report \\| focused \\| lispsm \\| plane-optimal \\| normal \\| psm \\| tsm-report \\|\n.*\\|   published \\(report\\) \\| 1886057 \\(0\\) \\|.*\nRows \"published \\(report\\)\" are the report's own Table 1 as printed: absolute counts summed over its 500 lights[^\n]*\n\nNo worst-10% rows: they need at least 20 lights \\(this sweep has 3[^\n]*\n.*## The fair comparison [^\n]*\n\nEvery method gets [^\n]*\n\n\\| method \\|"
           "^$" sweep "${small}" --lights 3 --format markdown)
expect_run(0 "^table,set,method,mean_misclassified,percent_more,percent_lights_beating_reference,mean_h,mean_ms,report_percent_more,mean_footprint,max_footprint,mean_uncovered_pixels,empty_partitions,median_storage_factor,max_storage_factor,mean_misclassified_ci95,percent_more_ci95,percent_lights_reference_beats,phases\nreport,all,optimal-report,[0-9.]+,0,.*\nfair,all,optimal,[0-9.]+,0,"
           "^$" sweep "${small}" --lights 3 --format csv)
expect_run(0 "^Table 1 as published .*\nThe fair comparison .*\nsweep: [0-9.]+ s for 3 lights\n$" "^$"
           sweep "${small}" --lights 3)
# Adaptive phases: from 2 phases, a mean is raised up to 16 where its residual is above
# 2%; lights.csv says at how many each mean is, the note how many were raised; the most below K
# is refused.
expect_run(0 "mean over 2 sub-texel phases of its map\\(s\\), raised \\(doubling, up to 16\\) where its[ \n]+standard[ \n]+error[ \n]+was[ \n]+above"
           "^lexel: wrote " sweep "${small}" --lights 3 --phases 2 --max-phases 16
           --methods focused-tight --methods normal --out "${WORK}/adaptive")
file(STRINGS "${WORK}/adaptive/lights.csv" adaptiveRows)
list(GET adaptiveRows 0 adaptiveHeader)
if(NOT adaptiveHeader MATCHES ",focused-tight_misclassified_se,focused-tight_phases,")
    message(FATAL_ERROR "--max-phases: lights.csv has no focused-tight_phases column: ${adaptiveHeader}")
endif()
expect_run(2 "^$" "^lexel: error: --max-phases: must be at least the phases \\(16\\), got 8\n$"
           sweep "${small}" --lights 1 --phases 16 --max-phases 8)
# A case's max_phases below --phases: the error names the flag given and the field it meets.
string(REPLACE "\"light_sweep\"" "\"max_phases\": 8, \"light_sweep\"" cappedText "${smallText}")
file(WRITE "${WORK}/capped.json" "${cappedText}")
expect_run(2 "^$" "^lexel: error: --phases: 16 is above the case's max_phases \\(8\\); give --max-phases too\n$"
           sweep "${WORK}/capped.json" --lights 1 --phases 16)
# Directional lights from the same hemisphere directions.
expect_run(0 "spatial_small, 2[ \n]+directional lights" "^$"
           sweep "${small}" --lights 2 --light-type directional --methods optimal --methods focused-tight)

# --out writes four files; --methods restricts the columns; the count defaults to the case's.
expect_run(0 "^Table 1 as published [^\n]*spatial_small, 4 point lights; in[ \n]+parentheses: % more than focused"
           "^lexel: wrote index.html, table1.md, table1.csv, sweep.json, lights.csv, sweep-record.json to [^\n]*\n$"
           sweep "${small}" --methods focused --methods normal --out "${WORK}/sweep")
check_html_links("${WORK}/sweep/index.html")
file(READ "${WORK}/sweep/index.html" page)
if(NOT page MATCHES "<h2 id=\"table0\">Table 1 as published" OR NOT page MATCHES "href=\"lights\\.csv\"")
    message(FATAL_ERROR "${WORK}/sweep/index.html:\n${page}")
endif()
foreach(file table1.md table1.csv sweep.json lights.csv)
    if(NOT EXISTS "${WORK}/sweep/${file}")
        message(FATAL_ERROR "missing ${WORK}/sweep/${file}")
    endif()
endforeach()
file(READ "${WORK}/sweep/sweep.json" written)
string(JSON sweepLights GET "${written}" lights)
string(JSON nMethods LENGTH "${written}" report_table methods)
string(JSON method0 GET "${written}" report_table methods 0 method)
string(JSON method1 GET "${written}" report_table methods 1 method)
string(JSON fair0 GET "${written}" fair_table methods 0 method)
if(NOT sweepLights EQUAL 4 OR NOT nMethods EQUAL 2 OR NOT method0 STREQUAL "focused"
   OR NOT method1 STREQUAL "normal" OR NOT fair0 STREQUAL "normal")
    message(FATAL_ERROR "unexpected ${WORK}/sweep/sweep.json:\n${written}")
endif()
file(STRINGS "${WORK}/sweep/lights.csv" rows)
list(LENGTH rows nRows)
list(GET rows 0 header)
if(NOT nRows EQUAL 5 OR NOT header STREQUAL
   "light,kind,x,y,z,receiver_pixels,focused_misclassified,focused_h,focused_e,focused_ms,focused_storage_factor,focused_storage_factor_p99,normal_misclassified,normal_h,normal_e,normal_ms,normal_storage_factor,normal_storage_factor_p99")
    message(FATAL_ERROR "unexpected ${WORK}/sweep/lights.csv:\n${rows}")
endif()
# --shimmer-poses: each light's shimmer along the case's camera_path, one column per method, its
# summary in the JSON; the case must have that many poses.
file(READ "${small}" smallText)
string(JSON walking SET "${smallText}" camera_path
       "[{\"position\": [0, 3, -9], \"target\": [0, 0.5, 0]}, {\"position\": [0, 3, -8.5], \"target\": [0, 0.5, 0.5]}]")
file(WRITE "${WORK}/small_walking.json" "${walking}")
expect_run(0 "\"mean_shimmer\": [0-9.e-]+" "^lexel: wrote "
           sweep "${WORK}/small_walking.json" --lights 2 --methods focused --methods tsm
           --shimmer-poses 2 --format json --out "${WORK}/sweep_shimmer")
file(STRINGS "${WORK}/sweep_shimmer/lights.csv" rows)
list(GET rows 0 header)
if(NOT header MATCHES ",focused_shimmer,.*,tsm_shimmer(,|$)")
    message(FATAL_ERROR "lights.csv with --shimmer-poses: ${header}")
endif()
# Shards of one walk merge with their shimmer; a shard of another walk (no shimmer) is refused.
foreach(k 0 1)
    expect_run(0 "" "" sweep "${WORK}/small_walking.json" --lights 2 --methods focused
               --methods tsm --shimmer-poses 2 --shard ${k}/2 --out "${WORK}/walk_shard${k}")
endforeach()
expect_run(0 "" "" merge "${WORK}/walk_shard0" "${WORK}/walk_shard1" --out "${WORK}/walk_merged")
# The merged lights.csv holds the whole sweep's shimmer, light for light.
file(STRINGS "${WORK}/sweep_shimmer/lights.csv" whole)
file(STRINGS "${WORK}/walk_merged/lights.csv" merged)
list(GET whole 0 header)
string(REPLACE "," ";" columns "${header}")
list(FIND columns focused_shimmer at)
foreach(l 1 2)
    list(GET whole ${l} a)
    list(GET merged ${l} b)
    string(REPLACE "," ";" a "${a}")
    string(REPLACE "," ";" b "${b}")
    list(GET a ${at} shimmerWhole)
    list(GET b ${at} shimmerMerged)
    if(at EQUAL -1 OR NOT shimmerWhole STREQUAL shimmerMerged)
        message(FATAL_ERROR "light ${l}: shimmer ${shimmerMerged} merged, ${shimmerWhole} whole")
    endif()
endforeach()
expect_run(0 "" "" sweep "${WORK}/small_walking.json" --lights 2 --methods focused
           --methods tsm --shard 1/2 --out "${WORK}/still_shard1")
expect_run(2 "^$" "they differ in shimmer poses \\('2' vs '0'\\)"
           merge "${WORK}/walk_shard0" "${WORK}/still_shard1" --out "${WORK}/refused_walk")
expect_run(2 "^$" "^lexel: error: --shimmer-poses: 3 poses, but the case's camera_path has 2\n$"
           sweep "${WORK}/small_walking.json" --lights 2 --methods focused --shimmer-poses 3)
expect_run(2 "^$" "^lexel: error: --shimmer-poses: 2 poses, but the case's camera_path has 0\n$"
           sweep "${small}" --lights 2 --methods focused --shimmer-poses 2)
# Each pose keeps its frame: 16 of 4000² exceed the memory budget, refused before any is made.
set(poses "")
foreach(k RANGE 15)
    string(APPEND poses "${comma}{\"position\": [0, 3, -9.${k}], \"target\": [0, 0.5, 0]}")
    set(comma ", ")
endforeach()
string(JSON bigWalk SET "${smallText}" camera_path "[${poses}]")
string(JSON bigWalk SET "${bigWalk}" camera width 4000)
string(JSON bigWalk SET "${bigWalk}" camera height 4000)
file(WRITE "${WORK}/big_walk.json" "${bigWalk}")
expect_run(2 "^$" "^lexel: error: --shimmer-poses: the sweep needs about [0-9.]+ GiB \\(16 camera_path frames besides the camera's, one light in flight\\), above lexel's memory budget of 8 GiB\n$"
           sweep "${WORK}/big_walk.json" --lights 2 --methods focused --shimmer-poses 16)
expect_run(2 "^$" "--shimmer-poses: Value 1 not in range 2 to 16"
           sweep "${small}" --lights 2 --methods focused --shimmer-poses 1)
file(READ "${WORK}/sweep/table1.csv" written)
if(NOT written MATCHES "^table,set,method,[^\n]*\nreport,all,focused,[^\n]*\nreport,all,normal,[^\n]*\nfair,all,normal,[^\n]*\n$")
    message(FATAL_ERROR "unexpected ${WORK}/sweep/table1.csv:\n${written}")
endif()
expect_run(0 "\"method\": \"psm\"" "^$" sweep "${small}" --lights 2 --method psm --format json)

# Partitioned methods: the equal-texel table; --out adds the cascade-count study (k = 1, 2, 4, 8)
# as CSV and a plot, and the first light's images with one map per cascade.
expect_run(0 "\nEqual texels [^\n]*\n  spatial_small, 3 point lights; ref = optimal\n[^\n]*\n[^\n]*\nmethod +maps +\\(95% CI\\) +\\(95% CI\\)[^\n]*\n-+\noptimal +1 [^\n]*\nsdsm +2 [^\n]*\nsdsm-optimal +2 "
           "^lexel: wrote index.html, table1.md, table1.csv, sweep.json, lights.csv, sweep-record.json, cascades.csv, cascades.png and 8 images of the first light to [^\n]*\n$"
           sweep "${small}" --lights 3 --methods optimal --methods sdsm --methods sdsm-optimal
           --cascades 2 --out "${WORK}/cascades")
foreach(file cascades.csv cascades.png spatial_small_light0_sdsm_map1.png)
    if(NOT EXISTS "${WORK}/cascades/${file}")
        message(FATAL_ERROR "missing ${WORK}/cascades/${file}")
    endif()
endforeach()
check_html_links("${WORK}/cascades/index.html" ALL_IMAGES)
file(STRINGS "${WORK}/cascades/cascades.csv" rows)
list(LENGTH rows nRows)
list(GET rows 0 header)
if(NOT nRows EQUAL 10 OR NOT header STREQUAL "method,k,mean_misclassified")
    message(FATAL_ERROR "unexpected ${WORK}/cascades/cascades.csv:\n${rows}")
endif()
file(READ "${WORK}/cascades/sweep.json" written)
string(JSON maps GET "${written}" equal_texel_table methods 1 maps)
string(JSON empty GET "${written}" equal_texel_table methods 1 empty_partitions)
if(NOT maps EQUAL 2 OR NOT empty EQUAL 0)
    message(FATAL_ERROR "unexpected equal_texel_table in ${WORK}/cascades/sweep.json:\n${written}")
endif()
expect_run(2 "^$" "--cascades" sweep "${small}" --cascades 17 --out "${WORK}/bad3d")

# Unknown methods, for run and sweep: exit 2 naming the method, nothing written.
expect_run(2 "^$" "^lexel: error: [^\n]*unknown 3D method 'nope'[^\n]*\n$"
           sweep "${small}" --methods focused --methods nope --out "${WORK}/bad3d")
expect_run(2 "^$" "^lexel: error: [^\n]*unknown 3D method 'nope'[^\n]*\n$"
           run "${small}" --method nope --out "${WORK}/bad3d")
expect_run(2 "^$" "^lexel: error: --format: xml not in [^\n]*\n$" sweep "${small}" --format xml --out "${WORK}/bad3d")
expect_run(2 "^$" "^lexel: error: --lights: Value 0 not in range 1 to 100000\n$" sweep "${small}" --lights 0 --out "${WORK}/bad3d")
expect_run(2 "^$" "^lexel: error: run: give one 3D case at a time \\(got 2 files\\)\n$"
           run "${small}" "${small}" --out "${WORK}/bad3d")
expect_run(2 "^$" "^lexel: error: [^\n]*single_plane.json: this is a flatland case[^\n]*\n$"
           sweep "${good}" --out "${WORK}/bad3d")

# Bad 3D input: exit 2, nothing on stdout, one line on stderr naming the file, the JSON pointer
# and the reason, and no --out directory. Each case runs through `run` and `sweep` (ARGN: extra
# arguments, e.g. the subcommand when only one applies).
function(expect_bad3d file stderrRegex)
    set(subcommands ${ARGN})
    if(NOT subcommands)
        set(subcommands run sweep)
    endif()
    foreach(sub ${subcommands})
        expect_run(2 "^$" "^lexel: error: ${stderrRegex}\n$" ${sub} "${DATA}/${file}" --out "${WORK}/bad3d")
        if(EXISTS "${WORK}/bad3d")
            message(FATAL_ERROR "lexel ${sub} ${file} left ${WORK}/bad3d behind")
        endif()
    endforeach()
endfunction()
set(any "[^\n]*")
expect_bad3d(spatial_bad_syntax.json
             "${any}spatial_bad_syntax.json:6:[0-9]+: invalid JSON: syntax error${any}")
expect_bad3d(spatial_unknown_key.json
             "${any}spatial_unknown_key.json: /camera/zoom: unknown key \\(allowed here: position, target${any}")
expect_bad3d(spatial_null_light.json
             "${any}spatial_null_light.json: /lights/0/position/1: must be a number, got null")
expect_bad3d(spatial_nan_light.json
             "${any}spatial_nan_light.json:5:[0-9]+: invalid JSON: ${any}invalid literal${any}")
expect_bad3d(spatial_light_inside.json
             "${any}spatial_light_inside.json: /lights/1/position: point light \\[1, 1, 1\\] is inside the geometry's bounds \\[-10, 0, -10\\] \\.\\. \\[10, 2, 10\\]${any}")
expect_bad3d(spatial_zero_scale.json
             "${any}spatial_zero_scale.json: /geometry/1/transform/scale: must be in \\(0, inf\\), got 0")
expect_bad3d(spatial_empty_geometry.json
             "${any}spatial_empty_geometry.json: /geometry: the scene has no geometry${any}")
expect_bad3d(spatial_missing_mesh.json
             "${any}spatial_missing_mesh.json: /geometry/1/mesh: ${any}models/does_not_exist.obj: mesh file not found")
expect_bad3d(spatial_invalid_mesh.json
             "${any}spatial_invalid_mesh.json: /geometry/1/mesh: /usr/share/assimp/models/invalid/empty.obj: cannot read mesh: ${any}")
# Found only once the camera is rendered; the message names the file and the camera.
expect_bad3d(spatial_no_visible.json
             "${any}spatial_no_visible.json: /camera: no geometry is visible${any}")
# A camera_path pose that sees nothing: the message names the pose.
expect_bad3d(spatial_path_no_visible.json
             "${any}spatial_path_no_visible.json: /camera_path/1: no geometry is visible${any}" run)
# run needs fixed lights, sweep needs a light_sweep: each points to the other.
expect_bad3d(spatial_sweep_only.json
             "${any}spatial_sweep_only.json: /lights: the case has no fixed lights; run `lexel sweep`${any}" run)
expect_bad3d(spatial_no_sweep.json
             "${any}spatial_no_sweep.json: /light_sweep: the case has none${any}" sweep)
# Out-of-range 3D scenes name the field and the real reason.
expect_bad3d(spatial_scale_overflow.json
             "${any}spatial_scale_overflow.json: /geometry/1/transform: the transformed geometry reaches \\|x\\| = 5e\\+299, coordinates must be at most 1e\\+15")
expect_bad3d(spatial_depth_range.json
             "${any}spatial_depth_range.json: /camera/far: far \\(1e\\+300\\) must be at most 100000 × near \\(1e-300\\): beyond that a depth buffer's step at far exceeds 0\\.6% of the distance")
# The box stands on the floor: its bottom and the floor share a plane, so each entry is tested alone.
expect_bad3d(spatial_camera_in_box.json
             "${any}spatial_camera_in_box.json: /camera/position: the camera \\[0, 2, -1\\] is inside closed geometry \\(/geometry/1; rays from it cross that surface an odd number of times in every direction tried\\); no light outside can reach what it sees")
# Found once the camera is rendered, before any method runs: a fixed light in the floor's plane.
expect_bad3d(spatial_light_in_floor.json
             "${any}spatial_light_in_floor.json: /lights/0/position: no visible pixel faces the light: all [0-9]+ pixels the camera sees have n·l <= 0 \\(the light lies in the plane of, or behind, every surface in view\\), so every count and h would be 0" run)
# Flatland coordinates beyond the bounds, not "zero-length segment".
expect_run(2 "^$" "^lexel: error: ${any}flat_huge_coordinate.json: /geometry/0/0: coordinate too large: \\|x\\| = 1e\\+200, must be at most 1e\\+15\n$"
           run "${DATA}/flat_huge_coordinate.json" --out "${WORK}/bad")
expect_run(2 "^$" "^lexel: error: ${any}flat_tiny_scene.json: /geometry: the scene is too small: its size \\(the largest distance from the camera to the light or a geometry point\\) is 4\\.0078e-299, must be at least 1e-15\n$"
           lowres "${DATA}/flat_tiny_scene.json")
# The mirror cases work.
expect_run(0 "^The fair comparison [^\n]*\n  spatial_sweep_only, 2 point lights; ref = optimal\n" "^$"
           sweep "${DATA}/spatial_sweep_only.json" --lights 2 --method optimal)
expect_run(0 "^light 0: point \\(8, 8, 2\\)" "^$" run "${DATA}/spatial_no_sweep.json" --method optimal --no-map-truth)

# Real Assimp meshes end to end (OBJ and STL from Debian's assimp-testmodels).
expect_run(0 "^light 0: point \\(12, 25, -8\\)[^\n]*\n[^\n]*\nmethod +misclassified +shadow[^\n]*\n-+\nfocused +[0-9]+ [^\n]*\n\nlight 1: directional"
           "^$" run "${CASES}/spatial/meshes.json" --no-map-truth --method focused)

# lowres on a shipped case.
expect_run(0 "decision pixels K.*\n *5 .*\n *10 " "" lowres "${good}")

# fit-thesis: refine the committed single-plane fit (no random starts) into a fresh directory.
expect_run(0 "Single Plane Geometry .*fitted: worst angle error [0-9.]+°, worst footprint error [0-9.]+% \\(tolerances 2°, 10%\\): met"
           "^$" fit-thesis --case single_plane --samples 0 --starts 0 --out "${WORK}/fitted")
foreach(f single_plane.json parameters.json)
    if(NOT EXISTS "${WORK}/fitted/${f}")
        message(FATAL_ERROR "fit-thesis did not write ${WORK}/fitted/${f}")
    endif()
endforeach()
expect_run(0 "optimal-l1" "^$" run "${WORK}/fitted/single_plane.json" --method optimal-l1)
expect_run(2 "^$" "^lexel: error: --case: unknown thesis case 'nope' \\(known: single_plane, simple_geometry, light_from_top, projection_aliasing\\)\n$"
           fit-thesis --case nope --out "${WORK}/fitted_bad")
# tables: the fitted scenes, and how far each is from its published table.
expect_run(0 "^Single Plane Geometry \\(fitted scene fitted/single_plane.json, 1000 visible pixels, 1028 lexels; against the published\n  table: worst angle error 0.19°, worst footprint error 1.2%\\)"
           "^$" tables --out "${WORK}/tables")
message(STATUS "cli tests passed")

# --metric chooses the flatland objective; a 3D case says so instead of ignoring it.
expect_run(2 "^$" "^lexel: error: --metric: 3D cases are measured by the report's h .*\n$"
           run "${DATA}/spatial_small.json" --metric l2)
# Errors found after loading name the case file and the JSON pointer.
expect_run(2 "^$" "spatial_path_no_visible.json: /camera_path/1: no geometry is visible"
           run "${DATA}/spatial_path_no_visible.json")

# lexel timing on the CPU backend (the GL backend: cli_gl_test.cmake): per frame and mean rows,
# the report's Table 3 beside ours, JSON with every column.
expect_run(0 "focused 0[^\n]*\n(.*\n)?focused mean[^\n]*\n(.*\n)?optimal mean[^\n]*\n\nframe time optimal/focused: [0-9.]+ \\(ours, 2 lights\\); report Table 3: 1.353[^\n]*(\n  )?Table 2[ \n]+\\(2[ \n]+lights\\):[ \n]+1.130 at 500"
           "^$" timing "${DATA}/spatial_small.json" --lights 2 --frames 2)
expect_run(0 "^\\{" "^$" timing "${DATA}/spatial_small.json" --lights 5 --frames 3 --update-every 3
           --format json)
string(JSON timingLights LENGTH "${lastStdout}" lights)
string(JSON timingFrames LENGTH "${lastStdout}" optimal frames)
string(JSON search1 GET "${lastStdout}" optimal frames 1 search)
string(JSON table3 GET "${lastStdout}" table3 total report_optimal)
if(NOT timingLights EQUAL 5 OR NOT timingFrames EQUAL 3 OR NOT search1 EQUAL 0 OR NOT table3 EQUAL 56)
    message(FATAL_ERROR "unexpected timing JSON:\n${lastStdout}")
endif()
expect_run(0 "^method,frame,total_ms,camera_pass_ms,readback_ms,extraction_ms,hull_ms,search_ms,shadow_map_ms,shading_ms\nfocused,0,[^\n]*\nfocused,mean,[^\n]*\noptimal,0,[^\n]*\noptimal,mean,"
           "^$" timing "${DATA}/spatial_small.json" --lights 1 --frames 1 --format csv)
expect_run(2 "^$" "^lexel: error: [^\n]*spatial_no_sweep.json: /lights: --lights 2 needs 2 lights; the case has 1 and no light_sweep\n$"
           timing "${DATA}/spatial_no_sweep.json" --lights 2)
# --backend: cpu or gl, 3D cases only.
expect_run(2 "^$" "^lexel: error: --backend: vulkan not in \\{cpu,gl\\}\n$" run "${DATA}/spatial_small.json" --backend vulkan)
expect_run(2 "^$" "^lexel: error: --backend: flatland cases have no renderer; --backend applies to 3D cases\n$"
           run "${good}" --backend gl)
expect_run(0 "^lexel [0-9.]+\ncpu \\([0-9]+ threads\\)\ngl: " "^$" info)

# ---- lexel storage: Lloyd et al. 2006's storage factor ----
# The default frustum is Fig. 12's (60°, f/n = 1000): S̄_opt 5.98, ZP + W overhead 865, 53.0, 16.0,
# 9.5 for 1, 2, 4, 8 maps; Figs. 5–6's S̄ = 85.74 from PSM to LiSPSM at f/n = 100.
expect_run(0 "^Lloyd et al. 2006's storage factor[^\n]*\n  fov_y 60°, aspect 1, n 1, f 1000 \\(f/n = 1000\\)\nS̄_opt = [^\n]* = 5.98229 .*\n *0.00 +16.454[0-9]* +85.736[0-9]* .*\nFig. 12:[^\n]*\n[^\n]*\n-+\n *1 +865159 +865.159 .*\n *8 +22.53[0-9]* +9.50[0-9]* "
           "^$" storage)
expect_run(0 "^\\{" "^$" storage --fov-y 60 --near 1 --far 100 --format json)
string(JSON optimal GET "${lastStdout}" optimal)
string(JSON hemispheres LENGTH "${lastStdout}" hemisphere)
string(JSON warpRatio GET "${lastStdout}" warp 1 depth_ratio)
if(NOT optimal MATCHES "^3\\.98819[0-9]*" OR NOT hemispheres EQUAL 3 OR NOT warpRatio MATCHES "^100(\\.0)?$")
    message(FATAL_ERROR "unexpected storage JSON:\n${lastStdout}")
endif()
expect_run(0 "^figure,series,x1,x2,value\nfig5_6,warp,-1,20,[^\n]*\n(.*\n)?fig12,ZP \\+ W overhead,4,,16.0159[0-9]*\n(.*\n)?fig13,vertex rule,4,1,"
           "^$" storage --format csv)
expect_run(0 "" "wrote storage.json, storage.csv and 7 figures" storage --far 100 --out "${WORK}/storage")
foreach(f storage.json storage.csv fig5_6_warp.png fig7_hemisphere_no_warp.png
        fig7_hemisphere_lispsm.png fig7_hemisphere_fp_w.png fig10_partitions.png fig12_maps.png
        fig13_crossover.png)
    if(NOT EXISTS "${WORK}/storage/${f}")
        message(FATAL_ERROR "lexel storage --out did not write ${f}")
    endif()
endforeach()
# Bad flags: one line naming the flag, exit 2, nothing written.
expect_run(2 "^$" "^lexel: error: --far: must be 1\\.000001 to 1e\\+06 times --near \\(1\\), got 0\\.5 \\(0\\.5 times\\)\n$"
           storage --far 0.5 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --fov-y: must be in \\[0\\.1, 179\\] degrees, got 180\n$"
           storage --fov-y 180 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --aspect: must be in \\[0\\.01, 100\\], got 0\n$"
           storage --aspect 0 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --near: must be in \\[1e-06, 1e\\+09\\], got -1\n$"
           storage --near -1 --out "${WORK}/storage_bad")
expect_run(2 "^$" "" storage --format xml --out "${WORK}/storage_bad")
expect_run(2 "^$" "--far excludes --case" storage --case "${small}" --far 10)
expect_run(2 "^$" "^lexel: error: --method: applies with --case" storage --method focused)
if(EXISTS "${WORK}/storage_bad")
    message(FATAL_ERROR "a failed lexel storage left ${WORK}/storage_bad behind")
endif()
# Measured beside analytic on a case: each method's storage factor and its scheme's S̄.
expect_run(0 "^Measured storage factor beside[^\n]*spatial_small:\n  camera fov_y 60°, aspect 1.33333, n 0.1, f 50 \\(f/n = 500\\)\n  visible planar depths [^\n]*\n  partitioned methods k = 4\nlight 0: point \\(8, 8, 2\\), γ = [0-9.]+°[^\n]*\nS̄_opt 5.382 \\(camera\\)[^\n]*\n[^\n]*\n[^\n]*\n[^\n]*\n-+\nfocused +1 +[0-9.e+]+ +[0-9.e+]+ +[0-9.e+]+ +no warp +[0-9.e+]+ .*\nlispsm +1 [^\n]* LiSPSM .*\nzp-lispsm +4 [^\n]* ZP \\+ W \\(k = 4\\) "
           "^$" storage --case "${small}" --method focused --method lispsm --method zp-lispsm)
expect_run(0 "^light,method,maps,texels,max_perspective_aliasing,storage_factor,storage_factor_p99,scheme,scheme_storage_camera,scheme_storage_visible,optimal_camera,optimal_visible\n0,optimal,1,16384,[^\n]*,best single map,"
           "^$" storage --case "${small}" --method optimal --format csv)

# Only regular files are read as cases: /dev/zero would be read without end (exit 2, one line).
expect_run(2 "^$" "^lexel: error: /dev/zero: not a regular file \\(a case is a JSON file\\)\n$"
           run /dev/zero --out "${WORK}/bad_dev")
expect_run(2 "^$" "^lexel: error: /dev/zero: not a regular file \\(a case is a JSON file\\)\n$"
           sweep /dev/zero --out "${WORK}/bad_dev")
if(EXISTS "${WORK}/bad_dev")
    message(FATAL_ERROR "a refused /dev/zero left ${WORK}/bad_dev behind")
endif()

# A number that overflows a double names its line, column and JSON pointer.
file(WRITE "${WORK}/overflow/overflow.json" "{\"name\": \"x\",\n \"camera\": {\"position\": [0, 1e400]}}")
expect_run(2 "^$" "^lexel: error: [^\n]*overflow.json:2:29: /camera/position/1: number 1e400 does not fit a double \\(numbers must be finite\\)\n$"
           run "${WORK}/overflow/overflow.json" --out "${WORK}/overflow/out")
# A 3D case whose sizes need more than the 8 GiB budget is refused before anything is allocated,
# naming the field whose size needs the most and the estimate.
string(REPLACE "\"width\": 160, \"height\": 120" "\"width\": 16384, \"height\": 16384" text "${smallText}")
file(WRITE "${WORK}/memory/camera.json" "${text}")
expect_run(2 "^$" "^lexel: error: [^\n]*camera.json: /camera: the case needs about [0-9.]+ GiB \\(camera 16384x16384, readback 64x64, shadow map 128x128\\), above lexel's memory budget of 8 GiB\n$"
           run "${WORK}/memory/camera.json" --out "${WORK}/memory/out")
string(REPLACE "\"shadow_map\": {\"width\": 128, \"height\": 128}" "\"shadow_map\": {\"width\": 16384, \"height\": 16384}" text "${smallText}")
file(WRITE "${WORK}/memory/map.json" "${text}")
expect_run(2 "^$" "^lexel: error: [^\n]*map.json: /shadow_map: the case needs about [0-9.]+ GiB "
           sweep "${WORK}/memory/map.json" --out "${WORK}/memory/out")
# Assimp's own invalid/OutOfMemory.off (3.5e11 vertices declared in 309 bytes) as a mesh.
string(REPLACE "{\"primitive\": \"box\"" "{\"mesh\": \"/usr/share/assimp/models/invalid/OutOfMemory.off\"" text "${smallText}")
file(WRITE "${WORK}/memory/oom_mesh.json" "${text}")
expect_run(2 "^$" "^lexel: error: [^\n]*oom_mesh.json: /geometry/1/mesh: /usr/share/assimp/models/invalid/OutOfMemory.off: declares 353535235358 vertices and 6 faces, more than its 309 bytes can hold \\(a truncated or corrupt file\\)\n$"
           run "${WORK}/memory/oom_mesh.json" --out "${WORK}/memory/out")
if(EXISTS "${WORK}/overflow/out" OR EXISTS "${WORK}/memory/out")
    message(FATAL_ERROR "a refused case left an output directory behind")
endif()
