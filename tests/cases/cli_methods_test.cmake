# Your own method: a case's clip matrices evaluated like every method. A matrix
# that `lexel run` prints, fed back as a case method, reproduces its method's numbers; CSV rows
# serve a sweep; bad matrices are refused in one line, exit 2; and a `lexel` built with
# tests/examples/my_method.cpp (CONTRIBUTING.md) knows its registered methods.
# Invoked by ctest with -DLEXEL=... -DLEXEL_MINE=... -DDATA=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")
set(expectRunTimeout 120)

# spatial_small (160 × 120, a 128² map) with a point and a directional light.
file(READ "${DATA}/spatial_small.json" small)
string(JSON small SET "${small}" lights
       "[{\"type\": \"point\", \"position\": [8, 8, 2]}, {\"type\": \"directional\", \"direction\": [-0.3, -1, 0.4]}]")
file(WRITE "${WORK}/two.json" "${small}")
expect_run(0 "" "" run "${WORK}/two.json" --no-map-truth --method focused-tight --method optimal
           --format json)
set(first "${lastStdout}")

# The printed matrices, fed back as methods mine-focused-tight and mine-optimal.
set(methods "[]")
foreach(m 0 1)
    string(JSON name GET "${first}" lights 0 methods ${m} method)
    string(JSON kind GET "${first}" lights 0 methods ${m} map_kind)
    if(NOT kind STREQUAL "single")
        message(FATAL_ERROR "${name}: map_kind ${kind}, expected single")
    endif()
    set(matrices "[]")
    foreach(l 0 1)
        string(JSON clip GET "${first}" lights ${l} methods ${m} clip_from_world)
        string(JSON matrices SET "${matrices}" ${l} "${clip}")
    endforeach()
    string(JSON methods SET "${methods}" ${m}
           "{\"name\": \"mine-${name}\", \"clip_from_world\": ${matrices}}")
endforeach()
string(JSON fed SET "${small}" methods "${methods}")
file(WRITE "${WORK}/fed.json" "${fed}")
expect_run(0 "" "" run "${WORK}/fed.json" --no-map-truth --method mine-focused-tight
           --method mine-optimal --format json)
set(second "${lastStdout}")
foreach(l 0 1)
    foreach(m 0 1)
        string(JSON name GET "${first}" lights ${l} methods ${m} method)
        string(JSON mine GET "${second}" lights ${l} methods ${m} method)
        if(NOT mine STREQUAL "mine-${name}")
            message(FATAL_ERROR "light ${l}: method ${m} is ${mine}, expected mine-${name}")
        endif()
        foreach(key misclassified false_shadow uncovered texels)
            string(JSON a GET "${first}" lights ${l} methods ${m} ${key})
            string(JSON b GET "${second}" lights ${l} methods ${m} ${key})
            if(NOT a STREQUAL b)
                message(FATAL_ERROR "light ${l} ${name}: ${key} ${a}, fed back ${b}")
            endif()
        endforeach()
        # h to 8 significant digits (the matrix goes through the clip form and back: rounding).
        string(JSON a GET "${first}" lights ${l} methods ${m} h)
        string(JSON b GET "${second}" lights ${l} methods ${m} h)
        string(SUBSTRING "${a}" 0 9 a)
        string(SUBSTRING "${b}" 0 9 b)
        if(NOT a STREQUAL b)
            message(FATAL_ERROR "light ${l} ${name}: h ${a}..., fed back ${b}...")
        endif()
        string(JSON a GET "${first}" lights ${l} methods ${m} misclassified)
        message(STATUS "light ${l} ${name}: ${a} misclassified, fed back the same")
    endforeach()
endforeach()
# By default `lexel run` includes the case's own methods (after the built-in ones).
expect_run(0 "\n1,mine-focused-tight,[0-9]+,[^\n]*\n1,mine-optimal," "" run "${WORK}/fed.json"
           --no-map-truth --format csv)

# A sweep's method from CSV: the first two lights of spatial_sweep_only's sweep, as fixed lights,
# give focused-tight's matrices; as clip_from_world_csv rows they reproduce focused-tight's counts.
expect_run(0 "" "" sweep "${DATA}/spatial_sweep_only.json" --lights 2 --method focused-tight
           --out "${WORK}/sweep1")
file(STRINGS "${WORK}/sweep1/lights.csv" rows)
set(lights "[]")
foreach(l 1 2)
    list(GET rows ${l} row)
    string(REPLACE "," ";" cells "${row}")
    list(GET cells 2 x)
    list(GET cells 3 y)
    list(GET cells 4 z)
    math(EXPR k "${l} - 1")
    string(JSON lights SET "${lights}" ${k} "{\"type\": \"point\", \"position\": [${x}, ${y}, ${z}]}")
endforeach()
file(READ "${DATA}/spatial_sweep_only.json" sweepOnly)
string(JSON fixed SET "${sweepOnly}" lights "${lights}")
file(WRITE "${WORK}/fixed.json" "${fixed}")
expect_run(0 "" "" run "${WORK}/fixed.json" --no-map-truth --method focused-tight --format json)
set(csv "# focused-tight of the first two sweep lights\n")
foreach(l 0 1)
    string(JSON clip GET "${lastStdout}" lights ${l} methods 0 clip_from_world)
    string(REGEX REPLACE "[][ \n]" "" clip "${clip}")
    string(APPEND csv "${clip}\n")
endforeach()
file(WRITE "${WORK}/mine.csv" "${csv}")
string(JSON sweepCase SET "${sweepOnly}" light_sweep count 2)
string(JSON sweepCase SET "${sweepCase}" methods
       "[{\"name\": \"mine\", \"clip_from_world_csv\": \"mine.csv\"}]")
file(WRITE "${WORK}/sweep_mine.json" "${sweepCase}")
expect_run(0 "" "" sweep "${WORK}/sweep_mine.json" --method focused-tight --method mine
           --out "${WORK}/sweep2")
file(STRINGS "${WORK}/sweep2/lights.csv" rows2)
list(GET rows2 0 header)
if(NOT header MATCHES ",focused-tight_misclassified,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,mine_misclassified,")
    message(FATAL_ERROR "lights.csv header: ${header}")
endif()
foreach(l 1 2)
    list(GET rows2 ${l} row)
    string(REPLACE "," ";" cells "${row}")
    list(GET cells 6 tight)
    list(GET cells 12 mine)
    list(GET rows ${l} row1)
    string(REPLACE "," ";" cells1 "${row1}")
    list(GET cells1 6 tight1)
    if(NOT tight STREQUAL mine OR NOT tight STREQUAL tight1)
        message(FATAL_ERROR "sweep light ${l}: focused-tight ${tight} (${tight1} before), mine ${mine}")
    endif()
endforeach()
# A shard takes each light's matrix by its index in the whole sweep: shard 1/2 holds light 1 only,
# whose `mine` is the CSV's second row and matches focused-tight there as in the whole sweep.
expect_run(0 "" "" sweep "${WORK}/sweep_mine.json" --method focused-tight --method mine
           --shard 1/2 --out "${WORK}/sweep3")
file(STRINGS "${WORK}/sweep3/lights.csv" rows3)
list(LENGTH rows3 rowCount3)
list(GET rows3 1 row3)
list(GET rows2 2 row2)
string(REPLACE "," ";" cells3 "${row3}")
string(REPLACE "," ";" cells2 "${row2}")
list(GET cells3 0 light3)
list(GET cells3 6 tight3)
list(GET cells3 12 mine3)
list(GET cells2 6 tight2)
if(NOT rowCount3 EQUAL 2 OR NOT light3 STREQUAL "1" OR NOT mine3 STREQUAL tight3
   OR NOT tight3 STREQUAL tight2)
    message(FATAL_ERROR "shard 1/2: ${rowCount3} rows, light ${light3}: focused-tight ${tight3} "
                        "(${tight2} unsharded), mine ${mine3}")
endif()
# By default the sweep includes it, in the fair comparison's table.
expect_run(0 "\nfair,all,mine,[0-9.]+," "" sweep "${WORK}/sweep_mine.json" --format csv)
# The sweep's method is not lexel run's, and --lights beyond its rows is refused.
expect_run(2 "^$" "/methods/0: 'mine' has one matrix per light of the light sweep \\(for lexel sweep\\), not per light of lexel run\n$"
           run "${WORK}/sweep_mine.json" --method mine)
expect_run(2 "^$" "/methods/0: 'mine' has 2 matrices, the sweep has 3 lights \\(--lights\\)\n$"
           sweep "${WORK}/sweep_mine.json" --method mine --lights 3)

# Bad matrices: one line naming the field, exit 2, nothing on stdout.
function(expect_refused what jsonText stderrRegex)
    file(WRITE "${WORK}/bad.json" "${jsonText}")
    expect_run(2 "^$" "^lexel: error: ${WORK}/bad\\.json: ${stderrRegex}\n$" run "${WORK}/bad.json"
               --no-map-truth --method normal)
endfunction()
string(JSON bad SET "${small}" methods "[{\"name\": \"mine\", \"clip_from_world\": [[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]]}]")
expect_refused(count "${bad}" "/methods/0/clip_from_world: has 1 matrices, expected one per light: 2 \\(the fixed lights, for lexel run\\) or 4 \\(light_sweep\\.count, for lexel sweep\\)")
string(JSON bad SET "${fed}" methods 0 name "\"optimal\"")
expect_refused(clash "${bad}" "/methods/0/name: 'optimal' clashes with a built-in method of that name; give yours another")
string(JSON bad SET "${fed}" methods 0 clip_from_world 1 3 "[0, 0, 0, 0]")
expect_refused(singular "${bad}" "/methods/0/clip_from_world/1: the matrix for light 1 is singular[^\n]*")
string(JSON bad SET "${fed}" methods 0 clip_from_world 0 3 1 "\"HUGE\"")
string(REPLACE "\"HUGE\"" "1e999" bad "${bad}")  # beyond CMake's JSON writer
file(WRITE "${WORK}/bad.json" "${bad}")
expect_run(2 "^$" "^lexel: error: ${WORK}/bad\\.json:[0-9]+:[0-9]+: /methods/0/clip_from_world/0/3/1: number 1e999 does not fit a double \\(numbers must be finite\\)\n$"
           run "${WORK}/bad.json" --method normal)
string(JSON m0 GET "${fed}" methods 0 clip_from_world 0)
string(JSON m1 GET "${fed}" methods 0 clip_from_world 1)
string(JSON bad SET "${fed}" methods 0 clip_from_world "[${m1}, ${m0}]")
expect_refused(wronglight "${bad}" "/methods/0/clip_from_world/0: the matrix for light 0 does not project from its light: row 1 does not send the point light to infinity[^\n]*")
file(WRITE "${WORK}/short.csv" "1,2,3\n")
string(JSON bad SET "${small}" methods "[{\"name\": \"mine\", \"clip_from_world_csv\": \"short.csv\"}]")
expect_refused(csv "${bad}" "/methods/0/clip_from_world_csv: short\\.csv:1: has 3 numbers, expected 16 \\(a 4x4 clip matrix, row-major\\)")

# A lexel built with tests/examples/my_method.cpp lists its methods and runs them; my-focused is
# focused-tight. The plain lexel does not know them.
set(LEXEL_PLAIN "${LEXEL}")
set(LEXEL "${LEXEL_MINE}")
expect_run(0 "\n  my-focused +focused-tight, registered from tests/examples/my_method\\.cpp\n  focused-wide " ""
           run --help)
expect_run(0 "" "" run "${WORK}/two.json" --no-map-truth --method focused-tight --method my-focused
           --format csv)
foreach(l 0 1)
    string(REGEX MATCH "\n${l},focused-tight,([0-9]+)," _ "${lastStdout}")
    set(tight "${CMAKE_MATCH_1}")
    string(REGEX MATCH "\n${l},my-focused,([0-9]+)," _ "${lastStdout}")
    if(tight STREQUAL "" OR NOT CMAKE_MATCH_1 STREQUAL tight)
        message(FATAL_ERROR "light ${l}: my-focused ${CMAKE_MATCH_1}, focused-tight ${tight}:\n${lastStdout}")
    endif()
endforeach()
set(LEXEL "${LEXEL_PLAIN}")
expect_run(2 "^$" "--method: unknown 3D method 'my-focused'" run "${WORK}/two.json" --method my-focused)

# `lexel methods`: the registry for scripts. Every built-in method once, in the reports' order
# (the fair table's first, optimal its reference), 31 of them; flatland's beside them.
expect_run(0 "" "" methods --format json)
set(listing "${lastStdout}")
string(JSON count LENGTH "${listing}" spatial)
string(JSON first GET "${listing}" spatial 0 name)
string(JSON firstFair GET "${listing}" spatial 0 traits fair_table)
string(JSON flatlandCount LENGTH "${listing}" flatland)
if(NOT count EQUAL 31 OR NOT first STREQUAL "optimal" OR NOT firstFair OR flatlandCount LESS 1)
    message(FATAL_ERROR "lexel methods --format json: ${count} methods, first ${first}:\n${listing}")
endif()
set(storageOf_sdsm-optimal-h "z-partitions-warped")
set(storageOf_logpsm "logpsm")
set(storageOf_tsm-report "trapezoid")
set(familyOf_sdsm-optimal-h "partitioned")
set(familyOf_logpsm "warped")
set(familyOf_tsm-report "trapezoid")
math(EXPR last "${count} - 1")
set(seen "")
foreach(i RANGE ${last})
    string(JSON name GET "${listing}" spatial ${i} name)
    string(JSON family GET "${listing}" spatial ${i} family)
    string(JSON model GET "${listing}" spatial ${i} storage_model)
    list(APPEND seen "${name}")
    if(DEFINED storageOf_${name} AND (NOT model STREQUAL storageOf_${name} OR
                                     NOT family STREQUAL familyOf_${name}))
        message(FATAL_ERROR "${name}: family ${family}, storage model ${model}")
    endif()
endforeach()
list(REMOVE_DUPLICATES seen)
list(LENGTH seen distinct)
if(NOT distinct EQUAL count)
    message(FATAL_ERROR "lexel methods --format json lists a method twice:\n${listing}")
endif()
expect_run(0 "^3D method +family +runs +storage model +description\noptimal +optimizer +by default +best-single-map +Algorithm 1" "" methods)
expect_run(2 "^$" "--format" methods --format yaml)

# A registered method is in the listing with its family and storage model, and `lexel storage`
# sets that model's analytic value beside it: my-focused is focused-tight, "no warp" both.
set(LEXEL "${LEXEL_MINE}")
expect_run(0 "" "" methods --format json)
string(JSON count LENGTH "${lastStdout}" spatial)
math(EXPR mine "${count} - 2")
string(JSON name GET "${lastStdout}" spatial ${mine} name)
string(JSON family GET "${lastStdout}" spatial ${mine} family)
string(JSON model GET "${lastStdout}" spatial ${mine} storage_model)
if(NOT count EQUAL 33 OR NOT name STREQUAL "my-focused" OR NOT family STREQUAL "registered" OR
   NOT model STREQUAL "unwarped")
    message(FATAL_ERROR "lexel_with_my_method methods: ${count}, ${name} ${family} ${model}")
endif()
expect_run(0 "" "" storage --case "${WORK}/two.json" --method focused-tight --method my-focused
           --format csv)
foreach(l 0 1)
    string(REGEX MATCH "\n${l},focused-tight,[^\n]*,(no warp,[^,]*,[^,]*)," _ "${lastStdout}")
    set(tight "${CMAKE_MATCH_1}")
    string(REGEX MATCH "\n${l},my-focused,[^\n]*,(no warp,[^,]*,[^,]*)," _ "${lastStdout}")
    if(tight STREQUAL "" OR NOT CMAKE_MATCH_1 STREQUAL tight)
        message(FATAL_ERROR "light ${l}: my-focused's scheme '${CMAKE_MATCH_1}', focused-tight's '${tight}':\n${lastStdout}")
    endif()
endforeach()
set(LEXEL "${LEXEL_PLAIN}")
