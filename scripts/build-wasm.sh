#!/usr/bin/env bash
# Builds the wasm module into www/pkg (for the page, --target web) and pkg-node (for Node, --target nodejs).
# Usage: scripts/build-wasm.sh [--dev]
#   Also builds one smaller module per group of demos into www/pkg/<group>/ (web target only; the groups and their
#   cargo features: www/lib/wasm-groups.js). WASM_SPLIT=0 skips them (then the pages fall back to the full module).
#   WASM_PROFILE=<profile>  build with another cargo profile (default `wasm-release`: opt-level 3, LTO; see Cargo.toml)
#   WASM_OPT_FLAGS=-O3     wasm-opt flags (default "-Os -ocimfs=0": inlining functions that have one caller makes the module smaller raw but larger gzipped); WASM_OPT=none skips wasm-opt
#   WASM_SIMD=0            build without wasm SIMD (simd128: Chrome 91+, Firefox 89+, Safari 16.4+, Node 16.4+)
# Measurements of each choice (size and speed): benches/README.md.
set -euo pipefail
cd "$(dirname "$0")/.."
profile=${WASM_PROFILE:-wasm-release}
[ "${1:-}" = "--dev" ] && profile=dev
if [ "${WASM_SIMD:-1}" = 1 ]; then
  export RUSTFLAGS="${RUSTFLAGS:-} -C target-feature=+simd128"
fi
dir=$profile; [ "$profile" = dev ] && dir=debug
wasm="${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/$dir/splinelab.wasm"   # (cargo builds into CARGO_TARGET_DIR when set)
# wasm-opt: Debian's binaryen 108 breaks wasm-bindgen's externref table; use a recent one (npm binaryen 123).
WASM_OPT=${WASM_OPT:-node_modules/.bin/wasm-opt}
optimise() { # $1: a wasm file, optimised in place
  if [ -x "$WASM_OPT" ] && [ "$profile" != dev ]; then
    "$WASM_OPT" ${WASM_OPT_FLAGS:--Os -ocimfs=0} --enable-reference-types --enable-multivalue --enable-bulk-memory \
      --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals --enable-simd \
      "$1" -o "$1.opt" && mv "$1.opt" "$1" || { rm -f "$1.opt"; echo "wasm-opt failed; keeping the unoptimised $1"; }
  fi
}

# The per-group modules first, the complete module last (so target/ ends with the default features, as cargo
# test and clippy use them). Each group rebuilds only this crate (its dependencies are shared).
# Two lanes where there are two cores (WASM_LANES=1: one): cargo's last phase (LTO, one codegen unit) keeps one
# core busy per build, so the first group builds alone (it compiles the dependencies on both cores), its target
# folders are copied for a second lane (target/lane-b: cargo finds the dependencies fresh there and rebuilds only
# this crate), and the other groups build two at a time, each lane running its own wasm-bindgen and wasm-opt.
lanes=${WASM_LANES:-$(( $(nproc) >= 2 ? 2 : 1 ))}
[ "$profile" = dev ] && lanes=1   # (a dev build is quick, and target/debug holds the native builds too: nothing to copy)
# build_group <target dir> <group> <features>
build_group() {
  local tdir=$1 group=$2 features=$3 start out
  start=$(date +%s)
  out="$tdir/wasm32-unknown-unknown/$dir/splinelab.wasm"
  CARGO_TARGET_DIR=$tdir cargo build --lib --target wasm32-unknown-unknown --profile "$profile" --no-default-features --features "$features"
  rm -rf "www/pkg/$group"
  wasm-bindgen --target web --no-typescript --out-dir "www/pkg/$group" "$out"
  optimise "www/pkg/$group/splinelab_bg.wasm"
  echo "group $group ($features): $(wc -c < "www/pkg/$group/splinelab_bg.wasm") bytes, $(( $(date +%s) - start )) s"
}
# The complete module (every export: the public API, the sandbox, the npm package, the exercise checks).
build_full() {
  cargo build --lib --target wasm32-unknown-unknown --profile "$profile"
  wasm-bindgen --target web --no-typescript --out-dir www/pkg "$wasm"
  # The TypeScript declarations are generated from the Rust bindings (src/api: api_options! structs, the
  # typescript_custom_sections and the exports' unchecked_param_type / unchecked_return_type): pkg-node/splinelab.d.ts,
  # which the npm package ships (scripts/pack-stage.mjs), copied to types/splinelab.d.ts (git-ignored) for the front end.
  wasm-bindgen --target nodejs --out-dir pkg-node "$wasm"
  mkdir -p types && cp pkg-node/splinelab.d.ts types/splinelab.d.ts
  echo '{ "type": "commonjs" }' > pkg-node/package.json
  optimise www/pkg/splinelab_bg.wasm && cp www/pkg/splinelab_bg.wasm pkg-node/splinelab_bg.wasm
  ls -l www/pkg/splinelab_bg.wasm
}
target=${CARGO_TARGET_DIR:-target}
if [ "${WASM_SPLIT:-1}" = 1 ]; then
  mapfile -t groups < <(node --input-type=module -e "import('./www/lib/wasm-groups.js').then((m) => { for (const [g, v] of Object.entries(m.WASM_GROUPS)) console.log(g + ' ' + v.features.join(',')); })")
  # shellcheck disable=SC2086
  build_group "$target" ${groups[0]}
  if [ "$lanes" -ge 2 ] && [ "${#groups[@]}" -gt 2 ]; then
    laneb="$target/lane-b"
    mkdir -p "$laneb/wasm32-unknown-unknown"
    for d in "$dir" "wasm32-unknown-unknown/$dir"; do
      [ -d "$target/$d" ] && { rm -rf "${laneb:?}/$d"; cp -a "$target/$d" "$laneb/$d"; }
    done
    # lane a ends with the complete module (in target/, so that it ends with the default features)
    ( for ((i = 2; i < ${#groups[@]}; i += 2)); do build_group "$target" ${groups[i]}; done; build_full ) &
    a=$!
    ( for ((i = 1; i < ${#groups[@]}; i += 2)); do build_group "$laneb" ${groups[i]}; done ) > "$laneb/build.log" 2>&1 &
    b=$!
    ok=0
    wait "$a" || ok=1
    wait "$b" || ok=1
    echo "--- lane b:"; cat "$laneb/build.log"
    [ "$ok" = 0 ] || { echo "a group build failed"; exit 1; }
  else
    for ((i = 1; i < ${#groups[@]}; i++)); do build_group "$target" ${groups[i]}; done
    build_full
  fi
else
  build_full
fi

