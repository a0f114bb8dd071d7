# Hostile input around a sweep, each refused with one line and exit 2 before anything is printed
# or written, or run to the end: the journal beside --out opened as the output set opens its
# files (no link followed, regular files only, never blocking), a run into a directory a sweep
# holds, merges of records and images that a sweep did not write, and the schema's extreme sizes
# for every 3D method. Invoked by ctest with -DLEXEL=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")
set(expectRunTimeout 120)  # a run that blocks (a FIFO read) fails instead of hanging

set(case "${DATA}/spatial_small.json")
set(sweep sweep "${case}" --lights 2 --method focused-tight --method sdsm --cascades 2)

# ---- The journal's path ---------------------------------------------------------------------
# Before: a link there was followed, its target truncated and the link removed.
file(WRITE "${WORK}/precious.txt" "a user's file\n")
file(CREATE_LINK "${WORK}/precious.txt" "${WORK}/.linked.lexel-sweep-journal" SYMBOLIC)
expect_run(2 "^$" "^lexel: error: --out: [^\n]*linked\\.lexel-sweep-journal: is a symbolic link \\(lexel opens no file beside --out through a link; remove it\\)\n$"
           ${sweep} --out "${WORK}/linked")
file(READ "${WORK}/precious.txt" kept)
if(NOT kept STREQUAL "a user's file\n" OR NOT IS_SYMLINK "${WORK}/.linked.lexel-sweep-journal"
   OR EXISTS "${WORK}/linked")
    message(FATAL_ERROR "a sweep whose journal path is a link changed '${kept}' or wrote its --out")
endif()
# Before: --resume blocked for ever reading a FIFO; a directory exited 1.
find_program(MKFIFO mkfifo)
if(MKFIFO)
    execute_process(COMMAND "${MKFIFO}" "${WORK}/.fifo.lexel-sweep-journal")
    expect_run(2 "^$" "^lexel: error: --out: [^\n]*fifo\\.lexel-sweep-journal: is a FIFO \\(named pipe\\), not a resume journal\n$"
               ${sweep} --out "${WORK}/fifo" --resume)
endif()
file(MAKE_DIRECTORY "${WORK}/.folder.lexel-sweep-journal")
expect_run(2 "^$" "^lexel: error: --out: [^\n]*folder\\.lexel-sweep-journal: is a directory, not a resume journal \\(remove it\\)\n$"
           ${sweep} --out "${WORK}/folder" --resume)

# ---- A run into a directory whose sweep is running is refused (before: both exit 0) ---------
find_program(FLOCK flock)
if(FLOCK)
    execute_process(COMMAND "${FLOCK}" "${WORK}/.held.lexel-sweep-journal" "${LEXEL}" run "${case}"
                            --method focused --no-map-truth --out "${WORK}/held"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR EXISTS "${WORK}/held" OR NOT err MATCHES
       "^lexel: error: --out: another lexel command writing into this directory is running \\(it holds the resume journal [^\n]*held\\.lexel-sweep-journal\\)\n$")
        message(FATAL_ERROR "a run into a directory a sweep holds: exit ${code}: ${err}")
    endif()
endif()
# So are storage and merge (below) into such a directory.
if(FLOCK)
    execute_process(COMMAND "${FLOCK}" "${WORK}/.stored.lexel-sweep-journal" "${LEXEL}" storage
                            --out "${WORK}/stored"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR EXISTS "${WORK}/stored")
        message(FATAL_ERROR "a storage into a directory a sweep holds: exit ${code}: ${err}")
    endif()
endif()
# A run leaves no journal behind.
expect_run(0 "" "" run "${case}" --method focused --no-map-truth --out "${WORK}/ran")
if(EXISTS "${WORK}/.ran.lexel-sweep-journal")
    message(FATAL_ERROR "a run left the lock it held beside its --out")
endif()

# ---- More shards than lights (before: 0/3 over 2 lights ran, though shard 2 has none) ---------
expect_run(2 "^$" "^lexel: error: --shard 0/3: the sweep has 2 lights, fewer than its 3 shards \\(give at most 2 shards\\)\n$"
           ${sweep} --shard 0/3)

# ---- Merge checks every record field and every shard file before printing --------------------
expect_run(0 "" "" ${sweep} --out "${WORK}/shard")
file(READ "${WORK}/shard/sweep-record.json" record)
string(REGEX MATCH "\"file\": *\"[^\"]+\"" firstImage "${record}")
string(REGEX REPLACE "\"file\": *\"([^\"]+)\"" "\\1" firstImage "${firstImage}")
if(firstImage STREQUAL "")
    message(FATAL_ERROR "the sweep's record names no first-light image")
endif()
# merge_refused(name regex): a copy of the shard changed by the caller first, merged; exit 2,
# nothing on stdout, no --out.
function(merge_refused name stderrRegex)
    expect_run(2 "^$" "^lexel: error: ${stderrRegex}\n$" merge "${WORK}/${name}" --out "${WORK}/${name}_merged")
    if(EXISTS "${WORK}/${name}_merged")
        message(FATAL_ERROR "a refused merge wrote ${WORK}/${name}_merged")
    endif()
endfunction()
function(shard_copy name)
    file(REMOVE_RECURSE "${WORK}/${name}")
    file(COPY "${WORK}/shard/" DESTINATION "${WORK}/${name}")
endfunction()
# Before: 16 bytes were allocated per light of identity.lights, believed up to 2^63 - 1.
shard_copy(lights)
string(REGEX REPLACE "\"lights\": *2," "\"lights\":1000000000," text "${record}")
file(WRITE "${WORK}/lights/sweep-record.json" "${text}")
merge_refused(lights "[^\n]*lights/sweep-record\\.json: /identity/lights: must be [^\n]*100000[^\n]*")
# Before: a missing image, a FIFO, a link to a non-PNG or an image named like another output
# printed the whole table, then exited 1.
shard_copy(missing)
file(REMOVE "${WORK}/missing/${firstImage}")
merge_refused(missing "merge: [^\n]*missing/${firstImage}: not found")
shard_copy(link)
file(REMOVE "${WORK}/link/${firstImage}")
file(CREATE_LINK "${WORK}/precious.txt" "${WORK}/link/${firstImage}" SYMBOLIC)
merge_refused(link "merge: [^\n]*link/${firstImage}: is a symbolic link \\(lexel reads no file here through one\\)")
shard_copy(text)
file(WRITE "${WORK}/text/${firstImage}" "not a PNG\n")
merge_refused(text "merge: [^\n]*text/${firstImage}: not a complete PNG image \\(10 bytes without the PNG signature\\)")
if(MKFIFO)
    shard_copy(fifo_image)
    file(REMOVE "${WORK}/fifo_image/${firstImage}")
    execute_process(COMMAND "${MKFIFO}" "${WORK}/fifo_image/${firstImage}")
    merge_refused(fifo_image "merge: [^\n]*fifo_image/${firstImage}: is a FIFO \\(named pipe\\), not a regular file")
endif()
shard_copy(renamed)
string(REPLACE "\"file\":\"${firstImage}\"" "\"file\":\"cascades.png\"" text "${record}")
file(WRITE "${WORK}/renamed/sweep-record.json" "${text}")
merge_refused(renamed "merge: [^\n]*renamed/cascades\\.png: the record names an image that a sweep of spatial_small does not write")
# The same image listed twice (before: read twice into memory, then exit 1 after the tables).
string(REGEX MATCHALL "\"file\": *\"[^\"]+\"" imageEntries "${record}")
list(GET imageEntries 1 secondEntry)
shard_copy(twice)
string(REPLACE "${secondEntry}" "\"file\":\"${firstImage}\"" text "${record}")
file(WRITE "${WORK}/twice/sweep-record.json" "${text}")
merge_refused(twice "[^\n]*twice/sweep-record\\.json: /first_light_images/1/file: names an image listed before")
# A merge into a directory a sweep holds is refused like a run.
if(FLOCK)
    execute_process(COMMAND "${FLOCK}" "${WORK}/.merged.lexel-sweep-journal" "${LEXEL}" merge "${WORK}/shard" --out "${WORK}/merged"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR EXISTS "${WORK}/merged")
        message(FATAL_ERROR "a merge into a directory a sweep holds: exit ${code}: ${err}")
    endif()
endif()
expect_run(0 "" "" merge "${WORK}/shard" --out "${WORK}/merged")

# ---- The schema's extremes for every 3D method -------------------------------------------------
# Every method, with a 1 x 1 readback, a 1 x 1 shadow map, both, and the largest of each, runs or is
# refused with one
# line naming the field and exit 2 (before: rtw tripped an Embree assertion, exit 134, and logpsm
# exited 1 with an internal message); the largest sweep (100000 lights) runs its one-light shard.
execute_process(COMMAND "${LEXEL}" run "${case}" --method none ERROR_VARIABLE err OUTPUT_QUIET)
string(REGEX REPLACE "^.*\\(known: ([^)]*)\\)\n$" "\\1" methods "${err}")
string(REPLACE ", " ";" methods "${methods}")
list(LENGTH methods nMethods)
if(nMethods LESS 25)
    message(FATAL_ERROR "could not read the 3D methods from '${err}'")
endif()
file(READ "${case}" caseText)
# The largest readback and map (16384 x 16384) are refused by the memory budget, naming the field.
foreach(variant "1|1|128|128" "64|64|1|1" "1|1|1|1" "16384|16384|128|128" "64|64|16384|16384")
    string(REPLACE "|" ";" sides "${variant}")
    list(GET sides 0 rw)
    list(GET sides 1 rh)
    list(GET sides 2 mw)
    list(GET sides 3 mh)
    string(REPLACE "\"readback\": {\"width\": 64, \"height\": 64}" "\"readback\": {\"width\": ${rw}, \"height\": ${rh}}" text "${caseText}")
    string(REPLACE "\"shadow_map\": {\"width\": 128, \"height\": 128}" "\"shadow_map\": {\"width\": ${mw}, \"height\": ${mh}}" text "${text}")
    set(extreme "${WORK}/extreme_${rw}_${mw}.json")
    file(WRITE "${extreme}" "${text}")
    foreach(method ${methods})
        execute_process(COMMAND "${LEXEL}" run "${extreme}" --method ${method} --no-map-truth --phases 1
                        RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 300)
        if(NOT (code EQUAL 0 OR (code EQUAL 2 AND err MATCHES "^lexel: error: [^\n]+\n$")))
            message(FATAL_ERROR "readback ${rw}x${rh}, map ${mw}x${mh}, ${method}: exit ${code}: ${err}")
        endif()
    endforeach()
endforeach()
foreach(method ${methods})
    execute_process(COMMAND "${LEXEL}" sweep "${case}" --lights 100000 --shard 7/100000 --method ${method} --phases 1
                    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 300)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "100000 lights, shard 7, ${method}: exit ${code}: ${err}")
    endif()
endforeach()
