#!/usr/bin/env bash
# Builds the wasm module and serves the playground on http://127.0.0.1:${PORT:-8080}/
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build-wasm.sh
port=${PORT:-8080}
echo "SplineLab playground: http://127.0.0.1:$port/"
exec node scripts/static-server.mjs www "$port"
