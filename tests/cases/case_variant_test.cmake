# cases/scripts/case_variant.py: the copy has the new readback and map, its name says so, relative
# mesh paths become absolute (the copy may live anywhere), and the copy loads and runs in lexel;
# bad input is one line, exit 2, no file. Invoked by ctest with -DPYTHON=... -DSCRIPT=...
# -DLEXEL=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${DATA}/spatial_small.json" "${WORK}/small.json"
                        --readback 64 48 --shadow-map 128 96
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "case_variant.py: exit ${code}: ${err}")
endif()
file(READ "${WORK}/small.json" json)
string(JSON rw GET "${json}" readback width)
string(JSON rh GET "${json}" readback height)
string(JSON mw GET "${json}" shadow_map width)
string(JSON mh GET "${json}" shadow_map height)
string(JSON name GET "${json}" name)
if(NOT rw EQUAL 64 OR NOT rh EQUAL 48 OR NOT mw EQUAL 128 OR NOT mh EQUAL 96
   OR NOT name MATCHES "-readback64x48-map128x96$")
    message(FATAL_ERROR "case_variant.py wrote readback ${rw}x${rh}, map ${mw}x${mh}, name ${name}")
endif()
execute_process(COMMAND "${LEXEL}" run "${WORK}/small.json" --method focused-tight --no-map-truth
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "focused-tight")
    message(FATAL_ERROR "lexel run on the variant: exit ${code}: ${err}")
endif()

# lexel runs `optimal` on a variant.
function(expect_optimal_runs variant)
    execute_process(COMMAND "${LEXEL}" run "${variant}" --method optimal --no-map-truth
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 0 OR NOT out MATCHES "optimal")
        message(FATAL_ERROR "lexel run on ${variant}: exit ${code}: ${err}")
    endif()
endfunction()

# The optimizer's sample budget: optimizer.max_samples, and the variant runs `optimal` on it.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${DATA}/spatial_small.json" "${WORK}/budget.json"
                        --max-samples 5
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${WORK}/budget.json" json)
string(JSON budget GET "${json}" optimizer max_samples)
string(JSON name GET "${json}" name)
if(NOT code EQUAL 0 OR NOT budget EQUAL 5 OR NOT name MATCHES "-samples5$")
    message(FATAL_ERROR "case_variant.py --max-samples 5: budget ${budget}, name ${name} "
                        "(exit ${code}: ${err})")
endif()
expect_optimal_runs("${WORK}/budget.json")

# The edge energy's exponent: optimizer.edge_exponent beside the budget, and lexel runs the variant.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/budget.json" "${WORK}/exponent.json"
                        --edge-exponent 1
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${WORK}/exponent.json" json)
string(JSON exponent GET "${json}" optimizer edge_exponent)
string(JSON budget GET "${json}" optimizer max_samples)
string(JSON name GET "${json}" name)
if(NOT code EQUAL 0 OR NOT exponent EQUAL 1 OR NOT budget EQUAL 5 OR NOT name MATCHES "-samples5-exponent1$")
    message(FATAL_ERROR "case_variant.py --edge-exponent 1: exponent ${exponent}, budget ${budget}, "
                        "name ${name} (exit ${code}: ${err})")
endif()
expect_optimal_runs("${WORK}/exponent.json")

# --max-samples all takes the budget away again (the report's set-up of a shipped case).
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${WORK}/budget.json" "${WORK}/all.json"
                        --readback 40 30 --max-samples all
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${WORK}/all.json" json)
string(JSON optimizer ERROR_VARIABLE missing GET "${json}" optimizer)
string(JSON name GET "${json}" name)
if(NOT code EQUAL 0 OR NOT missing MATCHES "not found" OR NOT name MATCHES "-samplesall$")
    message(FATAL_ERROR "case_variant.py --max-samples all: optimizer '${optimizer}', name ${name} "
                        "(exit ${code}: ${err})")
endif()

# A relative mesh path is made absolute against the case file's directory.
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${DATA}/spatial_missing_mesh.json"
                        "${WORK}/mesh.json" --readback 90 90
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${WORK}/mesh.json" json)
string(JSON mesh GET "${json}" geometry 1 mesh)
if(NOT code EQUAL 0 OR NOT IS_ABSOLUTE "${mesh}" OR NOT mesh MATCHES "^${DATA}/")
    message(FATAL_ERROR "case_variant.py: mesh path ${mesh} (exit ${code}: ${err})")
endif()

# Bad input: one line naming the flag or file, exit 2, nothing written.
foreach(bad "--readback;0;90" "" "--readback;90;90;--name" "--max-samples;0"
            "--max-samples;many" "--edge-exponent;0" "--edge-exponent;x")
    execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${DATA}/spatial_small.json" "${WORK}/bad.json"
                            ${bad}
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 2 OR NOT out STREQUAL "" OR EXISTS "${WORK}/bad.json"
       OR NOT err MATCHES "^case_variant.py: [^\n]+\n$")
        message(FATAL_ERROR "case_variant.py ${bad}: exit ${code}, stdout '${out}', stderr '${err}'")
    endif()
endforeach()
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${DATA}/spatial_small.json" "${WORK}/bad.json"
                        --readback 0 90
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT err STREQUAL "case_variant.py: --readback: width and height must be in [1, 16384], got 0 90\n")
    message(FATAL_ERROR "case_variant.py --readback 0 90: stderr '${err}'")
endif()
