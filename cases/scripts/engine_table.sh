#!/usr/bin/env bash
# The table of what engines ship (RESULTS.md, "What engines ship"): every shipped 3D case's
# point and directional lights (lexel sweep), each method's phase-averaged misclassified pixels
# against `optimal`, its effective storage factor, its cost and its shimmer along the first three
# poses of the case's camera path; then cases/scripts/engine_table.py prints the tables.
#
# Usage: cases/scripts/engine_table.sh LEXEL OUTDIR [LIGHTS [PHASES]]   (defaults 100 and 8)
# Run from the repository root. About an hour on 2 cores with the defaults; each sweep shows
# its progress on a terminal.
set -euo pipefail
if [[ $# -lt 2 || $# -gt 4 ]]; then
    echo "usage: cases/scripts/engine_table.sh LEXEL OUTDIR [LIGHTS [PHASES]]" >&2
    exit 2
fi
lexel=$1 out=$2 lights=${3:-100} phases=${4:-8}
methods=(optimal lispsm-engine sdsm tsm rtw rtw-lagrange logpsm vsm vsm-dynamic)
args=()
for m in "${methods[@]}"; do args+=(--method "$m"); done
mkdir -p "$out"
dirs=()
for scene in walkthrough courtyard street meshes; do
    for type in point directional; do
        dir="$out/${scene}_$type"
        "$lexel" sweep "cases/spatial/$scene.json" --lights "$lights" --light-type "$type" \
            --phases "$phases" --shimmer-poses 3 "${args[@]}" --out "$dir" > "$dir.txt"
        dirs+=("$dir")
    done
done
python3 "$(dirname "$0")/engine_table.py" "${dirs[@]}"
