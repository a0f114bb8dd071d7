# Runs one libFuzzer target for CTest: a fixed seed and number of executions, bounded in time,
# starting from the seed directories with an empty scratch corpus (WORK/corpus) that receives
# the new inputs; a crash, leak, sanitizer report or timeout is written to WORK/ and fails.
# cmake -DFUZZER=... -DWORK=... -DRUNS=... -DMAX_SECONDS=... -DMAX_LEN=... -DSEEDS="dir;dir" -P run_fuzzer.cmake
file(REMOVE_RECURSE ${WORK}/corpus)
file(MAKE_DIRECTORY ${WORK}/corpus)
execute_process(
    COMMAND ${FUZZER} -seed=1 -runs=${RUNS} -max_total_time=${MAX_SECONDS} -timeout=10
            -rss_limit_mb=2048 -max_len=${MAX_LEN} -print_final_stats=1 -artifact_prefix=${WORK}/
            ${WORK}/corpus ${SEEDS}
    RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${FUZZER}: finding (exit ${status}); the input is in ${WORK}/")
endif()
