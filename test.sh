#!/usr/bin/env bash
# Every test of tileslide: the Rust workspace's (with the CLI's peer benchmarks and the core
# crate's serde round trips), then the web package's (web/: built from
# crates/tileslide-wasm, tested in Node). Installs what the web build lacks (the wasm32
# target, wasm-bindgen-cli; see web/build.sh). Both parts run; the exit status is non-zero
# if either failed.
set -uo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")"
if ! command -v cargo >/dev/null 2>&1 && [ -f "${CARGO_HOME:-$HOME/.cargo}/env" ]; then
    # shellcheck disable=SC1091
    . "${CARGO_HOME:-$HOME/.cargo}/env"
fi

status=0
cargo test --workspace --features tileslide-cli/peers,tileslide/serde || status=1
if ! command -v node >/dev/null 2>&1; then
    echo "error: the web tests need Node.js 18 or later (node)" >&2
    exit 1
fi
(sh web/build.sh && cd web && node --test test/) || status=1
exit $status
