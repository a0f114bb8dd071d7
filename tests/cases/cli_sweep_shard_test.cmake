# Sweeps that scale out: `lexel sweep --shard K/N` run as N concurrent processes and
# joined by `lexel merge` gives the files of one unsharded sweep bit for bit (times aside), and
# `lexel sweep --resume` after a SIGKILL finishes with the same files as an uninterrupted run
# without recomputing the lights its journal holds. Invoked by ctest with -DLEXEL=... -DDATA=...
# -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/compare_sweep_outputs.cmake")
set(expectRunTimeout 300)

# A small sweep that still has every kind of output: optimal (a winner per light), sdsm (the
# partitions study at k = 1, 4, 8 besides --cascades 2, and the first light's images); its frame
# 480 x 360 so that a light takes long enough (~0.1 s) for the kill below to come mid-sweep.
file(READ "${DATA}/spatial_small.json" caseText)
string(REPLACE "\"width\": 160, \"height\": 120" "\"width\": 480, \"height\": 360" caseText "${caseText}")
set(case "${WORK}/case.json")
file(WRITE "${case}" "${caseText}")
set(sweep sweep "${case}" --lights 6 --methods optimal --methods sdsm --cascades 2)

function(expect_same a b)
    compare_sweep_dirs("${a}" "${b}" difference)
    if(NOT difference STREQUAL "")
        message(FATAL_ERROR "${difference}")
    endif()
endfunction()

# ---- The whole sweep, uninterrupted ----
expect_run(0 "" "^lexel: wrote index.html, table1.md, table1.csv, sweep.json, lights.csv, sweep-record.json, cascades.csv, cascades.png and [0-9]+ images of the first light to [^\n]*\n$"
           ${sweep} --out "${WORK}/whole")
if(EXISTS "${WORK}/.whole.lexel-sweep-journal")
    message(FATAL_ERROR "the journal of a finished sweep is left behind")
endif()

# ---- N = 3 shards as 3 concurrent processes, merged ----
set(script "")
foreach(k 0 1 2)
    string(APPEND script "\"$0\" ${sweep} --shard ${k}/3 --out \"${WORK}/shard${k}\" >\"${WORK}/shard${k}.log\" 2>&1 & p${k}=$!\n")
endforeach()
string(APPEND script "wait $p0 && wait $p1 && wait $p2\n")
string(REPLACE ";" " " script "${script}")
execute_process(COMMAND sh -c "${script}" "${LEXEL}" RESULT_VARIABLE code TIMEOUT 300)
if(NOT code EQUAL 0)
    file(READ "${WORK}/shard0.log" log0)
    message(FATAL_ERROR "the shards failed (${code}):\n${log0}")
endif()
file(STRINGS "${WORK}/shard1/lights.csv" rows)
list(LENGTH rows nRows)
list(GET rows 1 first)
if(NOT nRows EQUAL 3 OR NOT first MATCHES "^1,point,")  # lights 1 and 4 of 0 ... 5
    message(FATAL_ERROR "shard 1/3's lights.csv:\n${rows}")
endif()
if(EXISTS "${WORK}/shard1/spatial_small_light0_sdsm_map1.png"
   OR NOT EXISTS "${WORK}/shard0/spatial_small_light0_sdsm_map1.png")
    message(FATAL_ERROR "the first light's images belong to shard 0 alone")
endif()
# In any order of the directories.
expect_run(0 "merge: 6 lights from 3 shards" "^lexel: wrote index.html, table1.md, [^\n]* to [^\n]*merged\n$"
           merge "${WORK}/shard2" "${WORK}/shard0" "${WORK}/shard1" --out "${WORK}/merged")
expect_same("${WORK}/whole" "${WORK}/merged")

# The comparison can fail: a count changed in a copy is found, a time changed is not.
file(COPY "${WORK}/merged/" DESTINATION "${WORK}/tampered")
file(READ "${WORK}/merged/lights.csv" csv)
string(REGEX REPLACE "\n0,point,([^,]*),([^,]*),([^,]*),([0-9]+)," "\n0,point,\\1,\\2,\\3,1\\4," tampered "${csv}")
file(WRITE "${WORK}/tampered/lights.csv" "${tampered}")
compare_sweep_dirs("${WORK}/whole" "${WORK}/tampered" difference)
if(NOT difference MATCHES "^lights.csv differs at line 2")
    message(FATAL_ERROR "a changed receiver count went unnoticed: '${difference}'")
endif()
# (the first method's misclassified, h and e, then its ms)
string(REGEX REPLACE "\n0,point,([^,]*,[^,]*,[^,]*,[0-9]+,[0-9]+,[^,]*,[^,]*),[^,]*," "\n0,point,\\1,12345.678," retimed "${csv}")
file(WRITE "${WORK}/tampered/lights.csv" "${retimed}")
compare_sweep_dirs("${WORK}/whole" "${WORK}/tampered" difference)
if(retimed STREQUAL csv OR NOT difference STREQUAL "")
    message(FATAL_ERROR "a changed time is not masked: '${difference}'")
endif()

# ---- Merge refuses what is not one sweep, with one line and nothing written ----
expect_run(0 "" "" sweep "${case}" --lights 6 --methods focused --shard 1/3 --out "${WORK}/other")
foreach(refusal
        "light 0 is in both [^\n]*shard0 and [^\n]*shard0 \\(overlapping shards\\)|${WORK}/shard0;${WORK}/shard0;${WORK}/shard1;${WORK}/shard2"
        "lights 2 and 5 of 6 are in none of the shards given \\(missing shards\\?\\)|${WORK}/shard0;${WORK}/shard1"
        "[^\n]*other is not a shard of the sweep of [^\n]*shard0: they differ in methods \\('optimal,sdsm' vs 'focused'\\)|${WORK}/shard0;${WORK}/other;${WORK}/shard2"
        "[^\n]*/sweep-record.json: not found \\(is [^\n]* the --out directory of a lexel sweep\\?\\)|${WORK}")
    string(REPLACE "|" ";" parts "${refusal}")
    list(GET parts 0 message)
    list(REMOVE_AT parts 0)
    expect_run(2 "^$" "^lexel: error: (merge: )?${message}\n$" merge ${parts} --out "${WORK}/refused")
    if(EXISTS "${WORK}/refused")
        message(FATAL_ERROR "a refused merge wrote ${WORK}/refused")
    endif()
endforeach()

# ---- Bad --shard values and --resume without --out: one line, exit 2, nothing written ----
foreach(bad "3/3" "0/0" "1" "a/b" "-1/3" "1/3x" "/3" "1/")
    expect_run(2 "^$" "^lexel: error: --shard: must be K/N with N >= 1 and K = 0 ... N-1 \\(light i belongs to shard i mod N\\), got '${bad}'\n$"
               ${sweep} --shard "${bad}" --out "${WORK}/refused")
endforeach()
expect_run(2 "^$" "^lexel: error: --shard 6/7: the sweep has 6 lights, fewer than its 7 shards [^\n]*\n$"
           ${sweep} --shard 6/7 --out "${WORK}/refused")
expect_run(2 "^$" "^lexel: error: --resume: [^\n]*give --out\n$" ${sweep} --resume)
if(EXISTS "${WORK}/refused" OR EXISTS "${WORK}/.refused.lexel-sweep-journal")
    message(FATAL_ERROR "a refused sweep wrote ${WORK}/refused or its journal")
endif()

# A second sweep into a directory whose journal another run holds is refused.
find_program(FLOCK flock)
if(FLOCK)
    execute_process(COMMAND "${FLOCK}" "${WORK}/.locked.lexel-sweep-journal" "${LEXEL}" ${sweep} --out "${WORK}/locked"
                    RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET)
    if(NOT code EQUAL 2 OR NOT err MATCHES "^lexel: error: --out: another lexel command writing into this directory is running \\(it holds the resume journal [^\n]*locked\\.lexel-sweep-journal\\)\n$"
       OR EXISTS "${WORK}/locked")
        message(FATAL_ERROR "a sweep into a directory whose journal is locked: exit ${code}: ${err}")
    endif()
endif()

# ---- --resume after a SIGKILL ----
# The sweep in the background on one core (so that its lights finish one by one), reaped by a
# shell that writes its exit status; killed once its journal holds two lights.
set(journal "${WORK}/.resumed.lexel-sweep-journal")
set(pin "")
find_program(TASKSET taskset)
file(STRINGS "/proc/self/status" allowed REGEX "^Cpus_allowed_list:")
if(TASKSET AND allowed MATCHES "^Cpus_allowed_list:[ \t]*([0-9]+)")
    set(pin "\"${TASKSET}\" -c ${CMAKE_MATCH_1}")  # the first CPU this process may use
endif()
set(quoted "")
foreach(arg IN LISTS sweep)
    string(APPEND quoted " \"${arg}\"")
endforeach()
execute_process(COMMAND sh -c "(${pin} \"$0\" ${quoted} --out \"${WORK}/resumed\" >\"${WORK}/killed.log\" 2>&1 & echo $! >\"${WORK}/killed.pid\"; wait $!; echo $? >\"${WORK}/killed.rc\") >/dev/null 2>&1 &"
                "${LEXEL}" RESULT_VARIABLE code)
set(lines 0)
foreach(try RANGE 1200)
    if(EXISTS "${journal}" AND EXISTS "${WORK}/killed.pid")
        file(STRINGS "${journal}" journaled REGEX "^\\{\"light\":")
        list(LENGTH journaled lines)
        if(lines GREATER_EQUAL 2)
            break()
        endif()
    endif()
    if(EXISTS "${WORK}/killed.rc")
        break()
    endif()
    execute_process(COMMAND sleep 0.02)
endforeach()
file(READ "${WORK}/killed.pid" pid)
string(STRIP "${pid}" pid)
execute_process(COMMAND kill -KILL "${pid}")
foreach(try RANGE 500)
    if(EXISTS "${WORK}/killed.rc")
        break()
    endif()
    execute_process(COMMAND sleep 0.02)
endforeach()
file(READ "${WORK}/killed.rc" rc)
string(STRIP "${rc}" rc)
if(NOT rc EQUAL 137 OR EXISTS "${WORK}/resumed")
    message(FATAL_ERROR "the sweep was not killed mid-sweep (exit ${rc}, ${lines} lights journaled)")
endif()
# What the journal holds (its complete lines): each light's times, which a light computed again
# would not repeat.
file(READ "${journal}" journalText)
string(REGEX MATCHALL "\\{\"light\":[^\n]*\n" journaled "${journalText}")
list(LENGTH journaled nJournaled)
if(nJournaled LESS 2 OR nJournaled GREATER_EQUAL 6)
    message(FATAL_ERROR "${nJournaled} lights journaled when killed")
endif()
# A line cut short by the kill is dropped.
file(APPEND "${journal}" "{\"light\":{\"cells\":[[1,")

# A journal of another sweep is refused and left as it is.
file(READ "${journal}" before)
expect_run(2 "^$" "^lexel: error: --resume: [^\n]*resumed\\.lexel-sweep-journal: is the journal of another sweep: it differs from this run in methods \\('optimal,sdsm' vs 'optimal'\\); run without --resume to start over\n$"
           sweep "${case}" --lights 6 --methods optimal --cascades 2 --out "${WORK}/resumed" --resume)
file(READ "${journal}" after)
if(NOT before STREQUAL after OR EXISTS "${WORK}/resumed")
    message(FATAL_ERROR "a refused --resume changed the journal or wrote ${WORK}/resumed")
endif()

expect_run(0 "" "^lexel: resuming from [^\n]*resumed\\.lexel-sweep-journal: ${nJournaled} of 6 lights done, [0-9]+ of 18 lights of the partitions study\n"
           ${sweep} --out "${WORK}/resumed" --resume)
expect_same("${WORK}/whole" "${WORK}/resumed")
if(EXISTS "${journal}")
    message(FATAL_ERROR "the journal of a finished sweep is left behind")
endif()
# The journaled lights were not computed again: their times in the record are the journal's.
file(READ "${WORK}/resumed/sweep-record.json" record)
foreach(line IN LISTS journaled)
    if(NOT line MATCHES "\"index\":([0-9]+),\"ms\":(\\[[^]]*\\])")
        message(FATAL_ERROR "unexpected journal line: ${line}")
    endif()
    string(FIND "${record}" "\"index\":${CMAKE_MATCH_1},\"ms\":${CMAKE_MATCH_2}" at)
    if(at LESS 0)
        message(FATAL_ERROR "light ${CMAKE_MATCH_1} was computed again (its journaled times ${CMAKE_MATCH_2} are not in the record)")
    endif()
endforeach()
