# cases/scripts/concordance_table.py on a lights.csv worked by hand (methods A, B, C; se 0 unless
# said):
#   light 0: h 1, 2, 3; e 1, 3, 2; errors 10, 20, 30: h orders all three pairs right; e gets
#            (A,B) and (A,C) right and (B,C) wrong.
#   light 1: A and B 10 ± 3 and 15 ± 3 (5 < 1.96·√18 = 8.3: within the noise); C's h is inf and
#            its e empty: nothing counts.
#   light 2: h 2, 2, 1 (A,B tie: only e ranks it); e 2, 1, 9; errors 10, 50, 30: h gets (A,C)
#            wrong and (B,C) right; e gets (A,B) wrong, (A,C) right, (B,C) wrong.
# The 5 pairs both rank: h 4 (80.0%), e 3 (60.0%); the 1 only e ranks, (A,B) on light 2: 0.0%.
# Among A and B: h and e 1 of 1 (light 0); e 0 of 1 on light 2's.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/abc")
set(columns "")
foreach(m A B C)
    string(APPEND columns ",${m}_h,${m}_e,${m}_misclassified_mean,${m}_misclassified_se")
endforeach()
file(WRITE "${WORK}/abc/lights.csv" "light${columns}\n"
     "0,1,1,10,0,2,3,20,0,3,2,30,0\n"
     "1,5,5,10,3,1,1,15,3,inf,,40,0\n"
     "2,2,2,10,0,2,1,50,0,1,9,30,0\n")

expect_rows("${WORK}/abc"
    "| set | lights | pairs | h orders as errors | e orders as errors | pairs only e ranks | e orders those |"
    "| abc | 3 | 5 | 80.0% | 60.0% | 1 | 0.0% |"
    "Pairs of every method whose phase means differ")
expect_rows("--among;A;--among;B;${WORK}/abc"
    "| abc | 3 | 1 | 100.0% | 100.0% | 1 | 0.0% |"
    "Pairs of A, B whose phase means differ")

expect_script_errors(concordance_table.py
                     "--among;A;--among;psm;${WORK}/abc|abc/lights.csv: no psm_h"
                     "--among;A;${WORK}/abc|abc/lights.csv: fewer than two methods"
                     "${WORK}/none|none: cannot read lights.csv"
                     "--phases;${WORK}/abc|--phases: unknown option"
                     "--among|--among: needs a method name"
                     "--among;A;--among;A;${WORK}/abc|--among A: given twice")
# A short row (a cell missing) counts as no value, not a crash: light 3 has only A's cells.
file(MAKE_DIRECTORY "${WORK}/short")
file(READ "${WORK}/abc/lights.csv" abc)
file(WRITE "${WORK}/short/lights.csv" "${abc}3,1,1,10,0\n")
expect_rows("${WORK}/short" "| short | 4 | 5 | 80.0% | 60.0% | 1 | 0.0% |")
