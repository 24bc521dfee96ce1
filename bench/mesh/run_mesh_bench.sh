#!/bin/sh
# kerf mesh on the cup and the gyroid ball at two voxel sizes (time, triangles, distance to the
# surface, volumes from --stats), and OpenSCAD's STL export of the same cup for comparison.
# Usage: bench/mesh/run_mesh_bench.sh [build/kerf]   (writes into a temporary folder)
set -eu
KERF=${1:-build/kerf}
HERE=$(dirname "$0")
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
for case in "$HERE/cup.kerf 0.02" "$HERE/cup.kerf 0.01" \
            "models/gyroid_sphere.kerf 0.02" "models/gyroid_sphere.kerf 0.01"; do
    set -- $case
    echo "== kerf mesh $1 --voxel $2"
    /usr/bin/time -f "wall %e s, max RSS %M KB" "$KERF" mesh "$1" -o "$OUT/m.stl" --voxel "$2" --stats 2>&1 |
        grep -E "triangles|hausdorff|volume|time|wall"
done
if command -v openscad >/dev/null; then
    for fn in 64 256; do
        echo "== openscad cup.scad -D \$fn=$fn -o cup.stl"
        /usr/bin/time -f "wall %e s, max RSS %M KB" openscad -D "\$fn=$fn" -o "$OUT/cup.stl" "$HERE/cup.scad" 2>&1 |
            grep -E "wall|Facets|Volumes|Simple" || true
        echo "facets: $(grep -c 'facet normal' "$OUT/cup.stl" || true)"
    done
fi
