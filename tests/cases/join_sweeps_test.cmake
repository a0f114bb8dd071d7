# cases/scripts/join_sweeps.py on hand-written lights.csv files:
#   a: lights 0, 1 (kind, x), optimal and lispsm-tight      (the base: its lights and order)
#   b: lights 1, 0 (the same, another order), optimal       (joined as optimal-e1)
#   c: light 0 only; d: light 1's x differs from a's
# The joined file has a's light columns, a's methods, then b's optimal renamed, in a's order.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/script_errors.cmake)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/a" "${WORK}/b" "${WORK}/c" "${WORK}/d")
file(WRITE "${WORK}/a/lights.csv"
     "light,kind,x,optimal_misclassified,optimal_misclassified_mean,"
     "lispsm-tight_misclassified,lispsm-tight_misclassified_mean\n"
     "0,point,0.5,10,11.5,20,21.5\n1,point,0.25,30,31.5,40,41.5\n")
file(WRITE "${WORK}/b/lights.csv"
     "light,kind,x,optimal_misclassified,optimal_misclassified_mean\n"
     "1,point,0.25,33,33.5\n0,point,0.5,13,13.5\n")
file(WRITE "${WORK}/c/lights.csv"
     "light,kind,x,optimal_misclassified,optimal_misclassified_mean\n0,point,0.5,13,13.5\n")
file(WRITE "${WORK}/d/lights.csv"
     "light,kind,x,optimal_misclassified,optimal_misclassified_mean\n"
     "0,point,0.5,13,13.5\n1,point,0.75,33,33.5\n")

execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/out" "${WORK}/a"
                        "${WORK}/b:optimal=optimal-e1"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${WORK}/out/lights.csv" joined)
set(wanted
    "light,kind,x,optimal_misclassified,optimal_misclassified_mean,lispsm-tight_misclassified,"
    "lispsm-tight_misclassified_mean,optimal-e1_misclassified,optimal-e1_misclassified_mean\n"
    "0,point,0.5,10,11.5,20,21.5,13,13.5\n1,point,0.25,30,31.5,40,41.5,33,33.5\n")
string(REPLACE ";" "" wanted "${wanted}")
string(REPLACE "\r\n" "\n" joined "${joined}")
if(NOT code EQUAL 0 OR NOT joined STREQUAL wanted OR NOT out MATCHES "2 lights, 8 columns")
    message(FATAL_ERROR "join_sweeps.py: exit ${code}, ${out}${err}\nwrote\n${joined}\n"
                        "wanted\n${wanted}")
endif()
# DIR:METHOD keeps the name; a's lispsm-tight alone after b's whole optimal.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/out2" "${WORK}/b" "${WORK}/a:lispsm-tight"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ "${WORK}/out2/lights.csv" joined)
string(REPLACE "\r\n" "\n" joined "${joined}")
set(wanted "light,kind,x,optimal_misclassified,optimal_misclassified_mean,"
           "lispsm-tight_misclassified,lispsm-tight_misclassified_mean\n"
           "1,point,0.25,33,33.5,40,41.5\n0,point,0.5,13,13.5,20,21.5\n")
string(REPLACE ";" "" wanted "${wanted}")
if(NOT code EQUAL 0 OR NOT joined STREQUAL wanted)
    message(FATAL_ERROR "join_sweeps.py b a:lispsm-tight: exit ${code}, ${err}\nwrote\n${joined}")
endif()

# Errors write nothing: OUT/lights.csv stays absent.
expect_script_errors(join_sweeps.py
                     "${WORK}/bad;${WORK}/a;${WORK}/b|b: column optimal_misclassified given twice"
                     "${WORK}/bad;${WORK}/a;${WORK}/c:optimal=c|c/lights.csv: its lights differ"
                     "${WORK}/bad;${WORK}/a;${WORK}/d:optimal=d|d/lights.csv: light 1's x differs"
                     "${WORK}/bad;${WORK}/a;${WORK}/b:psm|b/lights.csv: no columns of psm"
                     "${WORK}/bad;${WORK}/a;${WORK}/b:optimal=|b:optimal=: wanted DIR, DIR:METHOD"
                     "${WORK}/bad;${WORK}/none|none: cannot read lights.csv"
                     "${WORK}/bad|wanted OUT and at least one sweep directory"
                     "--phases;${WORK}/bad;${WORK}/a|--phases: unknown option")
# OUT an existing file: one line, not a traceback.
file(WRITE "${WORK}/afile" "x")
expect_script_errors(join_sweeps.py "${WORK}/afile;${WORK}/a|afile: cannot write lights.csv")
if(EXISTS "${WORK}/bad/lights.csv")
    message(FATAL_ERROR "join_sweeps.py wrote ${WORK}/bad/lights.csv on an error")
endif()
