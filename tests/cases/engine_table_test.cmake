# cases/scripts/engine_table.py on a three-light lights.csv whose numbers are worked by hand:
#   light  optimal (mean, se, S, ms)   tsm (mean, se, S, ms)   tsm − optimal   noise 1.96·√(se²+se²)
#     0      100,  5,  2, 1              80,  5, 4, 0.5          −20 (won)       13.9
#     1      200, 10,  3, 3             210, 10, 1, 0.5           10 (tie)       27.7
#     2      300,  0,  –, 2             330,  0, 5, 0.5           30 (lost)       0
# Means 200 and 206.7; the differences' mean 6.67 = +3.3% of 200, their s.d. 25.17, so the 95%
# half-width is t(2) = 4.303 · 25.17/√3 = 62.5 = 31.3%. Won / lost 33% / 33%. Median storage
# factor 2.5 (the empty one left out) and 4; ms per light 2.00 and 0.50 (0.25× optimal's);
# shimmer the mean over the run's two lights: 0.6 and 0.4. The residual noise: se/mean 0.05,
# 0.05, 0.0625, 0.0476 and two zeros, median 4.9%. Bad input: one line, exit status 2.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/set")
file(WRITE "${WORK}/set/lights.csv"
     "light,optimal_misclassified_mean,optimal_misclassified_se,optimal_storage_factor,"
     "optimal_ms,tsm_misclassified_mean,tsm_misclassified_se,tsm_storage_factor,tsm_ms\n"
     "0,100,5,2,1,80,5,4,0.5\n1,200,10,3,3,210,10,1,0.5\n2,300,0,,2,330,0,5,0.5\n")
file(WRITE "${WORK}/run.json" "{\"camera_path\": [{\"shimmer_percent\": {\"optimal\": 0.5, "
                              "\"tsm\": 0.3}}, {\"shimmer_percent\": {\"optimal\": 0.7, "
                              "\"tsm\": 0.5}}]}")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --shimmer "${WORK}/run.json" "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
foreach(row "| optimal | 200 | – | – | 2.5 | 2.00 (1×) | 0.600 |"
            "| tsm | 207 | +3.3 ± 31.3% | 33% / 33% | 4 | 0.50 (0.25×) | 0.400 |"
            "| set | 3 | 200 | +3.3 ± 31.3% |"
            "Residual noise (each light's standard error over its mean, median over the lights and methods with errors): 4.9%")
    string(FIND "${out}" "${row}" at)
    if(NOT code EQUAL 0 OR at EQUAL -1)
        message(FATAL_ERROR "engine_table.py: exit ${code}, wanted\n${row}\ngot\n${out}${err}")
    endif()
endforeach()
# --reference tsm: optimal − tsm is −3.2% of 206.7; without --shimmer no shimmer column.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --reference tsm "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| optimal \\| 200 \\| -3\\.2 ± 30\\.3% \\| 33% / 33% \\|"
   OR out MATCHES "shimmer")
    message(FATAL_ERROR "engine_table.py --reference tsm: exit ${code}: ${out}${err}")
endif()

file(MAKE_DIRECTORY "${WORK}/onephase")
file(WRITE "${WORK}/onephase/lights.csv" "light,optimal_misclassified,optimal_ms\n0,1,2\n")
file(WRITE "${WORK}/nopath.json" "{\"lights\": []}")
file(MAKE_DIRECTORY "${WORK}/emptyms")
file(WRITE "${WORK}/emptyms/lights.csv" "light,optimal_misclassified_mean,optimal_misclassified_se,"
                                        "optimal_storage_factor,optimal_ms\n0,1,0,,\n")
expect_script_errors(engine_table.py
                     "--shimmer;${WORK}/nopath.json;${WORK}/set|--shimmer .*: no camera_path"
                     "--shimmer;${WORK}/none.json;${WORK}/set|--shimmer .*: cannot read it as JSON"
                     "${WORK}/none|none: cannot read lights.csv"
                     "${WORK}/onephase|.*onephase/lights.csv: no lights with optimal's phase-averaged"
                     "--reference|--reference: needs a method name"
                     "--phases;${WORK}/set|--phases: unknown option"
                     "--reference;psm;${WORK}/set|.*set/lights.csv: no lights with psm's phase-averaged"
                     "${WORK}/emptyms|.*emptyms/lights.csv: optimal_ms is missing or not a number"
                     "|no sweep directory given")
