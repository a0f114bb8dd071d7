# Scenes from the wild. `lexel mesh-info` on real glTF and PLY models of Debian's
# assimp-testmodels, with and without a case; the shipped formats.json case run end to end; and
# malformed meshes refused in one line, exit 2, nothing on stdout.
# Invoked by ctest with -DLEXEL=... -DCASES=... -DWORK=...
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include("${CMAKE_CURRENT_LIST_DIR}/cli_expect_run.cmake")
set(expectRunTimeout 120)
set(models /usr/share/assimp/models)
if(NOT IS_DIRECTORY ${models})
    message(FATAL_ERROR "${models} is missing: install the Debian package assimp-testmodels")
endif()
set(any "[^\n]*")

set(engine ${models}/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb)
expect_run(0 "^file: ${engine}\nformat: glTF 2\\.0 \\(binary\\)\nvertices: 84657\ntriangles: 121496\nbounds \\(file units\\): \\[-371\\.692, -180\\.972, -140\\] \\.\\. \\[371\\.692, 92\\.0416, 128\\], size \\[743\\.384, 273\\.013, 268\\]\nup axis: y \\(the default${any}\n$"
           "^$" mesh-info ${engine})
# With the case: units mm, then scale 5, a turn of 30° about y and the translation (-2, 0.905, 4).
expect_run(0 "\n${any}formats\\.json /geometry/1:\n  up axis: y, units: 0\\.001 scene units per file unit\n  bounds \\(scene axes and units\\): \\[-0\\.371692, -0\\.180972, -0\\.14\\] \\.\\. \\[0\\.371692, 0\\.0920416, 0\\.128\\]${any}\n  bounds \\(world, after the transform\\): \\[-3\\.83176, 0\\.000142212, 2\\.77114\\] \\.\\. \\[-0\\.16802, 1\\.36521, 5\\.22888\\]${any}\n$"
           "^$" mesh-info ${engine} --case "${CASES}/spatial/formats.json")
expect_run(0 "^file: ${any}\nformat: PLY \\(ASCII\\)\nvertices: 11184\ntriangles: 3732\n" "^$"
           mesh-info ${models}/PLY/Wuson.ply)
expect_run(0 "format: PLY \\(binary little-endian\\)\nvertices: 8\ntriangles: 12\nbounds \\(file units\\): \\[0, 0, 0\\] \\.\\. \\[1, 1, 1\\]"
           "^$" mesh-info ${models}/PLY/cube_binary.ply)

# A Z-up model in centimetres: the tetrahedron's apex (0, 0, 300) is 3 m up in the scene.
file(WRITE "${WORK}/tetra.ply" "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n100 0 0\n0 200 0\n0 0 300\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
file(WRITE "${WORK}/zup.json" "{\"camera\": {\"position\": [0, 1.7, -10], \"target\": [0, 1, 0], \"fov_y_deg\": 50, \"width\": 64, \"height\": 48}, \"lights\": [{\"type\": \"directional\", \"direction\": [0, -1, 0.2]}], \"geometry\": [{\"primitive\": \"plane\", \"transform\": {\"scale\": 20}}, {\"mesh\": \"tetra.ply\", \"up\": \"z\", \"units\": \"cm\", \"transform\": {\"translate\": [1, 0, 0]}}]}")
expect_run(0 "zup\\.json /geometry/1:\n  up axis: z, units: 0\\.01 scene units per file unit\n  bounds \\(scene axes and units\\): \\[0, 0, -2\\] \\.\\. \\[1, 3, 0\\], size \\[1, 3, 2\\]\n  bounds \\(world, after the transform\\): \\[1, 0, -2\\] \\.\\. \\[2, 3, 0\\], size \\[1, 3, 2\\]\n$"
           "^$" mesh-info "${WORK}/tetra.ply" --case "${WORK}/zup.json")

# The shipped case of glTF and PLY models runs (two fixed lights; focused only, to keep it short).
expect_run(0 "^light 0: point \\(12, 25, -8\\)${any}\n +false +false${any}\nmethod +misclassified${any}\n-+\nfocused +[0-9]+ ${any}\n\nlight 1: directional"
           "^$" run "${CASES}/spatial/formats.json" --no-map-truth --method focused)

# Refusals: one line, exit 2, nothing on stdout.
expect_run(2 "^$" "^lexel: error: ${models}/PLY/issue623\\.ply: cannot read PLY: vertex 0 of 24, property 'vertex_indices' \\(line 14\\): '7\\.941797' is not an integer of type uchar\n$"
           mesh-info ${models}/PLY/issue623.ply)
expect_run(2 "^$" "^lexel: error: ${models}/glTF2/RecursiveNodes/RecursiveNodes\\.gltf: cannot read glTF: node 0 is reached twice from the scene${any}\n$"
           mesh-info ${models}/glTF2/RecursiveNodes/RecursiveNodes.gltf)
expect_run(2 "^$" "^lexel: error: --case: ${any}formats\\.json has no mesh entry for ${models}/PLY/cube\\.ply \\(its mesh entries: /geometry/1 ${any}\\)\n$"
           mesh-info ${models}/PLY/cube.ply --case "${CASES}/spatial/formats.json")
expect_run(2 "^$" "^lexel: error: ${WORK}/missing\\.glb: mesh file not found\n$"
           mesh-info "${WORK}/missing.glb")
# In a case the same refusals name the entry; nothing is written.
file(READ "${CASES}/spatial/formats.json" formats)
string(REPLACE "PLY/cube_binary.ply" "glTF2/IndexOutOfRange/IndexOutOfRange.gltf" bad "${formats}")
file(WRITE "${WORK}/bad/formats.json" "${bad}")
expect_run(2 "^$" "^lexel: error: ${WORK}/bad/formats\\.json: /geometry/4/mesh: ${models}/glTF2/IndexOutOfRange/IndexOutOfRange\\.gltf: cannot read glTF: mesh 0 primitive 0: index 255 is past its 24 vertices\n$"
           run "${WORK}/bad/formats.json" --out "${WORK}/bad/out")
string(REPLACE "\"units\": 0.8" "\"units\": \"furlong\"" bad "${formats}")
file(WRITE "${WORK}/bad/formats.json" "${bad}")
expect_run(2 "^$" "^lexel: error: ${WORK}/bad/formats\\.json: /geometry/4/units: must be one of m, cm, mm, km, in, ft or a positive number, got 'furlong'\n$"
           run "${WORK}/bad/formats.json" --out "${WORK}/bad/out")
if(EXISTS "${WORK}/bad/out")
    message(FATAL_ERROR "a refused run wrote ${WORK}/bad/out")
endif()
