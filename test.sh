#!/usr/bin/env bash
# Every test of tileslide: the Rust workspace's (with the CLI's peer benchmarks, the core
# crate's serde round trips, and the Bevy plugin's debug drawing and hot reload), the C
# API's in C (examples/c), the Python package's (crates/tileslide-py, pytest), then the web
# package's (web/: built from crates/tileslide-wasm, tested in Node) and the playground's
# (web/playground, built with Vite and played in headless Chromium). Installs what the
# Python and web builds lack (maturin, NumPy and pytest in a virtual environment in
# target/py; the wasm32 target, wasm-bindgen-cli, see web/build.sh; the npm packages of
# web/package-lock.json).
# Every part runs; the exit status is non-zero if any failed.
set -uo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")"
if ! command -v cargo >/dev/null 2>&1 && [ -f "${CARGO_HOME:-$HOME/.cargo}/env" ]; then
    # shellcheck disable=SC1091
    . "${CARGO_HOME:-$HOME/.cargo}/env"
fi

status=0
cargo test --workspace --no-fail-fast --features tileslide-cli/peers,tileslide/serde,tileslide-bevy/debug,tileslide-bevy/hot_reload || status=1
# The C API's tests and example in C, under AddressSanitizer and UndefinedBehaviorSanitizer
# (the system's C compiler and make; examples/c/Makefile builds the static library first).
make -C examples/c test || status=1
# The Python package's tests (crates/tileslide-py/test.sh: a virtual environment in
# target/py with maturin, NumPy and pytest from PyPI, the wheel built and installed, pytest).
crates/tileslide-py/test.sh || status=1
if ! command -v node >/dev/null 2>&1; then
    echo "error: the web tests need Node.js 20.19 or later (node)" >&2
    exit 1
fi
if sh web/build.sh; then
    (cd web && node --test test/*.test.mjs) || status=1
    # The playground in Chromium (Debian's, /usr/bin/chromium; .ci/run installs it), driven
    # by playwright-core from web/node_modules.
    (cd web && npm ci --no-audit --no-fund && npm run test:browser) || status=1
else
    status=1
fi
exit $status
