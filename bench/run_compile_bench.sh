#!/usr/bin/env bash
# Issue 9's compile-time figures: `kerf check` on the 1000-sphere model written out as 1000
# lines (before the language had loops) and as a `random` loop (now), by a kerf from before the
# language changes (--kerf-baseline) and by this one, in one hyperfine run; and a loop that
# makes 100,000 spheres. Prints a Markdown table; writes nothing into the repository.
#   bench/run_compile_bench.sh --kerf-baseline /path/to/old/kerf [--runs N]
set -euo pipefail
cd "$(dirname "$0")/.."
baseline="" runs=20
while [[ $# -gt 0 ]]; do
    case "$1" in
        --kerf-baseline) baseline="$2"; shift 2 ;;
        --runs) runs="$2"; shift 2 ;;
        *) echo "run_compile_bench: unknown option $1" >&2; exit 2 ;;
    esac
done
command -v hyperfine >/dev/null || { echo "run_compile_bench: hyperfine is missing (apt-get install hyperfine)" >&2; exit 1; }
[[ -x "$baseline" ]] || { echo "run_compile_bench: --kerf-baseline must name a kerf executable" >&2; exit 2; }
KERF="${KERF:-build/kerf}"
[[ -x "$KERF" ]] || { echo "run_compile_bench: no kerf at $KERF (set KERF or build first)" >&2; exit 1; }

out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
# The model as it was before loops: the last commit whose box_minus_spheres.kerf was written out.
git show 339ce74:models/box_minus_spheres.kerf > "$out/written_out.kerf"
cp models/box_minus_spheres.kerf "$out/loop.kerf"
cat > "$out/loop100k.kerf" <<'KERF'
// 100,000 spheres from one loop (issue 9: compiles in under a second).
object union {
    for i in 0 .. 99999 {
        sphere { center <random(1, 3 * i) * 100, random(1, 3 * i + 1) * 100, random(1, 3 * i + 2) * 100> radius 0.1 }
    }
};
KERF
hyperfine -N -w 3 -r "$runs" --export-json "$out/h.json" \
    -n "before: written out, old kerf" "$baseline check $out/written_out.kerf" \
    -n "before: written out, this kerf" "$KERF check $out/written_out.kerf" \
    -n "now: loop, this kerf" "$KERF check $out/loop.kerf" \
    -n "100,000 spheres in a loop, this kerf" "$KERF check $out/loop100k.kerf" >&2
python3 - "$out/h.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"]
base = r[0]["median"]
print("| model and kerf | median s | mean ± sd s | user s | ÷ old kerf on the written-out model |")
print("|---|---:|---:|---:|---:|")
for x in r:
    print(f"| {x['command']} | {x['median']:.4f} | {x['mean']:.4f} ± {x['stddev']:.4f} | {x['user']:.4f} | {x['median']/base:.2f} |")
PY
