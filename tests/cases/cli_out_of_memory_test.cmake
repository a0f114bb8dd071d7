# A case inside lexel's 8 GiB budget on a machine that cannot give it that much (address space
# limited to 1 GiB with `ulimit -v`): std::bad_alloc becomes one `lexel: error:` line, exit 2, and
# no output directory (issue 16). Invoked by ctest with -DLEXEL=... -DDATA=... -DWORK=...
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
