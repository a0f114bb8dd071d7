# spatial/README.md (the embedding guide) quotes tests/install/consumer/optimize_shadows.h, which
# install_tests compiles and runs against the installed package: the guide's copy must be the
# file's text between its two "// [readme]" lines, character for character. The quoted block is
# the ```cpp fence after the line "<!-- snippet: tests/install/consumer/optimize_shadows.h -->".
# Arguments: README, SNIPPET (the two files).
file(READ "${README}" readme)
file(READ "${SNIPPET}" source)

set(marker "<!-- snippet: tests/install/consumer/optimize_shadows.h -->\n```cpp\n")
string(FIND "${readme}" "${marker}" start)
if(start LESS 0)
    message(FATAL_ERROR "${README} has no line '<!-- snippet: tests/install/consumer/optimize_shadows.h -->' followed by a ```cpp fence")
endif()
string(LENGTH "${marker}" markerLength)
math(EXPR start "${start} + ${markerLength}")
string(SUBSTRING "${readme}" ${start} -1 rest)
string(FIND "${rest}" "\n```\n" end)
string(SUBSTRING "${rest}" 0 ${end} quoted)
string(APPEND quoted "\n")

set(open "// [readme]\n")
string(FIND "${source}" "${open}" first)
string(FIND "${source}" "${open}" second REVERSE)
if(first LESS 0 OR first EQUAL second)
    message(FATAL_ERROR "${SNIPPET} needs two '// [readme]' lines")
endif()
string(LENGTH "${open}" openLength)
math(EXPR first "${first} + ${openLength}")
math(EXPR length "${second} - ${first}")
string(SUBSTRING "${source}" ${first} ${length} snippet)

if(NOT quoted STREQUAL snippet)
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.quoted" "${quoted}")
    file(WRITE "${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.source" "${snippet}")
    message(FATAL_ERROR "The guide's snippet differs from ${SNIPPET}: compare "
                        "${CMAKE_CURRENT_BINARY_DIR}/readme_snippet.quoted and readme_snippet.source")
endif()
message(STATUS "The guide's snippet is ${SNIPPET} verbatim")
