# cases/case.schema.json: every shipped case and every structurally valid test case validates
# (cases/scripts/check_case_schema.py exits 0); cases the loader refuses for their keys, types or
# ranges fail it, each naming the field.
# Invoked by ctest with -DPYTHON=... -DSCRIPT=... -DSOURCE=...
cmake_policy(SET CMP0057 NEW)  # if(... IN_LIST ...)
file(GLOB shipped ${SOURCE}/cases/flatland/*.json ${SOURCE}/cases/flatland/fitted/*.json
     ${SOURCE}/cases/spatial/*.json)
list(FILTER shipped EXCLUDE REGEX "/fitted/parameters\\.json$")  # the fits' parameters, no case
file(GLOB tests ${SOURCE}/tests/cases/data/*.json)
set(bad bad_fov bad_syntax nan_light spatial_bad_syntax spatial_nan_light spatial_null_light
        spatial_unknown_key spatial_zero_scale unknown_key)
set(valid)
foreach(file IN LISTS tests)
    get_filename_component(stem "${file}" NAME_WE)
    if(NOT stem IN_LIST bad)
        list(APPEND valid "${file}")
    endif()
endforeach()
list(LENGTH shipped shippedCount)
if(shippedCount LESS 13)
    message(FATAL_ERROR "case schema: only ${shippedCount} shipped cases found under ${SOURCE}")
endif()
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" ${shipped} ${valid}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "case schema: a valid case fails it (exit ${code})\n${out}${err}")
endif()

# Refused by the schema, each with the field named: "ARGS|WANTED" (exit 1 unless WANTED says 2:).
foreach(check
        "bad_fov|/camera/fov_deg: 190 is greater than or equal to the maximum of 180"
        "unknown_key|/camera: Additional properties are not allowed \\('zoom' was unexpected\\)"
        "spatial_unknown_key|/camera: Additional properties are not allowed"
        "spatial_null_light|/lights/0/position/1: None is not of type 'number'"
        "spatial_zero_scale|/geometry/1/transform/scale: 0 is less than or equal to the minimum"
        "spatial_nan_light|2:not JSON \\(NaN is not a JSON number\\)")
    string(REPLACE "|" ";" parts "${check}")
    list(GET parts 0 stem)
    list(GET parts 1 wanted)
    set(status 1)
    if(wanted MATCHES "^2:(.*)")
        set(status 2)
        set(wanted "${CMAKE_MATCH_1}")
    endif()
    execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${SOURCE}/tests/cases/data/${stem}.json"
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL status OR NOT "${out}${err}" MATCHES "${wanted}")
        message(FATAL_ERROR "case schema on ${stem}.json: exit ${code}, wanted ${status} and "
                            "'${wanted}'\n${out}${err}")
    endif()
endforeach()
