# cases/scripts/oracle_table.py on lights.csv files whose numbers are worked by hand:
#   set   light  optimal  optimal-h  optimal-oracle  closed: (optimal-h − optimal)/(h − oracle)
#   pair     0       20        30           10          50%
#   pair     1       60        60           20           0%
#   same     0      100       100            0           0%
# pair: the sums 80, 90, 30 close (90 − 80)/(90 − 30) = 17%; a resample of its two lights is
# {0, 0} (50%), {1, 1} (0%) or mixed (17%), so with 2000 resamples the 95% interval is 0 to 50
# (each end drawn about 500 times). Means 40, 45, 15: optimal +166.7% and optimal-h +200.0% above
# the bound. same: 0% in every resample; its bound's mean is 0, so "above" is undefined (—).
# Average (17% + 0%)/2 = 8%, interval (0 + 0)/2 to (50 + 0)/2 = 0 to 25%; pooled over the three
# lights, the sums 180, 190, 30 close (190 − 180)/(190 − 30) = 6%.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
set(header "light,optimal_misclassified_mean,optimal-h_misclassified_mean,"
           "optimal-oracle_misclassified_mean\n")
file(MAKE_DIRECTORY "${WORK}/pair" "${WORK}/same" "${WORK}/worse" "${WORK}/flat")
file(WRITE "${WORK}/pair/lights.csv" ${header} "0,20,30,10\n1,60,60,20\n")
file(WRITE "${WORK}/same/lights.csv" ${header} "0,100,100,0\n")
# worse: optimal above optimal-h, (30 − 40)/(30 − 10) = −50%. flat: optimal-h at the bound, the
# share undefined and left out of the average.
file(WRITE "${WORK}/worse/lights.csv" ${header} "0,40,30,10\n")
file(WRITE "${WORK}/flat/lights.csv" ${header} "0,10,10,10\n")

expect_rows("${WORK}/pair;${WORK}/same"
    "| set | lights | optimal | optimal-h | optimal-oracle | optimal above optimal-oracle | optimal-h above optimal-oracle | closed |"
    "| pair | 2 | 40 | 45 | 15 | +166.7% | +200.0% | 17% (0 to 50) |"
    "| same | 1 | 100 | 100 | 0 | — | — | 0% (0 to 0) |"
    "Average over the 2 sets: optimal closes 8% (0 to 25%) of optimal-h's gap to optimal-oracle; pooled over the 3 lights: 6%.")
# Without pair's light 1 (the pattern matches pair alone): pair closes 50% in every resample, the
# average is 25% (25 to 25), and the two lights left pool to (130 − 120)/(130 − 10) = 8%.
expect_rows("--exclude;p*:1;${WORK}/pair;${WORK}/same"
    "| pair | 1 | 20 | 30 | 10 | +100.0% | +200.0% | 50% (50 to 50) |"
    "| same | 1 | 100 | 100 | 0 | — | — | 0% (0 to 0) |"
    "Average over the 2 sets: optimal closes 25% (25 to 25%)"
    "pooled over the 2 lights: 8%.")
expect_rows("${WORK}/worse;${WORK}/flat"
    "| worse | 1 | 40 | 30 | 10 | +300.0% | +200.0% | −50% (−50 to −50) |"
    "| flat | 1 | 10 | 10 | 10 | +0.0% | +0.0% | — |"
    "Average over the 1 set: optimal closes −50% (−50 to −50%)")
# --reference optimal-h --from optimal: pair's share is (40 − 45)/(40 − 15) = −20%. A method
# below the bound is "−" percent above it: with --bound optimal (40) worse's optimal-oracle (10)
# is 75% below it and optimal-h (30) 25%, and the share is (30 − 10)/(30 − 40) = −200%.
expect_rows("--bound;optimal;--reference;optimal-oracle;${WORK}/worse"
    "| worse | 1 | 40 | 30 | 10 | −75.0% | −25.0% | −200% (−200 to −200) |")
expect_rows("--reference;optimal-h;--from;optimal;${WORK}/pair"
    "optimal-h above optimal-oracle | optimal above optimal-oracle | closed |"
    "| pair | 2 | 40 | 45 | 15 | +200.0% | +166.7% | −20% ")

# With the phase means' standard errors: noisy's gap, 30 − 25 = 5 against √(10² + 10²) = 14.1
# (z 0.4), is within its noise, so its share (30 − 20)/(30 − 25) = 200% is named and the average
# over the other set (pair, which has no standard errors and so no z) is pair's 17% (0 to 50).
# clear's gap, 60 − 10 = 50 against √2 (z 35), is beyond it: no such line.
file(MAKE_DIRECTORY "${WORK}/noisy" "${WORK}/clear")
set(se_header "light,optimal_misclassified_mean,optimal-h_misclassified_mean,"
              "optimal-h_misclassified_se,optimal-oracle_misclassified_mean,"
              "optimal-oracle_misclassified_se\n")
file(WRITE "${WORK}/noisy/lights.csv" ${se_header} "0,20,30,10,25,10\n")
file(WRITE "${WORK}/clear/lights.csv" ${se_header} "0,20,60,1,10,1\n")
expect_rows("${WORK}/pair;${WORK}/noisy"
    "| noisy | 1 | 20 | 30 | 25 | −20.0% | +20.0% | 200% (200 to 200) |"
    "Average over the 2 sets: optimal closes 108%"
    "Gap to optimal-oracle within its phase noise (|gap| < 1.96 standard errors): noisy (z 0.4). Average over the other 1 set: 17% (0 to 50%).")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/clear"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| clear \\| 1 \\|" OR out MATCHES "within its phase noise")
    message(FATAL_ERROR "oracle_table.py: clear's gap is beyond its noise, exit ${code}, got\n"
                        "${out}${err}")
endif()
# Adaptive phases: the phase counts 16 and 64 (average 40); of the two means, 20 ± 1 is settled
# (a pixel) and 25 ± 1.5 is not (above 2% of 25 = 0.5 and above a pixel).
file(MAKE_DIRECTORY "${WORK}/raised")
file(WRITE "${WORK}/raised/lights.csv"
     "light,optimal_misclassified_mean,optimal_misclassified_se,optimal_phases,"
     "optimal-h_misclassified_mean,optimal-oracle_misclassified_mean,"
     "optimal-oracle_misclassified_se,optimal-oracle_phases\n0,20,1,16,30,25,1.5,64\n")
expect_rows("${WORK}/raised"
    "Phases per mean: 16 to 64, 40.0 on average; 1 of 2 means with a standard error above 2% of the mean and above a pixel.")
# An empty standard-error cell (a NaN the sweep wrote as nothing) leaves the set without a z.
file(MAKE_DIRECTORY "${WORK}/blank")
file(WRITE "${WORK}/blank/lights.csv" ${se_header} "0,20,30,,25,10\n")
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/blank"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "\\| blank \\| 1 \\|" OR out MATCHES "within its phase noise")
    message(FATAL_ERROR "oracle_table.py blank: exit ${code}, got\n${out}${err}")
endif()

expect_script_errors(oracle_table.py
                     "--from;psm;${WORK}/pair|pair/lights.csv: no phase-averaged counts of psm"
                     "--reference;psm;${WORK}/pair|pair/lights.csv: no lights with psm's"
                     "${WORK}/pair;${WORK}/none|none: cannot read lights.csv"
                     "--exclude;8;${WORK}/pair|--exclude 8: wanted PATTERN:LIGHT"
                     "--exclude;same:0;${WORK}/same|same/lights.csv: --exclude leaves no light"
                     "--resamples;0;${WORK}/pair|--resamples 0: wanted a whole number"
                     "--bound;optimal;${WORK}/pair|--reference, --from and --bound: wanted three"
                     "--resamples|--resamples: needs a count"
                     "--phases;${WORK}/pair|--phases: unknown option"
                     "--resamples;5|no sweep directory given")
