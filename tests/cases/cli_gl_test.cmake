# The `lexel` command with --backend gl: the same outputs as the CPU backend on the small 3D case,
# the timing command, and the one-line error when no context can be made. Invoked by ctest with
# -DLEXEL=... -DDATA=... -DWORK=...; prints "SKIPPED" (CTest: skipped) when this machine has no
# OpenGL 4.5 context, unless LEXEL_REQUIRE_GL=1 (CI), which makes that a failure.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(small "${DATA}/spatial_small.json")

include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")

expect_run(0 "^lexel [0-9.]+\ncpu \\([0-9]+ threads\\)\ngl: " "^$" info)
if(lastStdout MATCHES "\ngl: unavailable: ([^\n]*)")
    if("$ENV{LEXEL_REQUIRE_GL}" STREQUAL "1")
        message(FATAL_ERROR "LEXEL_REQUIRE_GL=1 but ${CMAKE_MATCH_1}")
    endif()
    message("SKIPPED: ${CMAKE_MATCH_1}")
    return()
endif()
string(REGEX MATCH "\ngl: ([^\n]*)" renderer "${lastStdout}")

# run: the GL output against the CPU's on a 160×120 camera with a 64² readback (before: the GL
# readback of a camera whose aspect ratio was not the readback's saw another frustum): the same
# counted pixels and boundary samples, and per method misclassified and uncovered pixels within
# RESULTS.md's CPU/GL bound max(5, 5e-4 × counted).
set(methods focused focused-tight plane-optimal sdsm optimal-report optimal)
set(methodFlags)
foreach(m ${methods})
    list(APPEND methodFlags --method ${m})
endforeach()
expect_run(0 "^\\{\n  \"case\": \"spatial_small\"" "^lexel: backend gl: [^\n]+\n$"
           run "${small}" --backend gl --format json ${methodFlags})
set(glJson "${lastStdout}")
expect_run(0 "^\\{" "^$" run "${small}" --format json ${methodFlags})
set(cpuJson "${lastStdout}")
string(JSON counted GET "${cpuJson}" lights 0 receiver_pixels)
string(JSON glCounted GET "${glJson}" lights 0 receiver_pixels)
string(JSON samples GET "${cpuJson}" lights 0 boundary_samples)
string(JSON glSamples GET "${glJson}" lights 0 boundary_samples)
if(NOT counted EQUAL glCounted OR NOT samples EQUAL glSamples)
    message(FATAL_ERROR "run --backend gl: ${glCounted} counted pixels and ${glSamples} boundary "
                        "samples, the CPU ${counted} and ${samples}")
endif()
math(EXPR bound "${counted} / 2000")
if(bound LESS 5)
    set(bound 5)
endif()
list(LENGTH methods nMethods)
math(EXPR last "${nMethods} - 1")
foreach(m RANGE ${last})
    string(JSON name GET "${cpuJson}" lights 0 methods ${m} method)
    foreach(field misclassified uncovered)
        string(JSON cpuValue GET "${cpuJson}" lights 0 methods ${m} ${field})
        string(JSON glValue GET "${glJson}" lights 0 methods ${m} ${field})
        math(EXPR diff "${glValue} - ${cpuValue}")
        if(diff LESS -${bound} OR diff GREATER ${bound})
            message(FATAL_ERROR "run --backend gl: ${name} ${field} ${glValue} of ${glCounted}, "
                                "the CPU ${cpuValue} of ${counted} (bound ${bound})")
        endif()
    endforeach()
endforeach()

# --out: the same images as the CPU backend (same files; their pixels differ only where the
# decisions do, gl_tests).
expect_run(0 "^light 0" "wrote [1-9][0-9]* images" run "${small}" --backend gl --out "${WORK}/out_gl")
expect_run(0 "^light 0" "wrote [1-9][0-9]* images" run "${small}" --out "${WORK}/out_cpu")
file(GLOB glFiles RELATIVE "${WORK}/out_gl" "${WORK}/out_gl/*")
file(GLOB cpuFiles RELATIVE "${WORK}/out_cpu" "${WORK}/out_cpu/*")
list(LENGTH glFiles nGl)
if(NOT glFiles STREQUAL cpuFiles OR nGl LESS 3)
    message(FATAL_ERROR "run --out: the GL backend wrote ${glFiles}, the CPU backend ${cpuFiles}")
endif()

# Warped methods: rtw renders on the GPU (the vertex warp of tessellated geometry); logpsm's map is
# ray-cast on the CPU, and one line says so.
expect_run(0 "^\\{\n  \"case\": \"spatial_small\""
           "^lexel: backend gl: [^\n]+\nlexel: note: --backend gl: logpsm's map is ray-cast on the CPU [^\n]+\n$"
           run "${small}" --backend gl --format json --method rtw --method logpsm)
string(JSON rtwName GET "${lastStdout}" lights 0 methods 0 method)
string(JSON logName GET "${lastStdout}" lights 0 methods 1 method)
if(NOT rtwName STREQUAL "rtw" OR NOT logName STREQUAL "logpsm")
    message(FATAL_ERROR "run --backend gl --method rtw --method logpsm: ${rtwName}, ${logName}")
endif()

# sweep and timing.
expect_run(0 "^\\{\n  \"case\": \"spatial_small\"" "^lexel: backend gl" sweep "${small}" --backend gl
           --lights 3 --methods optimal --methods focused --format json)
expect_run(0 "^\\{" "^lexel: backend gl" timing "${small}" --backend gl --lights 2 --frames 2 --format json)
string(JSON backend GET "${lastStdout}" backend)
string(JSON frames LENGTH "${lastStdout}" optimal frames)
string(JSON ratio GET "${lastStdout}" ratio ours)
if(NOT backend MATCHES "^gl: " OR NOT frames EQUAL 2 OR NOT ratio GREATER 0)
    message(FATAL_ERROR "unexpected timing JSON:\n${lastStdout}")
endif()

# No usable context: one line naming --backend, exit 2, nothing on stdout. A software renderer
# refused by LEXEL_GL_REQUIRE_HARDWARE=1 is "no context" on a machine without a GPU.
if(renderer MATCHES "llvmpipe|softpipe")
    set(ENV{LEXEL_GL_REQUIRE_HARDWARE} 1)
    expect_run(2 "^$" "^lexel: error: --backend gl: no OpenGL 4.5 context: [^\n]*refused[^\n]*\n$"
               run "${small}" --backend gl)
    unset(ENV{LEXEL_GL_REQUIRE_HARDWARE})
endif()
set(ENV{__EGL_VENDOR_LIBRARY_FILENAMES} "${WORK}/no_such_vendor.json")
expect_run(2 "^$" "^lexel: error: --backend gl: no OpenGL 4.5 context: [^\n]*\n$"
           timing "${small}" --backend gl)
expect_run(0 "\ngl: unavailable: " "" info)
