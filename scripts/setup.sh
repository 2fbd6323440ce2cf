#!/usr/bin/env bash
# Installs what a fresh machine lacks, idempotently. Usage: scripts/setup.sh [--browser] [--npm]
#   always: the wasm32 target and the wasm-bindgen CLI of exactly the version in Cargo.lock
#   --browser: Debian's chromium and chromium-driver (for browser tests), and for the cross-engine smoke suite
#              (tests/cross/) firefox-esr, webkit2gtk-driver (WebKitWebDriver + MiniBrowser), xvfb and xauth
#   --npm: the npm dev dependencies (playwright-core, axe-core, binaryen, verb-nurbs) from package-lock.json
set -euo pipefail
cd "$(dirname "$0")/.."
want_browser=0; want_npm=0
for a in "$@"; do case "$a" in --browser) want_browser=1;; --npm) want_npm=1;; esac; done

rustup target list --installed 2>/dev/null | grep -q wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
cargo clippy --version >/dev/null 2>&1 || rustup component add clippy
[ -f Cargo.lock ] || cargo generate-lockfile
ver=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if ! wasm-bindgen --version 2>/dev/null | grep -q " $ver\$"; then
  echo "installing wasm-bindgen-cli $ver (about two minutes)"
  cargo install wasm-bindgen-cli --version "$ver"
fi
if [ $want_browser = 1 ] && { ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; }; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq chromium chromium-driver >/dev/null
fi
if [ $want_browser = 1 ] && { ! command -v firefox-esr >/dev/null || ! command -v WebKitWebDriver >/dev/null \
    || [ ! -x /usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser ] || ! command -v xvfb-run >/dev/null || ! command -v xauth >/dev/null; }; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq && apt-get install -y -qq firefox-esr webkit2gtk-driver xvfb xauth >/dev/null
fi
if [ $want_npm = 1 ] && [ -f package.json ]; then
  if [ ! -d node_modules ] || [ package-lock.json -nt node_modules ]; then
    if [ -f package-lock.json ]; then npm ci --no-audit --no-fund; else npm install --no-audit --no-fund; fi
  fi
fi
