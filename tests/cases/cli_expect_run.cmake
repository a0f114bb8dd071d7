# expect_run(<exit code> <stdout regex> <stderr regex> ARGS...): runs "${LEXEL}" ARGS and fails the
# CLI test unless the exit code and both streams match; leaves lastStdout and lastStderr set in the
# caller's scope. A run longer than expectRunTimeout seconds (when set) fails, so that a hang is a
# failure. Included by cli_test.cmake, cli_io_test.cmake and cli_gl_test.cmake.
function(expect_run expectedCode stdoutRegex stderrRegex)
    set(timeout)
    if(DEFINED expectRunTimeout)
        set(timeout TIMEOUT ${expectRunTimeout})
    endif()
    execute_process(COMMAND "${LEXEL}" ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                    ${timeout})
    if(NOT code EQUAL expectedCode)
        message(FATAL_ERROR "lexel ${ARGN}: exit ${code}, expected ${expectedCode}\nstdout: ${out}\nstderr: ${err}")
    endif()
    if(NOT out MATCHES "${stdoutRegex}")
        message(FATAL_ERROR "lexel ${ARGN}: stdout does not match '${stdoutRegex}':\n${out}")
    endif()
    if(NOT err MATCHES "${stderrRegex}")
        message(FATAL_ERROR "lexel ${ARGN}: stderr does not match '${stderrRegex}':\n${err}")
    endif()
    set(lastStdout "${out}" PARENT_SCOPE)
    set(lastStderr "${err}" PARENT_SCOPE)
endfunction()
