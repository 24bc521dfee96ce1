#!/usr/bin/env bash
# app/cmake_install: `cmake --install BUILD --prefix P` lays out P/bin/kerf and
# P/lib/kerf/kerf_image_plugin.so; moved elsewhere, the installed kerf renders the same pixels
# as the build tree's kerf (the PNG files are byte-identical).
#   cmake_install_test.sh BUILD_DIR BUILD_KERF
set -euo pipefail
build=$1
built_kerf=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
test -x "$tmp/prefix/bin/kerf"
test -f "$tmp/prefix/lib/kerf/kerf_image_plugin.so"
mkdir "$tmp/elsewhere"
mv "$tmp/prefix" "$tmp/elsewhere/kerf"
cat > "$tmp/ball.kerf" <<'MODEL'
object sphere { center <0, 0, 0> radius 1 };
camera { eye <0, 0, -5> look_at <0, 0, 0> fov 40 }
light point { at <-3, 4, -5> power 400 }
render { width 8 height 6 }
MODEL
cd "$tmp"
"$tmp/elsewhere/kerf/bin/kerf" render ball.kerf -o installed.png --quiet
"$built_kerf" render ball.kerf -o built.png --quiet
cmp installed.png built.png
echo "cmake_install: installed kerf renders as the build tree's does"
