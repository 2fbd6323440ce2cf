#!/usr/bin/env bash
# Builds the npm package dist/splinelab-<version>.tgz (version from Cargo.toml) from the outputs of
# scripts/build-wasm.sh — www/pkg (--target web) and pkg-node (--target nodejs) — without building Rust again:
#   web/   the web build (ES module + .wasm)          node/  the Node build (CommonJS) + an ES-module wrapper
#   splinelab.d.ts  the TypeScript declarations generated from src/api (pkg-node/), web/splinelab.d.ts (npm/web.d.ts)
#   package.json (exports map), README.md and LICENSE (npm/)
# Usage: scripts/pack.sh [--build]   (--build, or missing outputs, runs scripts/build-wasm.sh first)
#   PACK_OUT=dir   where the .tgz goes (default dist/); the script prints its path as the last line.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--build" ] || [ ! -f www/pkg/splinelab.js ] || [ ! -f pkg-node/splinelab.js ]; then
  scripts/build-wasm.sh
fi
out=${PACK_OUT:-dist}
mkdir -p "$out"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
node scripts/pack-stage.mjs "$stage/package"
tgz=$(cd "$stage" && npm pack ./package --pack-destination "$stage" --silent --ignore-scripts | tail -n 1)
mv "$stage/$tgz" "$out/$tgz"
echo "$(cd "$out" && pwd)/$tgz"
