# The README's picture caption against the command beside it: the misclassified pixels it states
# for focused-tight and optimal on the walkthrough's light 1 are what `lexel run` prints now, so a
# change that moves them fails here until the caption (and cases/figures/tour.png, the two
# `walkthrough_light1_*_errors.png` of the tour's third command side by side) is remade.
# Invoked by ctest with -DLEXEL=... -DSOURCE=... (the source tree).
file(READ "${SOURCE}/README.md" readme)
string(REGEX MATCH "focused map \\(left, ([0-9,]+) pixels\\) and lexel's[ \n]+optimized light matrix \\(right, ([0-9,]+)\\)"
       caption "${readme}")
if(NOT caption)
    message(FATAL_ERROR "README.md: the tour picture's caption with its two counts was not found")
endif()
string(REPLACE "," "" captionFocused "${CMAKE_MATCH_1}")
string(REPLACE "," "" captionOptimal "${CMAKE_MATCH_2}")
execute_process(COMMAND "${LEXEL}" run "${SOURCE}/cases/spatial/walkthrough.json" --method optimal
                        --method focused-tight --no-map-truth --format csv
                RESULT_VARIABLE code OUTPUT_VARIABLE csv ERROR_VARIABLE err TIMEOUT 600)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "lexel run walkthrough.json: exit ${code}: ${err}")
endif()
foreach(pair "focused-tight|${captionFocused}" "optimal|${captionOptimal}")
    string(REPLACE "|" ";" pair "${pair}")
    list(GET pair 0 method)
    list(GET pair 1 stated)
    string(REGEX MATCH "\n1,${method},([0-9]+)," row "${csv}")
    if(NOT row)
        message(FATAL_ERROR "lexel run printed no light 1 row for ${method}:\n${csv}")
    endif()
    if(NOT CMAKE_MATCH_1 EQUAL stated)
        message(FATAL_ERROR "README.md's tour caption says ${method} misclassifies ${stated} "
                            "pixels on light 1; lexel run prints ${CMAKE_MATCH_1}")
    endif()
endforeach()
