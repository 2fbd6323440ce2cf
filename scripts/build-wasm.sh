#!/usr/bin/env bash
# Builds the wasm module into www/pkg (for the page, --target web) and pkg-node (for Node, --target nodejs).
# Usage: scripts/build-wasm.sh [--dev]
set -euo pipefail
cd "$(dirname "$0")/.."
profile=release; flag=--release
[ "${1:-}" = "--dev" ] && { profile=debug; flag=; }
cargo build --lib --target wasm32-unknown-unknown $flag
wasm=target/wasm32-unknown-unknown/$profile/splinelab.wasm
wasm-bindgen --target web --no-typescript --out-dir www/pkg "$wasm"
wasm-bindgen --target nodejs --no-typescript --out-dir pkg-node "$wasm"
echo '{ "type": "commonjs" }' > pkg-node/package.json
# wasm-opt: Debian's binaryen 108 breaks wasm-bindgen's externref table; use a recent one (npm binaryen) if present.
WASM_OPT=${WASM_OPT:-node_modules/.bin/wasm-opt}
if [ -x "$WASM_OPT" ] && [ "$profile" = release ]; then
  "$WASM_OPT" -O3 --enable-reference-types --enable-multivalue --enable-bulk-memory --enable-nontrapping-float-to-int \
    --enable-sign-ext --enable-mutable-globals www/pkg/splinelab_bg.wasm -o www/pkg/splinelab_bg.wasm \
    && cp www/pkg/splinelab_bg.wasm pkg-node/splinelab_bg.wasm || echo "wasm-opt failed; keeping the unoptimised module"
fi
ls -l www/pkg/splinelab_bg.wasm
