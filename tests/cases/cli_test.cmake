# Runs the built `lexel` binary on good and bad case files and checks output and exit codes.
# Invoked by ctest with -DLEXEL=... -DCASES=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

function(expect_run expectedCode stdoutRegex stderrRegex)
    execute_process(COMMAND "${LEXEL}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL expectedCode)
        message(FATAL_ERROR "lexel ${ARGN}: exit ${code}, expected ${expectedCode}\nstdout: ${out}\nstderr: ${err}")
    endif()
    if(NOT out MATCHES "${stdoutRegex}")
        message(FATAL_ERROR "lexel ${ARGN}: stdout does not match '${stdoutRegex}':\n${out}")
    endif()
    if(NOT err MATCHES "${stderrRegex}")
        message(FATAL_ERROR "lexel ${ARGN}: stderr does not match '${stderrRegex}':\n${err}")
    endif()
    set(lastStdout "${out}" PARENT_SCOPE)
    set(lastStderr "${err}" PARENT_SCOPE)
endfunction()

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

# --out writes the three files per case.
expect_run(0 "" "wrote 3 files" run "${good}" --method normal --out "${WORK}/out")
foreach(ext json csv md)
    if(NOT EXISTS "${WORK}/out/single_plane.${ext}")
        message(FATAL_ERROR "missing ${WORK}/out/single_plane.${ext}")
    endif()
endforeach()

# Bad input: one line naming the field and the reason, exit 2, no output files.
expect_run(2 "^$" "^lexel: error: .*bad_fov.json: /camera/fov_deg: must be in \\(0, 180\\), got 190\n$"
           run "${DATA}/bad_fov.json" --out "${WORK}/bad")
expect_run(2 "^$" "bad_syntax.json:4:[0-9]+: invalid JSON" run "${DATA}/bad_syntax.json" --out "${WORK}/bad")
expect_run(2 "^$" "/camera/zoom: unknown key" run "${DATA}/unknown_key.json" --out "${WORK}/bad")
expect_run(2 "^$" "no camera pixel sees any geometry" run "${DATA}/no_visible.json" --out "${WORK}/bad")
expect_run(2 "^$" "/light/position: the light lies on segment /geometry/0/0" run "${DATA}/light_on_segment.json" --out "${WORK}/bad")
expect_run(2 "^$" "no lexel plane has them all in front" run "${DATA}/wide_sweep.json" --out "${WORK}/bad")
expect_run(2 "^$" "zero-length segment" run "${DATA}/zero_segment.json" --out "${WORK}/bad")
expect_run(2 "^$" "the camera is inside the closed polyline" run "${DATA}/camera_inside.json" --out "${WORK}/bad")
expect_run(2 "^$" "/light/position/0: must be a number, got null" run "${DATA}/nan_light.json" --out "${WORK}/bad")
# A bad second case stops the run before anything is written.
expect_run(2 "^$" "fov_deg" run "${good}" "${DATA}/bad_fov.json" --out "${WORK}/bad")
expect_run(2 "" "unknown flatland method 'nope'" run "${good}" --method nope --out "${WORK}/bad")
expect_run(2 "" "" run "${good}" --format xml)
expect_run(2 "" "" run "${WORK}/does_not_exist.json")
if(EXISTS "${WORK}/bad")
    message(FATAL_ERROR "a failed run left ${WORK}/bad behind")
endif()

# lowres on a shipped case.
expect_run(0 "decision pixels K.*\n *5 .*\n *10 " "" lowres "${good}")
message(STATUS "cli tests passed")
