#!/usr/bin/env bash
# Set up a fresh Debian 12 machine for lexel, build it, and run the main job or the tests.
#   ./bootstrap.sh tables   install what is missing, build Release, run `lexel tables --out out`
#   ./bootstrap.sh test     install what is missing, check the C++ formatting, build Release with
#                           warnings as errors, run the whole test suite, then the sanitizer suite:
#                           build-asan (clang, ASan + UBSan, the fuzz targets)
# Both install the Python module (`import lexel`) where Debian's python3 finds it.
# Packages come from Debian 12 only; those already installed are skipped.
set -euo pipefail
cd "$(dirname "$0")"

job="${1:-}"
if [[ "$job" != "tables" && "$job" != "test" ]]; then
    echo "usage: $0 tables|test" >&2
    exit 2
fi

packages=(build-essential cmake ninja-build pkg-config
          libceres-dev libglm-dev libopenimageio-dev openimageio-tools libcli11-dev nlohmann-json3-dev
          libgtest-dev googletest libbenchmark-dev libcairo2-dev
          libtbb-dev libembree-dev libassimp-dev assimp-testmodels libtinygltf-dev libqhull-dev
          libegl-dev libopengl-dev libepoxy-dev libegl-mesa0 libgl1-mesa-dri
          clang-14 libclang-rt-14-dev clang-format-14
          python3-dev python3-numpy pybind11-dev python3-jsonschema)
# The libegl-dev … libgl1-mesa-dri line is the OpenGL backend (spatial/gl): EGL and GL through
# GLVND, libepoxy for the GL functions, and Mesa's EGL with its llvmpipe rasterizer, the GL path
# on machines without a GPU. clang and its runtimes (libFuzzer, the sanitizers) build the
# sanitizer suite of the test job; clang-format 14 is the formatter the tree is kept in
# (.clang-format). The last line is the Python module (spatial/python): Debian's python3 headers,
# numpy and pybind11; and jsonschema, which checks the case files against the case format's
# schema (cases/case.schema.json) in the test suite.
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "bootstrap: installing ${missing[*]}"
    sudo=""
    [[ $(id -u) -ne 0 ]] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# With the packages above a GL context can always be made (llvmpipe at worst), so both jobs build
# the OpenGL backend, and the test job requires its tests rather than letting them skip. Both
# build with warnings as errors (LEXEL_WERROR; Debian 12's GCC 12 is the compiler CI uses): the
# two jobs configure build/ alike, so `test` after `tables` compiles nothing again.
gl=ON
werror=ON
if [[ "$job" == "test" ]]; then
    export LEXEL_REQUIRE_GL=1
fi

# Each step of the test job says what it took: wall clock, and the CPU time of it and its children.
TIMEFORMAT="bootstrap: %R s wall, %U s user + %S s sys CPU"
step() {
    echo "bootstrap: $1"
    shift
    time "$@"
}

# The formatting check (test job): every tracked C++ file as clang-format 14 formats it.
format_check() {
    local files=()
    if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
        mapfile -d '' files < <(git ls-files -z '*.cpp' '*.h')
    else
        mapfile -d '' files < <(find solvers flatland spatial cases tests bench notebooks_cpp \
                                     \( -name '*.cpp' -o -name '*.h' \) -print0)
    fi
    clang-format-14 --dry-run -Werror "${files[@]}"
}

# The sanitizer suite (test job): clang with AddressSanitizer and UBSan in build-asan, on what reads
# input: input_tests (the tests of the case, name, mesh and output-set code, label `input`) and the
# fuzz targets (a short fixed run each, label `fuzz`, tests/fuzz/). The whole suite does not fit
# CI's time under the sanitizers (solvers_tests alone took 640 s instead of a few seconds on the
# development machine), so only these are built and run.
sanitizer_build() {
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Asan -DCMAKE_CXX_COMPILER=clang++-14 \
        -DLEXEL_FUZZ=ON -DLEXEL_WERROR="$werror" -DLEXEL_GL=OFF -DLEXEL_BUILD_BENCHMARKS=OFF \
        -DLEXEL_BUILD_NOTEBOOKS=OFF
    cmake --build build-asan --parallel "$(nproc)" --target input_tests \
        flatland_case_fuzzer spatial_case_fuzzer mesh_fuzzer ply_fuzzer gltf_fuzzer \
        sweep_record_fuzzer
}
sanitizer_tests() {
    (cd build-asan && ctest --output-on-failure --parallel "$(nproc)" -L '^(input|fuzz)$')
}

release_build() {
    cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DLEXEL_GL="$gl" -DLEXEL_WERROR="$werror" \
        -DLEXEL_PYTHON=ON
    cmake --build build --parallel "$(nproc)"
}
release_tests() {
    (cd build && ctest --output-on-failure --parallel "$(nproc)")
}

# The Python module into the interpreter's own dist-packages under /usr/local (Debian's python3
# has /usr/local/lib/python3.11/dist-packages on its path), so that `python3 -c "import lexel"`
# works from anywhere; checked with the interpreter it was built for.
python_install() {
    local python sudo=""
    python=$(sed -n 's/^Python3_EXECUTABLE:[A-Z]*=//p' build/CMakeCache.txt)
    [[ $(id -u) -ne 0 ]] && sudo="sudo"
    $sudo cmake --install build --component python
    (cd / && "$python" -c "import lexel, sys; print('bootstrap: import lexel works in', sys.executable)")
}

if [[ "$job" == "tables" ]]; then
    release_build
    python_install
    ./build/cases/lexel tables --out out
else
    step "formatting (clang-format 14)" format_check
    step "Release build" release_build
    step "the Python module's install" python_install
    step "the test suite" release_tests
    step "sanitizer build" sanitizer_build
    step "the sanitizer suite" sanitizer_tests
    echo "bootstrap: the test job took ${SECONDS} s"
fi
