#!/bin/sh
# Builds the package and serves the playground: the one command from a fresh clone
# (`sh web/play.sh`). Installs what is missing on the way: the wasm32 target and
# wasm-bindgen-cli (through web/build.sh), and the npm packages of web/package-lock.json.
# Arguments go to Vite's dev server (for example `--port 8080` or `--host`).
set -eu

cd "$(dirname "$0")"
if ! command -v npm >/dev/null 2>&1; then
    echo "error: the playground needs Node.js 20.19 or later with npm (node, npm)" >&2
    exit 1
fi
sh build.sh
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
    npm ci --no-audit --no-fund
fi
exec npx vite --config playground/vite.config.js "$@"
