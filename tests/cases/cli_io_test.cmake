# Never lose a file, and refuse early (exit 2, one line): the built `lexel` on --out directories it must not damage, flags and case files it must refuse before computing, mesh
# paths it must not open, and signals. Invoked by ctest with -DLEXEL=... -DCASES=... -DDATA=...
# -DWORK=...; the parts that need root (another user's files, chattr) say when they are skipped.
if(EXISTS "${WORK}")
    # A run stopped midway may have left chattr attributes that keep WORK from being removed.
    execute_process(COMMAND chattr -R -a -i "${WORK}" OUTPUT_QUIET ERROR_QUIET)
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")
set(expectRunTimeout 120)  # a hang (a FIFO opened) fails instead of blocking the suite

set(good "${CASES}/flatland/single_plane.json")
set(small "${DATA}/spatial_small.json")
file(READ "${good}" goodText)
file(READ "${small}" smallText)
set(any "[^\n]*")

# Fails unless the directory holds exactly `expected` (names relative to it, hidden ones too).
function(expect_entries dir expected)
    file(GLOB_RECURSE found LIST_DIRECTORIES true RELATIVE "${dir}" "${dir}/*" "${dir}/.*")
    list(SORT found)
    set(want ${expected})
    list(SORT want)
    if(NOT found STREQUAL want)
        message(FATAL_ERROR "${dir} holds '${found}', expected '${want}'")
    endif()
endfunction()

execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
set(root FALSE)
if(uid STREQUAL "0")
    set(root TRUE)
endif()

# ---- --out '' and --case '' are refused, not taken for "not given" --------------------------------
# Before: `--out ''` ran, printed and wrote nothing (exit 0); `fit-thesis --case ''` fitted all
# four cases; `tables --cases ''` read the shipped ones.
function(expect_empty_refused flag what)
    execute_process(COMMAND "${LEXEL}" ${ARGN} ${flag} "" RESULT_VARIABLE code
                    OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR
       NOT err STREQUAL "lexel: error: ${flag}: must name ${what}, got an empty string\n")
        message(FATAL_ERROR "lexel ${ARGN} ${flag} '': exit ${code}, stdout '${out}', stderr '${err}'")
    endif()
endfunction()
expect_empty_refused(--out "a directory" run "${good}" --method normal)
expect_empty_refused(--out "a directory" run "${small}" --method focused)
expect_empty_refused(--out "a directory" sweep "${small}" --lights 1 --method focused)
expect_empty_refused(--out "a directory" storage)
expect_empty_refused(--out "a directory" storage --case "${small}" --method focused)
expect_empty_refused(--out "a directory" lowres "${good}")
expect_empty_refused(--out "a directory" tables)
expect_empty_refused(--out "a directory" fit-thesis --case single_plane --samples 0 --starts 0)
expect_empty_refused(--case "a thesis case" fit-thesis --samples 0 --starts 0 --out "${WORK}/fit")
expect_empty_refused(--cases "a directory" tables --out "${WORK}/tables")

# ---- --out checked completely before computing (stdout empty: nothing was computed) -------------
# Before: each of these computed everything, then failed in the final rename (exit 1).
set(outs "${WORK}/outpath")
file(MAKE_DIRECTORY "${outs}/dir/single_plane.csv" "${outs}/sweep/table1.csv")
file(CREATE_LINK "loop" "${outs}/loop" SYMBOLIC)
file(CREATE_LINK "${outs}/missing/target" "${outs}/dangling" SYMBOLIC)
string(REPEAT "n" 300 longName)
expect_run(2 "^$" "^lexel: error: --out: ${any}outpath/loop: a symbolic link loop\n$"
           run "${good}" --method normal --out "${outs}/loop")
expect_run(2 "^$" "^lexel: error: --out: ${any}outpath/dangling: a dangling symbolic link \\(to ${any}outpath/missing/target, which does not exist\\)\n$"
           run "${small}" --method focused --out "${outs}/dangling")
expect_run(2 "^$" "^lexel: error: --out: ${any}outpath/n+: a path component is 300 bytes; a file name has at most 255\n$"
           run "${good}" --method normal --out "${outs}/${longName}")
expect_run(2 "^$" "^lexel: error: --out: ${any}outpath/dir/single_plane.csv: is a directory, and an output file has its name\n$"
           run "${good}" --method normal --out "${outs}/dir")
expect_run(2 "^$" "^lexel: error: --out: ${any}outpath/sweep/table1.csv: is a directory, and an output file has its name\n$"
           sweep "${small}" --lights 1 --method focused --out "${outs}/sweep")
expect_entries("${outs}" "dangling;dir;dir/single_plane.csv;loop;sweep;sweep/table1.csv")

# ---- The overwrite guard covers every command that reads a case ---------------------------------
# Before: `storage --case DIR/storage_x.json --out DIR` (case name x) replaced the case with its
# output, exit 0.
string(REPLACE "\"spatial_small\"" "\"x\"" text "${smallText}")
file(WRITE "${WORK}/self/storage_x.json" "${text}")
expect_run(2 "^$" "^lexel: error: --out: writing ${any}self/storage_x.json would overwrite the case file ${any}self/storage_x.json\n$"
           storage --case "${WORK}/self/storage_x.json" --method focused --out "${WORK}/self")
file(READ "${WORK}/self/storage_x.json" kept)
if(NOT kept STREQUAL text)
    message(FATAL_ERROR "storage --case replaced its case file")
endif()
expect_entries("${WORK}/self" "storage_x.json")

# ---- lexel storage: finite, ordered, a representable frustum -------------------------------------
# Before: exit 1 with internal messages ("near plane n: must be finite and > 0, got -107869.95").
expect_run(2 "^$" "^lexel: error: --fov-y: must be in \\[0\\.1, 179\\] degrees, got 179\\.9999999\n$"
           storage --fov-y 179.9999999 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --near: must be in \\[1e-06, 1e\\+09\\], got 1e-300\n$"
           storage --near 1e-300 --far 1e300 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --aspect: must be in \\[0\\.01, 100\\], got 1e\\+300\n$"
           storage --aspect 1e300 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --far: must be 1\\.000001 to 1e\\+06 times --near \\(1\\), got 1\\.0000000000000002 \\(1\\.0000000000000002 times\\)\n$"
           storage --near 1 --far 1.0000000000000002 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --far: must be 1\\.000001 to 1e\\+06 times --near \\(1\\), got 1e\\+07 \\(1e\\+07 times\\)\n$"
           storage --near 1 --far 1e7 --out "${WORK}/storage_bad")
expect_run(2 "^$" "^lexel: error: --fov-y: must be in \\[0\\.1, 179\\] degrees, got nan\n$"
           storage --fov-y nan --out "${WORK}/storage_bad")
if(EXISTS "${WORK}/storage_bad")
    message(FATAL_ERROR "a refused lexel storage left ${WORK}/storage_bad behind")
endif()
# The corners of the accepted box compute, with no nan anywhere.
foreach(corner "0.1 0.01 1e-6 1" "179 100 1e3 1e9" "179 0.01 999999000 1e9" "0.1 100 1e-6 1.000001e-6")
    separate_arguments(corner)
    list(GET corner 0 fov)
    list(GET corner 1 aspect)
    list(GET corner 2 near)
    list(GET corner 3 far)
    expect_run(0 "^figure,series" "^$"
               storage --fov-y ${fov} --aspect ${aspect} --near ${near} --far ${far} --format csv)
    string(TOLOWER "${lastStdout}" csv)
    if(csv MATCHES "nan")
        message(FATAL_ERROR "storage at the corner ${corner} prints nan")
    endif()
endforeach()

# ---- A repeated --method is refused (before: it ran twice, two CSV columns of one name) ----------
expect_run(2 "^$" "^lexel: error: --method: 'normal' is given twice\n$"
           run "${good}" --method normal --method psm --method normal)
expect_run(2 "^$" "^lexel: error: --method: 'focused' is given twice\n$"
           run "${small}" --method focused --method focused)
expect_run(2 "^$" "^lexel: error: --method: 'focused' is given twice\n$"
           sweep "${small}" --lights 1 --methods focused --method focused)
expect_run(2 "^$" "^lexel: error: --method: 'focused' is given twice\n$"
           storage --case "${small}" --method focused --method focused)

# ---- Case text: a non-UTF-8 file stem, a NUL byte -----------------------------------------------
# Before: a stem "caf\xE9" without /name ran, then failed writing the JSON report with nlohmann's
# "[json.exception.type_error.316]" (exit 1); `{...}\0 garbage` was read up to the NUL.
string(REPLACE "  \"name\": \"single_plane\",\n" "" unnamed "${goodText}")
file(WRITE "${WORK}/text/unnamed.json" "${unnamed}")
execute_process(COMMAND sh -c "cp \"$1/unnamed.json\" \"$1/$(printf 'caf\\351').json\" && cp \"$1/unnamed.json\" \"$1/$(printf 'caf\\303\\251').json\" && exec \"$0\" run \"$1/$(printf 'caf\\351').json\" --method normal --out \"$1/out\""
                        "${LEXEL}" "${WORK}/text"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "^lexel: error: ${any}: /name: absent, and the file's stem is not a safe file stem: not UTF-8 \\(byte 0xE9 at offset 3\\)\n$")
    message(FATAL_ERROR "a non-UTF-8 stem: exit ${code}, stdout '${out}', stderr '${err}'")
endif()
execute_process(COMMAND sh -c "exec \"$0\" run \"$1/$(printf 'caf\\303\\251').json\" --method normal --format json"
                        "${LEXEL}" "${WORK}/text" RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 0 OR NOT out MATCHES "\"case\": \"café\"")
    message(FATAL_ERROR "a UTF-8 stem: exit ${code}, stdout '${out}'")
endif()
execute_process(COMMAND sh -c "{ cat \"$0\"; printf '\\000 garbage'; } > \"$1\"" "${good}" "${WORK}/text/nul.json")
expect_run(2 "^$" "^lexel: error: ${any}text/nul.json:[0-9]+:[0-9]+: invalid JSON: a NUL byte \\(a case file is text\\)\n$"
           run "${WORK}/text/nul.json" --out "${WORK}/text/out")
if(EXISTS "${WORK}/text/out")
    message(FATAL_ERROR "a refused case wrote ${WORK}/text/out")
endif()

# ---- Mesh paths: only regular files are opened, and what a path is gets said ---------------------
# Before: a directory, FIFO or device was "mesh file not found", and an OBJ whose mtllib named a
# FIFO hung for ever (Assimp opened it).
set(meshes "${WORK}/mesh")
file(MAKE_DIRECTORY "${meshes}/dir.obj")
execute_process(COMMAND mkfifo "${meshes}/pipe.obj" "${meshes}/pipe.mtl" RESULT_VARIABLE code)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "mkfifo failed")
endif()
file(WRITE "${meshes}/names_fifo.obj" "mtllib pipe.mtl\nv -1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
file(WRITE "${meshes}/index_past.off" "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")
file(WRITE "${meshes}/index_negative.off" "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n\n3 0 -1 2\n")
foreach(entry "dir.obj|${meshes}/dir.obj: is a directory, not a mesh file"
              "pipe.obj|${meshes}/pipe.obj: is a FIFO \\(named pipe\\), not a mesh file"
              "/dev/null|/dev/null: is a character device, not a mesh file"
              "names_fifo.obj|${meshes}/names_fifo.obj: cannot read mesh: reading it would open ${meshes}/pipe.mtl, a FIFO \\(named pipe\\); only regular files are read"
              "index_past.off|${meshes}/index_past.off: face 0 \\(line 6\\): vertex index 2 is 7, past the file's 3 vertices \\(0 to 2\\)"
              "index_negative.off|${meshes}/index_negative.off: face 0 \\(line 7\\): vertex index 1 is negative; OFF indices count vertices from 0")
    string(FIND "${entry}" "|" bar)  # the reasons hold ';', so no list
    string(SUBSTRING "${entry}" 0 ${bar} mesh)
    math(EXPR bar "${bar} + 1")
    string(SUBSTRING "${entry}" ${bar} -1 reason)
    string(REPLACE "{\"primitive\": \"box\"" "{\"mesh\": \"${mesh}\"" text "${smallText}")
    string(MAKE_C_IDENTIFIER "${mesh}" stem)
    file(WRITE "${meshes}/case_${stem}.json" "${text}")
    expect_run(2 "^$" "^lexel: error: ${any}case_${stem}.json: /geometry/1/mesh: ${reason}\n$"
               run "${meshes}/case_${stem}.json" --out "${meshes}/out")
endforeach()
if(EXISTS "${meshes}/out")
    message(FATAL_ERROR "a refused mesh left ${meshes}/out")
endif()

# ---- Signals: SIGTERM and SIGINT remove the staging directory and exit 128 + n ------------------
# Before: no handler, so the staging directory stayed, as after SIGKILL; and no later run removed
# such debris. SIGINT is restored to its default for the background run (a shell ignores it
# there). The kill comes once the run has made its staging directory, while it computes.
function(run_and_kill dir signal)
    file(MAKE_DIRECTORY "${dir}")
    execute_process(COMMAND sh -c "env --default-signal=INT \"$0\" run \"$1\" --out \"$2/out\" > /dev/null 2> \"$2/stderr\" & pid=$!; i=0; until ls -d \"$2\"/.lexel-staging-* > /dev/null 2>&1 || [ $i -gt 1200 ]; do i=$((i + 1)); sleep 0.05; done; kill -$3 $pid; wait $pid; echo $?"
                            "${LEXEL}" "${small}" "${dir}" "${signal}"
                    OUTPUT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE)
    set(status "${status}" PARENT_SCOPE)
endfunction()
foreach(signal "TERM|143" "INT|130")
    string(REPLACE "|" ";" signal "${signal}")
    list(GET signal 0 name)
    list(GET signal 1 expected)
    run_and_kill("${WORK}/signal_${name}" ${name})
    file(READ "${WORK}/signal_${name}/stderr" err)
    if(NOT status STREQUAL expected OR NOT err STREQUAL "lexel: error: interrupted by SIG${name}; no --out file was written\n")
        message(FATAL_ERROR "SIG${name}: exit ${status} (expected ${expected}), stderr '${err}'")
    endif()
    expect_entries("${WORK}/signal_${name}" "stderr")
endforeach()
# SIGKILL leaves the staging directory; the next run into the same place removes it.
run_and_kill("${WORK}/signal_KILL" KILL)
file(GLOB debris LIST_DIRECTORIES true "${WORK}/signal_KILL/.lexel-staging-*")
list(LENGTH debris nDebris)
if(NOT status STREQUAL "137" OR NOT nDebris EQUAL 1)
    message(FATAL_ERROR "SIGKILL: exit ${status}, debris '${debris}'")
endif()
expect_run(0 "" "" run "${small}" --method focused --no-map-truth --out "${WORK}/signal_KILL/out")
file(GLOB debris LIST_DIRECTORIES true "${WORK}/signal_KILL/.lexel-staging-*")
if(debris)
    message(FATAL_ERROR "the run after a SIGKILL left ${debris}")
endif()

# ---- An append-only --out (chattr +a) ------------------------------------------------------------
# Before: every successful run left its staging directory inside (it could not be removed).
file(MAKE_DIRECTORY "${WORK}/appendonly/out")
execute_process(COMMAND chattr +a "${WORK}/appendonly/out" RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
if(code EQUAL 0)
    expect_run(0 "" "^lexel: wrote index.html and 3 files to " run "${good}" --method normal --out "${WORK}/appendonly/out")
    expect_run(2 "^$" "^lexel: error: --out: ${any}appendonly/out: is append-only \\(chattr \\+a\\), so its old (index\\.html|single_plane\\.(csv|json|md)) cannot be replaced\n$"
               run "${good}" --method psm --out "${WORK}/appendonly/out")
    execute_process(COMMAND chattr -a "${WORK}/appendonly/out")
    expect_entries("${WORK}/appendonly" "out;out/index.html;out/single_plane.csv;out/single_plane.json;out/single_plane.md")
else()
    message(STATUS "skipped the append-only --out: chattr +a failed here")
endif()

# ---- Old files that cannot be kept for a rollback are never replaced ------------------------------
# Another user's files in a directory of ours: Linux's fs.protected_hardlinks forbids us to
# hard-link them (so lexel cannot keep their old versions) but not to rename over them. Before, a
# later rename failing (here: an immutable file) made the rollback delete every file it had
# replaced (2 of these 3 gone) and say "no file was replaced", exit 1; now the run is refused
# before computing, nothing changed.
set(protected 0)
if(EXISTS /proc/sys/fs/protected_hardlinks)
    file(READ /proc/sys/fs/protected_hardlinks protected)
    string(STRIP "${protected}" protected)
endif()
find_program(SETPRIV setpriv)
set(foreign "${WORK}/foreign/out")
file(MAKE_DIRECTORY "${foreign}")
foreach(ext csv json md)
    file(WRITE "${foreign}/single_plane.${ext}" "old ${ext}")
endforeach()
set(immutable 1)
if(root)
    execute_process(COMMAND chattr +i "${foreign}/single_plane.md" RESULT_VARIABLE immutable
                    OUTPUT_QUIET ERROR_QUIET)
endif()
if(root AND SETPRIV AND protected STREQUAL "1" AND immutable EQUAL 0)
    execute_process(COMMAND chown 65534 "${foreign}")
    execute_process(COMMAND "${SETPRIV}" --reuid=65534 --regid=65534 --clear-groups
                            "${LEXEL}" run "${good}" --method normal --out "${foreign}"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    execute_process(COMMAND chattr -i "${foreign}/single_plane.md")
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "^lexel: error: --out: ${any}foreign/out/single_plane\\.csv: cannot keep the old file to restore it if publishing fails \\(link: Operation not permitted: another user's file \\(fs\\.protected_hardlinks\\), or an immutable or append-only one\\)\n$")
        message(FATAL_ERROR "another user's old files: exit ${code}, stdout '${out}', stderr '${err}'")
    endif()
    foreach(ext csv json md)
        file(READ "${foreign}/single_plane.${ext}" kept)
        if(NOT kept STREQUAL "old ${ext}")
            message(FATAL_ERROR "${foreign}/single_plane.${ext} was changed: '${kept}'")
        endif()
    endforeach()
    expect_entries("${foreign}" "single_plane.csv;single_plane.json;single_plane.md")
else()
    if(root AND immutable EQUAL 0)
        execute_process(COMMAND chattr -i "${foreign}/single_plane.md")
    endif()
    message(STATUS "skipped another user's old files: needs root, setpriv, chattr +i and fs.protected_hardlinks = 1")
endif()

# Only the command's own outputs are its old files: another user's unrelated PNG in DIR (which
# lexel could not keep for a rollback) does not stop `tables`, whose figures are named by its
# cases. Before, every *.png in DIR counted as an output of `tables` and this was refused.
if(root AND SETPRIV AND protected STREQUAL "1")
    set(unrelated "${WORK}/unrelated/out")
    file(MAKE_DIRECTORY "${unrelated}")
    file(WRITE "${unrelated}/photo.png" "not lexel's")
    execute_process(COMMAND chown 65534 "${WORK}/unrelated" "${unrelated}")
    execute_process(COMMAND "${SETPRIV}" --reuid=65534 --regid=65534 --clear-groups
                            "${LEXEL}" tables --out "${unrelated}"
                    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    file(READ "${unrelated}/photo.png" kept)
    if(NOT code EQUAL 0 OR NOT kept STREQUAL "not lexel's" OR NOT EXISTS "${unrelated}/tables.md")
        message(FATAL_ERROR "tables beside another user's photo.png: exit ${code}, stderr '${err}'")
    endif()
else()
    message(STATUS "skipped another user's unrelated file: needs root, setpriv and fs.protected_hardlinks = 1")
endif()

message(STATUS "cli io tests passed")
