#!/usr/bin/env bash
# Builds the wasm module and the deployment build of the site (dist/site/, scripts/build-site.mjs: one module per
# page plus lazily loaded chunks, 9–10 requests for a demo page instead of ~49) and serves it on
# http://127.0.0.1:${PORT:-8080}/.  DEV=1 serves www/ as it is (plain ES modules, no build step: edit and reload).
set -euo pipefail
cd "$(dirname "$0")/.."
port=${PORT:-8080}
if [ "${DEV:-0}" = 1 ]; then
  scripts/setup.sh
  scripts/build-wasm.sh
  echo "SplineLab playground (the source, www/): http://127.0.0.1:$port/"
  exec node scripts/static-server.mjs www "$port"
fi
scripts/setup.sh --npm   # (esbuild, a devDependency, builds dist/site)
scripts/build-wasm.sh
node scripts/build-offline.mjs   # the one-file build, which the site carries for its SCORM packages (issue 27)
node scripts/build-site.mjs
echo "SplineLab playground (the built site, dist/site/): http://127.0.0.1:$port/"
exec node scripts/static-server.mjs dist/site "$port"
