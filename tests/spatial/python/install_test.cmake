# Installs the Python module (cmake --install --component python) into a fresh prefix and imports
# it from there with nothing else on PYTHONPATH, from a directory outside the trees; runs the
# installed example. Arguments: BUILD (the build tree), PYTHON (the interpreter), DIR (the module's
# directory relative to the prefix, LEXEL_PYTHON_INSTALL_DIR), WORK (scratch).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(prefix "${WORK}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${prefix}"
                        --component python
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "cmake --install --component python failed:\n${err}")
endif()
set(ENV{PYTHONPATH} "${prefix}/${DIR}")
execute_process(COMMAND "${PYTHON}" -c
                        "import lexel; print(lexel.__file__, lexel.__version__, len(lexel.__all__))"
                WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "import lexel: ${out}")
if(NOT code EQUAL 0 OR NOT out MATCHES "^${prefix}/${DIR}/lexel/__init__.py ")
    message(FATAL_ERROR "importing the installed module failed (exit ${code}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${PYTHON}" "${prefix}/share/lexel/python/optimize_shadows.py"
                WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "checks hold")
    message(FATAL_ERROR "the installed example failed (exit ${code}):\n${out}\n${err}")
endif()
if(NOT EXISTS "${prefix}/share/lexel/python/README.md")
    message(FATAL_ERROR "the module's README was not installed")
endif()
