#!/usr/bin/env bash
# Heterogeneous media (docs/accuracy.md "Media", docs/BENCHMARKS.md "Fog volumes"):
#  1. transmittance error of each estimator against the analytic answer (constant slab, linear
#     ramp, exponential fog), per sample count or step;
#  2. noise (RMSE against a fine reference) against time for models/light_shafts.kerf;
#  3. OpenVDB's vdb_render against kerf on the same fog volume and camera, 1024², one core,
#     dense and 15× thinner: time, and transmittance error against a fine kerf reference.
# Times are CPU seconds (user + sys) of one-thread runs, from /usr/bin/time: the machine is
# shared, so wall time would measure the neighbours.
# Usage: bench/run_media_bench.sh [KERF [SECTIONS]] (default build/kerf, sections 123); writes
# into bench/out/media/.
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
KERF=$(realpath "${1:-$ROOT/build/kerf}")
SECTIONS=${2:-123}
OUT=$ROOT/bench/out/media
mkdir -p "$OUT"
cd "$OUT"
cmake -S "$ROOT/bench" -B "$ROOT/build-bench" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$ROOT/build-bench" --target media_bench > /dev/null
MB=$ROOT/build-bench/media_bench

cpu() {  # cpu LABEL CMD...: runs CMD, prints LABEL and its CPU seconds
    /usr/bin/time -f "%U %S" -o time.txt "${@:2}" > /dev/null 2> err.txt || { cat err.txt; exit 1; }
    printf "%-44s cpu %6.2f s\n" "$1" "$(awk '{print $1 + $2}' time.txt)"
}

if [[ $SECTIONS == *1* ]]; then
echo "== 1. transmittance against closed forms (64x64 parallel rays, T error per pixel)"
# Rays along +z through 0 <= z <= 2 (fov 0.01 degrees: lengths equal to 4e-9).
declare -A DENSITY=([constant]="0.6" [ramp]="0.1 + 0.5 * z" [exponential]="1.2 * exp(-z / 0.6)")
declare -A EXACT=([constant]="$(python3 -c 'import math; print(math.exp(-0.7*0.6*2))')"
                  [ramp]="$(python3 -c 'import math; print(math.exp(-0.7*(0.1*2+0.25*4)))')"
                  [exponential]="$(python3 -c 'import math; print(math.exp(-0.7*1.2*0.6*(1-math.exp(-2/0.6))))')")
for field in constant ramp exponential; do
    for cfg in "ratio 1" "ratio 4" "ratio 16" "ratio 64" "delta 1" "delta 4" "delta 16" "delta 64" \
               "march 0.2" "march 0.05" "march 0.01"; do
        set -- $cfg
        if [ "$1" = march ]; then method="method march step $2"; spp=1; else method="method $1"; spp=$2; fi
        cat > slab.kerf <<KERF
mist { density ${DENSITY[$field]} bounds box { min <-10, -10, 0> max <10, 10, 2> }
       extinction 0.7 albedo <0, 0, 0> $method }
background <1, 1, 1>;
camera { eye <0, 0, -1> look_at <0, 0, 1> fov 0.01 }
render { width 64 height 64 spp $spp }
KERF
        cpu "$field T=${EXACT[$field]} $cfg" "$KERF" render slab.kerf -o slab.exr --threads 1 -q
        echo "    $("$MB" const slab.exr "${EXACT[$field]}")"
    done
done

fi
if [[ $SECTIONS == *2* ]]; then
echo "== 2. light shafts: RMSE against a fine reference, 240x135"
SHAFTS=$ROOT/models/light_shafts.kerf
shafts() {  # shafts OUT.exr METHOD-LINE SPP
    sed -e "s|^    method march step 0.15$|    $2|" "$SHAFTS" > shafts.kerf
    cpu "$(basename "$1") $2 spp $3" "$KERF" render shafts.kerf -o "$1" --width 240 --height 135 --spp "$3" --threads 1 -q
}
shafts shafts_ref.exr "method march step 0.0375" 8
shafts shafts_ratio_ref.exr "method ratio samples 4" 256
echo "    ratio (1024 points/pixel) against the march reference: $("$MB" rmse shafts_ref.exr shafts_ratio_ref.exr)"
for spp in 1 4 16 64; do
    shafts s.exr "method ratio" "$spp"
    echo "    $("$MB" rmse shafts_ref.exr s.exr)"
done
for step in 0.6 0.3 0.15; do
    shafts s.exr "method march step $step" 2
    echo "    $("$MB" rmse shafts_ref.exr s.exr)"
done

fi
if [[ $SECTIONS == *3* ]]; then
echo "== 3. vdb_render against kerf, fog.vdb (256^3, voxel 2/256), 1024x1024, one core"
[ -f fog.vdb ] || "$MB" write-fog fog.vdb 256
CAM='camera { eye <0, 0, 3> look_at <0, 0, 0> up <0, 1, 0> fov 44.8 }'
# vdb_render: sigma_t = (absorb + scatter) per voxel per unit density, marched in voxel steps;
# kerf: extinction per unit length = (absorb + scatter) / voxel, albedo = scatter / sigma_t.
for medium in "dense 0.1 1.5 204.8" "thin 0.006667 0.1 13.653"; do
    set -- $medium
    name=$1 absorb=$2 scatter=$3 ext=$4
    albedo=$(python3 -c "print($scatter / ($absorb + $scatter))")
    cpu "vdb_render $name (defaults: step 1 voxel)" vdb_render fog.vdb "vdb_$name.exr" -res 1024x1024 \
        -translate 0,0,3 -lookat 0,0,0 -up 0,1,0 -cpus 1 -absorb $absorb,$absorb,$absorb -scatter $scatter,$scatter,$scatter
    printf 'mist { density volume "fog.vdb" extinction %s albedo <0, 0, 0> method march step 0.0009765625 }\nbackground <1, 1, 1>;\n%s\nrender { width 1024 height 1024 }\n' "$ext" "$CAM" > ref.kerf
    cpu "kerf $name T reference (march 1/8 voxel)" "$KERF" render ref.kerf -o "ref_$name.exr" --threads 1 -q
    echo "    vdb_render T error: $("$MB" trans "ref_$name.exr" "vdb_$name.exr" --alpha | head -1)"
    for method in "march step 0.03125" "march step 0.0625" "ratio"; do
        printf 'mist { density volume "fog.vdb" extinction %s albedo <%s, %s, %s> method %s }\nlight directional { direction <-0.7071, -0.7071, 0> color <0.7, 0.7, 0.7> }\n%s\nrender { width 1024 height 1024 }\n' \
            "$ext" "$albedo" "$albedo" "$albedo" "$method" "$CAM" > lit.kerf
        cpu "kerf $name lit, $method" "$KERF" render lit.kerf -o "kerf_$name.exr" --threads 1 -q
        sed -e 's/albedo <[^>]*>/albedo <0, 0, 0>/' -e 's/^light.*$/background <1, 1, 1>;/' lit.kerf > t.kerf
        "$KERF" render t.kerf -o t.exr --threads 1 -q
        echo "    kerf T error (same method, albedo 0): $("$MB" trans "ref_$name.exr" t.exr)"
    done
done
fi
