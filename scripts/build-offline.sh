#!/usr/bin/env bash
# Builds dist/splinelab.html: the whole playground in one self-contained file (JS, CSS and wasm inlined) that
# opens from file:// by double-click and can be uploaded to an LMS as a single file. Usage: scripts/build-offline.sh
# (SKIP_WASM=1 reuses an existing www/pkg instead of rebuilding it).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${SKIP_WASM:-0}" != 1 ] || [ ! -f www/pkg/splinelab_bg.wasm ]; then scripts/build-wasm.sh; fi
node scripts/build-offline.mjs "${1:-dist/splinelab.html}"
