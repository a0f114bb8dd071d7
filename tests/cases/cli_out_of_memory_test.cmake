# A case inside lexel's 8 GiB budget on a machine that cannot give it that much (address space
# limited to 1 GiB with `ulimit -v`): std::bad_alloc becomes one `lexel: error:` line, exit 2, and
# no output directory. Invoked by ctest with -DLEXEL=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")

# A 4000 x 4000 camera: about 3 GiB by the estimate, under the budget, over the limit.
file(READ "${DATA}/spatial_small.json" smallText)
string(REPLACE "\"width\": 160, \"height\": 120" "\"width\": 4000, \"height\": 4000" text "${smallText}")
file(WRITE "${WORK}/large_camera.json" "${text}")
set(LEXEL_UNLIMITED "${LEXEL}")
set(LEXEL /bin/sh)
expect_run(2 "^$" "^lexel: error: out of memory: this machine could not give the case what it needs \\(see the memory budget in cases/README.md\\)\n$"
           -c "ulimit -v 1048576 && exec \"$0\" run \"$1\" --method focused --out \"$2\""
           "${LEXEL_UNLIMITED}" "${WORK}/large_camera.json" "${WORK}/out")
if(EXISTS "${WORK}/out")
    message(FATAL_ERROR "a run out of memory left ${WORK}/out behind")
endif()

# JSON that needs more memory than the process may take: a 48 MB sweep record of empty arrays
# (about 40 bytes of document a byte) merged under the same 1 GiB limit. Before: nlohmann's
# std::bad_alloc reached std::terminate (its document frees through an allocating destructor),
# exit 134. Now the parse runs under a cap below what the process can take: one line, exit 2.
file(MAKE_DIRECTORY "${WORK}/huge_record")
string(REPEAT "[]," 262144 chunk)  # 768 KiB
file(WRITE "${WORK}/huge_record/sweep-record.json" "{\"lights\": [")
foreach(i RANGE 63)
    file(APPEND "${WORK}/huge_record/sweep-record.json" "${chunk}")
endforeach()
file(APPEND "${WORK}/huge_record/sweep-record.json" "[]]}\n")
expect_run(2 "^$" "^lexel: error: [^\n]*huge_record/sweep-record\\.json: [0-9]+ bytes of JSON need more memory than this machine gives \\([^\n]* were free to parse them\\)\n$"
           -c "ulimit -v 1048576 && exec \"$0\" merge \"$1\" --out \"$2\""
           "${LEXEL_UNLIMITED}" "${WORK}/huge_record" "${WORK}/merged")
if(EXISTS "${WORK}/merged")
    message(FATAL_ERROR "a merge out of memory left ${WORK}/merged behind")
endif()
