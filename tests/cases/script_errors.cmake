# expect_script_errors(NAME CASE...): runs ${PYTHON} ${SCRIPT} once per CASE, "ARG;ARG...|WANTED"
# (the arguments, then what the error says), and fails unless the script exits with status 2,
# prints nothing on stdout and one line on stderr that starts "NAME: " and, after an optional
# path, WANTED (a regular expression). Included by the scripts' tests.
function(expect_script_errors name)
    math(EXPR last "${ARGC} - 1")
    foreach(i RANGE 1 ${last})
        string(REPLACE "|" ";" parts "${ARGV${i}}")
        list(GET parts -1 expected)
        list(REMOVE_AT parts -1)
        execute_process(COMMAND "${PYTHON}" "${SCRIPT}" ${parts}
                        RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
        if(NOT code EQUAL 2 OR NOT err MATCHES "^${name}: (.*/)?${expected}" OR NOT out STREQUAL "")
            message(FATAL_ERROR "${name} ${parts}: exit ${code}, stderr '${err}', stdout '${out}'")
        endif()
    endforeach()
endfunction()

# expect_rows(ARGS WANTED...): runs ${PYTHON} ${SCRIPT} with ARGS ("ARG;ARG...") and fails unless
# it exits with status 0 and its stdout holds every WANTED string. Used by the scripts' tests.
function(expect_rows args)
    get_filename_component(name "${SCRIPT}" NAME)
    execute_process(COMMAND "${PYTHON}" "${SCRIPT}" ${args}
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    foreach(wanted IN LISTS ARGN)
        string(FIND "${out}" "${wanted}" at)
        if(NOT code EQUAL 0 OR at EQUAL -1)
            message(FATAL_ERROR "${name} ${args}: exit ${code}, wanted\n${wanted}\n"
                                "got\n${out}${err}")
        endif()
    endforeach()
endfunction()
