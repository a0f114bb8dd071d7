# The core's sources include nothing above the core (CONTRIBUTING.md, "Layout"): no file of
# solvers/, flatland/ or spatial/ outside their studies/, harness/, gl/ and python/ folders includes
# a header of the studies, the test bench, the OpenGL backend or the case layer. (The root
# CMakeLists.txt checks the core's links the same way when configuring.) And the case layer's
# folders include only those before them in the order plot, load, run, report, record, app,
# studies (each study in its own folder, which includes no other study; cases/main.cpp, the
# command line's entry point, registers them all).
# Arguments: ROOT, the source tree to check (the test of this script gives it a bad tree too).
set(forbidden "#include \"lexel/(cases|spatial/harness|spatial/gl|spatial/studies|flatland/studies)/")
file(GLOB core RELATIVE ${ROOT} ${ROOT}/solvers/*.h ${ROOT}/solvers/*.cpp ${ROOT}/flatland/*.h
     ${ROOT}/flatland/*.cpp ${ROOT}/spatial/*.h ${ROOT}/spatial/*.cpp)
if(NOT core)
    message(FATAL_ERROR "layers: no core sources under ${ROOT}")
endif()
set(violations)
foreach(file IN LISTS core)
    file(STRINGS ${ROOT}/${file} lines REGEX "${forbidden}")
    foreach(line IN LISTS lines)
        list(APPEND violations "${file}: ${line}")
    endforeach()
endforeach()
# The case layer, folder by folder: none includes a folder after it.
set(caseFolders plot load run report record app studies)
set(caseSources 0)
foreach(folder IN LISTS caseFolders)
    list(POP_FRONT caseFolders)
    if(NOT caseFolders)
        break()
    endif()
    list(JOIN caseFolders "|" above)
    file(GLOB sources RELATIVE ${ROOT} ${ROOT}/cases/${folder}/*.h ${ROOT}/cases/${folder}/*.cpp)
    foreach(file IN LISTS sources)
        math(EXPR caseSources "${caseSources} + 1")
        file(STRINGS ${ROOT}/${file} lines REGEX "#include \"lexel/cases/(${above})/")
        foreach(line IN LISTS lines)
            list(APPEND violations "${file}: ${line}")
        endforeach()
    endforeach()
endforeach()
# A study's folder includes no other study's.
file(GLOB_RECURSE studySources RELATIVE ${ROOT} ${ROOT}/cases/studies/*.h ${ROOT}/cases/studies/*.cpp)
foreach(file IN LISTS studySources)
    math(EXPR caseSources "${caseSources} + 1")
    string(REGEX REPLACE "^cases/studies/([^/]+)/.*" "\\1" study "${file}")
    file(STRINGS ${ROOT}/${file} lines REGEX "#include \"lexel/cases/studies/")
    foreach(line IN LISTS lines)
        if(NOT line MATCHES "lexel/cases/studies/${study}/")
            list(APPEND violations "${file}: ${line}")
        endif()
    endforeach()
endforeach()
# The teaching programs draw with the plotting module and read the shipped cases with the loader;
# they include nothing of the command line's other layers.
file(GLOB_RECURSE notebooks RELATIVE ${ROOT} ${ROOT}/notebooks_cpp/*.h ${ROOT}/notebooks_cpp/*.cpp)
foreach(file IN LISTS notebooks)
    file(STRINGS ${ROOT}/${file} lines REGEX "#include \"lexel/cases/(run|report|record|app)/")
    foreach(line IN LISTS lines)
        list(APPEND violations "${file}: ${line}")
    endforeach()
endforeach()
if(violations)
    list(JOIN violations "\n  " text)
    message(FATAL_ERROR "layers: sources include headers above their layer:\n  ${text}")
endif()
list(LENGTH core count)
message(STATUS "layers: ${count} core sources include only the core, ${caseSources} case-layer "
               "sources only the folders before theirs")
