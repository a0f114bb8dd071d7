# cases/scripts/fair_table.py on a four-light lights.csv whose numbers are worked by hand:
#   light  optimal  optimal-h  focused-tight  lispsm-tight   best (of the two baselines)
#     0      100       110         150            120           120
#     1      200       190         210            250           210
#     2      300       330         290            340           290
#     3     1100       401         501            901           501
# optimal − lispsm-tight: differences −20, −50, −40, 199, mean 22.25 = +5.5% of 402.75; their
# sample s.d. 118.49, so the 95% half-width is t(3) = 3.182 · 118.49/√4 = 188.5 = 46.8%.
# optimal − best: −20, −10, 10, 599, mean 144.75 = +51.7% of 280.25, half-width 482.2 = 172.1%.
# Light 3 breaks the 2×best+50 rule (1100 > 1052). Bad input: one line, exit status 2.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/set")
file(WRITE "${WORK}/set/lights.csv"
     "light,optimal_misclassified_mean,optimal-h_misclassified_mean,"
     "focused-tight_misclassified_mean,lispsm-tight_misclassified_mean\n"
     "0,100,110,150,120\n1,200,190,210,250\n2,300,330,290,340\n3,1100,401,501,901\n")

execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --against lispsm-tight "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(row "| set | 4 | 425 | 258 | 288 | 403 | +5.5 ± 46.8% | +51.7 ± 172.1% | 1 |")
string(FIND "${out}" "${row}" at)
if(NOT code EQUAL 0 OR at EQUAL -1 OR NOT out MATCHES "optimal − lispsm-tight")
    message(FATAL_ERROR "fair_table.py --against lispsm-tight: exit ${code}, wanted\n${row}\n"
                        "got\n${out}${err}")
endif()
# Without --against: the paired column is against optimal-h (differences −10, 10, −30, 699: mean
# 167.25 = +64.9% of 257.75).
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "optimal − optimal-h" OR NOT out MATCHES "\\+64\\.9 ± ")
    message(FATAL_ERROR "fair_table.py: exit ${code}: ${out}${err}")
endif()

# --reference optimal-h: its differences against optimal are 10, −10, 30, −699, mean −167.25 =
# −39.4% of 425 (half-width t(3) · 354.88/√4 = 3.18245 · 177.44 = 564.69 = 132.87%); against the
# best −10, −20, 40, −100, mean −22.5 = −8.0% of 280.25; no light breaks the rule.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --reference optimal-h --against optimal
                        "${WORK}/set"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(row "| set | 4 | 425 | 258 | 288 | 403 | -39.4 ± 132.9% | -8.0 ± 32.9% | 0 |")
string(FIND "${out}" "${row}" at)
if(NOT code EQUAL 0 OR at EQUAL -1 OR NOT out MATCHES "optimal-h − optimal")
    message(FATAL_ERROR "fair_table.py --reference optimal-h: exit ${code}, wanted\n${row}\n"
                        "got\n${out}${err}")
endif()
# Cascades without a single-map baseline: no per-light best column. sdsm − optimal: −10, 20,
# mean 5 = +3.3% of 150, half-width t(1) = 12.706 · 21.21/√2 = 190.6 = 127.1%.
file(MAKE_DIRECTORY "${WORK}/cascades")
file(WRITE "${WORK}/cascades/lights.csv"
     "light,optimal_misclassified_mean,sdsm_misclassified_mean\n0,100,90\n1,200,220\n")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --reference sdsm --against optimal
                        "${WORK}/cascades"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| cascades \\| 2 \\| 150 \\| 155 \\| \\+3\\.3 ± 127\\.1% \\|\n"
   OR out MATCHES "best baseline")
    message(FATAL_ERROR "fair_table.py --reference sdsm: exit ${code}: ${out}${err}")
endif()

expect_script_errors(fair_table.py
                     "--against;psm;${WORK}/set|--against psm: .* has no such method"
                     "${WORK}/none|none: cannot read lights.csv"
                     "--against|--against: needs a method name"
                     "--phases;${WORK}/set|--phases: unknown option"
                     "--reference|--reference: needs a method name"
                     "--reference;psm;${WORK}/set|.*set/lights.csv: no lights with psm's phase-averaged")
# The single-map baselines are the registry's fair ones (lispsm-engine among them) unless
# --baseline names them. optimal − best of focused-tight and lispsm-engine: 100 − 90, 200 − 180,
# mean 15 = +11.1% of 135, half-width t(1) · 7.071/√2 = 12.706 · 5 = 63.5 = 47.1%. With
# --baseline focused-tight: −50, 20, mean −15 = −9.1% of 165, half-width 12.706 · 35 = 444.7 =
# 269.5%. A --baseline the sweep did not run is refused.
file(MAKE_DIRECTORY "${WORK}/engine")
file(WRITE "${WORK}/engine/lights.csv"
     "light,optimal_misclassified_mean,focused-tight_misclassified_mean,"
     "lispsm-engine_misclassified_mean\n0,100,150,90\n1,200,180,260\n")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/engine"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| engine \\| 2 \\| 150 \\| 165 \\| 175 \\| \\+11\\.1 ± 47\\.1% \\| 0 \\|")
    message(FATAL_ERROR "fair_table.py, the registry's baselines: exit ${code}: ${out}${err}")
endif()
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" --baseline focused-tight "${WORK}/engine"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| engine \\| 2 \\| 150 \\| 165 \\| 175 \\| -9\\.1 ± 269\\.5% \\| 0 \\|")
    message(FATAL_ERROR "fair_table.py --baseline focused-tight: exit ${code}: ${out}${err}")
endif()
expect_script_errors(fair_table.py
                     "--baseline;psm-tight;${WORK}/engine|--baseline psm-tight: .* has no such method")
