# cases/scripts/engine_table.py on a three-light lights.csv whose numbers are worked by hand:
#   light  optimal (mean, se, S, S99, ms, shimmer)   tsm (the same)        tsm − optimal   noise
#     0      100,  5,  2, 1, 1, 0.5                    80,  5, 4, 3, 0.5, 0.3    −20 (won)    13.9
#     1      200, 10,  3, 2, 3, 0.7                   210, 10, 1, 1, 0.5, 0.5     10 (tie)    27.7
#     2      300,  0,  –, –, 2, 0.6                   330,  0, 5, 4, 0.5, 0.4     30 (lost)    0
# (noise 1.96·√(se² + se_ref²)). Means 200 and 206.7; the differences' mean 6.67 = +3.3% of 200,
# their s.d. 25.17, so the 95% half-width is t(2) = 4.303 · 25.17/√3 = 62.5 = 31.3%. Won / lost
# 33% / 33%. Median storage factors (the empty ones left out) 2.5 and 1.5, 4 and 3; ms per light
# 2.00 and 0.50 (0.25× optimal's); shimmer the mean over the lights, 0.6 and 0.4, tsm's −0.2 on
# every light, so −33.3 ± 0.0% of optimal's. The residual
# noise: se/mean 0.05, 0.05, 0.0625, 0.0476 and two zeros, median 4.9%. Bad input: one line,
# exit status 2.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/set")
file(WRITE "${WORK}/set/lights.csv"
     "light,optimal_misclassified_mean,optimal_misclassified_se,optimal_storage_factor,"
     "optimal_storage_factor_p99,optimal_ms,optimal_shimmer,tsm_misclassified_mean,"
     "tsm_misclassified_se,tsm_storage_factor,tsm_storage_factor_p99,tsm_ms,tsm_shimmer\n"
     "0,100,5,2,1,1,0.5,80,5,4,3,0.5,0.3\n1,200,10,3,2,3,0.7,210,10,1,1,0.5,0.5\n"
     "2,300,0,,,2,0.6,330,0,5,4,0.5,0.4\n")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
foreach(row "| optimal | 200 | – | – | 2.5, 1.5 | 2.00 (1×) | 0.600 |"
            "| tsm | 207 | +3.3 ± 31.3% | 33% / 33% | 4, 3 | 0.50 (0.25×) | 0.400 (-33.3 ± 0.0%) |"
            "| set | 3 | 200 | +3.3 ± 31.3% |"
            "Residual noise (each light's standard error over its mean, median over the lights and methods with errors): 4.9%")
    string(FIND "${out}" "${row}" at)
    if(NOT code EQUAL 0 OR at EQUAL -1)
        message(FATAL_ERROR "engine_table.py: exit ${code}, wanted\n${row}\ngot\n${out}${err}")
    endif()
endforeach()
# --reference tsm: optimal − tsm is −3.2% of 206.7, half-width 62.516 = 30.2497% (t(2) =
# 4.30265, exact: the script takes lexel's StudentT95). With a set that lacks the shimmer (a sweep
# without --shimmer-poses) there is no shimmer column.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --reference tsm "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| optimal \\| 200 \\| -3\\.2 ± 30\\.2% \\| 33% / 33% \\|")
    message(FATAL_ERROR "engine_table.py --reference tsm: exit ${code}: ${out}${err}")
endif()
file(MAKE_DIRECTORY "${WORK}/still")
file(WRITE "${WORK}/still/lights.csv"
     "light,optimal_misclassified_mean,optimal_misclassified_se,optimal_storage_factor,"
     "optimal_storage_factor_p99,optimal_ms,tsm_misclassified_mean,tsm_misclassified_se,"
     "tsm_storage_factor,tsm_storage_factor_p99,tsm_ms\n0,100,5,2,1,1,80,5,4,3,0.5\n")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/set" "${WORK}/still"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "Pooled over 2 sets, 4 lights" OR out MATCHES "shimmer")
    message(FATAL_ERROR "engine_table.py, a set without shimmer: exit ${code}: ${out}${err}")
endif()

file(MAKE_DIRECTORY "${WORK}/onephase")
file(WRITE "${WORK}/onephase/lights.csv" "light,optimal_misclassified,optimal_ms\n0,1,2\n")
file(MAKE_DIRECTORY "${WORK}/badshimmer")
file(WRITE "${WORK}/badshimmer/lights.csv"
     "light,optimal_misclassified_mean,optimal_misclassified_se,optimal_storage_factor,"
     "optimal_storage_factor_p99,optimal_ms,optimal_shimmer\n0,1,0,,,2,x\n")
file(MAKE_DIRECTORY "${WORK}/emptyms")
file(WRITE "${WORK}/emptyms/lights.csv" "light,optimal_misclassified_mean,optimal_misclassified_se,"
                                        "optimal_storage_factor,optimal_storage_factor_p99,optimal_ms\n"
                                        "0,1,0,,,\n")
expect_script_errors(engine_table.py
                     "--shimmer;${WORK}/set|--shimmer: unknown option"
                     "${WORK}/badshimmer|.*badshimmer/lights.csv: optimal_shimmer is missing or not a number"
                     "${WORK}/none|none: cannot read lights.csv"
                     "${WORK}/onephase|.*onephase/lights.csv: no lights with optimal's phase-averaged"
                     "--reference|--reference: needs a method name"
                     "--phases;${WORK}/set|--phases: unknown option"
                     "--reference;psm;${WORK}/set|.*set/lights.csv: no lights with psm's phase-averaged"
                     "${WORK}/emptyms|.*emptyms/lights.csv: optimal_ms is missing or not a number"
                     "|no sweep directory given")
