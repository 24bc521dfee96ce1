# Sourced by the bench/run_*.sh scripts.
# absolute PATH: PATH made absolute against the caller's directory.
absolute() { [[ "$1" = /* ]] && echo "$1" || echo "$PWD/$1"; }

# bench_absolute_env: KERF and BENCH_BUILD, when set, made absolute; call it before the script
# changes to the repository root, since paths in the environment are the caller's.
bench_absolute_env() {
    if [[ -n "${KERF:-}" ]]; then KERF="$(absolute "$KERF")"; fi
    if [[ -n "${BENCH_BUILD:-}" ]]; then BENCH_BUILD="$(absolute "$BENCH_BUILD")"; fi
}

# bench_setup NAME (from the repository root) checks the peer's tools and sets KERF (builds
# kerf when KERF is unset).
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
