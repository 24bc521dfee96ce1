# Sourced by bench/run_bench.sh and bench/run_implicit_bench.sh from the repository root:
# bench_setup NAME checks the peer's tools and sets KERF (builds kerf when KERF is unset).
bench_setup() {
    local name="$1" tool candidate
    for tool in povray python3 cmake; do
        command -v "$tool" >/dev/null || { echo "$name: '$tool' is missing (apt-get install $tool)" >&2; exit 1; }
    done
    if [[ -z "${KERF:-}" ]]; then
        if [[ -x scripts/build ]]; then
            scripts/build
        else
            cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
            cmake --build build --target kerf -j"$(nproc)"
        fi
        for candidate in build/kerf build/app/kerf; do
            if [[ -x "$candidate" ]]; then KERF="$candidate"; break; fi
        done
    fi
    [[ -x "${KERF:-}" ]] || { echo "$name: no kerf executable (looked for build/kerf)" >&2; exit 1; }
}
