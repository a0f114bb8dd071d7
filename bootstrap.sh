#!/usr/bin/env bash
# Set up a fresh Debian 12 machine for lexel, build it, and run the main job or the tests.
#   ./bootstrap.sh tables   install what is missing, build Release, run `lexel tables --out out`
#   ./bootstrap.sh test     install what is missing, build Release, run the whole test suite, then
#                           the sanitizer suite: build-asan (clang, ASan + UBSan, the fuzz targets)
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
          clang-14 libclang-rt-14-dev)
# The last line is the OpenGL backend (spatial/gl): EGL and GL through GLVND, libepoxy for the GL
# functions, and Mesa's EGL with its llvmpipe rasterizer, the GL path on machines without a GPU.
# clang and its runtimes (libFuzzer, the sanitizers) build the sanitizer suite of the test job.
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

# With the packages above a GL context can always be made (llvmpipe at worst), so the test job
# requires the OpenGL backend and its tests rather than letting them skip.
gl=AUTO
if [[ "$job" == "test" ]]; then
    gl=ON
    export LEXEL_REQUIRE_GL=1
fi
# The sanitizer suite (test job): clang with AddressSanitizer and UBSan in build-asan, on what reads
# input: the tests of the case and mesh loaders and the fuzz targets (a short fixed run each,
# tests/fuzz/). The whole suite does not fit CI's time under the sanitizers (solvers_tests alone
# took 640 s instead of a few seconds on the development machine), so only these are built and run.
sanitizer_tests='^(JsonReader|FlatlandCase|SpatialCase|SpatialCaseMeshEntry|CaseName|MeshLoader|PlyReader|GltfReader|MeshFrame|AllocationCap|Primitives|Transform|OutputSetTest|ReportNumbers|Containment)\.'
sanitizer_suite() {
    cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Asan -DCMAKE_CXX_COMPILER=clang++-14 \
        -DLEXEL_FUZZ=ON -DLEXEL_GL=OFF -DLEXEL_BUILD_BENCHMARKS=OFF -DLEXEL_BUILD_NOTEBOOKS=OFF
    cmake --build build-asan --parallel "$(nproc)" --target cases_tests spatial_tests \
        flatland_case_fuzzer spatial_case_fuzzer mesh_fuzzer ply_fuzzer gltf_fuzzer
    (cd build-asan && ctest --output-on-failure --parallel "$(nproc)" -R "$sanitizer_tests|_fuzzer\$")
}

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DLEXEL_GL="$gl"
cmake --build build --parallel "$(nproc)"

if [[ "$job" == "tables" ]]; then
    ./build/cases/lexel tables --out out
else
    (cd build && ctest --output-on-failure --parallel "$(nproc)")
    sanitizer_suite
fi
