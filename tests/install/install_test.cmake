# Installs the build into a fresh prefix and builds a consumer project against it with
# find_package(lexel CONFIG REQUIRED); runs the consumer and the installed lexel command, and
# checks that the exported link interface of lexel::spatial names none of the harness's
# dependencies. Arguments: BUILD (the build tree), SOURCE (tests/install), WORK (scratch).
file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD}" --prefix "${prefix}"
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "cmake --install failed:\n${err}")
endif()

file(READ "${prefix}/lib/cmake/lexel/lexelTargets.cmake" targets)
foreach(forbidden embree assimp OpenImageIO TBB tbb)
    if(targets MATCHES "${forbidden}")
        message(FATAL_ERROR "the exported targets name ${forbidden}:\n${targets}")
    endif()
endforeach()

execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}/consumer" -B "${WORK}/consumer"
                        -G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "configuring the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}/consumer"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "building the consumer failed:\n${out}\n${err}")
endif()
execute_process(COMMAND "${WORK}/consumer/consumer" RESULT_VARIABLE code OUTPUT_VARIABLE out)
message(STATUS "consumer: ${out}")
if(NOT code EQUAL 0 OR NOT out MATCHES "boundary samples; h [0-9.e+]+ -> [0-9.e+]+")
    message(FATAL_ERROR "the consumer failed (exit ${code}):\n${out}")
endif()

# The installed command finds its data under share/lexel.
execute_process(COMMAND "${prefix}/bin/lexel" run "${prefix}/share/lexel/cases/flatland/single_plane.json"
                        --method optimal-l1
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "optimal-l1 +9\\.00")
    message(FATAL_ERROR "the installed lexel failed (exit ${code}):\n${out}\n${err}")
endif()
message(STATUS "install test passed")
