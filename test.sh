#!/usr/bin/env bash
# Every test of tileslide: the Rust workspace's (with the CLI's peer benchmarks, the core
# crate's serde round trips and its `parallel` feature, whose tests compare 1, 2, 3 and 8
# threads, and the Bevy plugin's debug drawing and hot reload), the C
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
# Runs "$@" as the part named $1 and says how long it took; a failure fails the whole run
# (and this call, for a part that others need).
part() {
    name=$1
    shift
    start=$SECONDS
    if "$@"; then
        echo "--- test.sh: $name ok ($((SECONDS - start)) s)"
    else
        echo "--- test.sh: $name FAILED ($((SECONDS - start)) s)" >&2
        status=1
        return 1
    fi
}
# (.ci/run reads this line: its golden-release step builds with the same features.)
test_features=tileslide-cli/peers,tileslide/serde,tileslide/parallel,tileslide-bevy/debug,tileslide-bevy/hot_reload
part rust cargo test --workspace --no-fail-fast --features "$test_features"
# The programs the Python and web tests run for the native answers they compare with (the
# scenes' exports, the reference picture): built with the same features, so Cargo links
# them against the libraries it has just built (`cargo run -p …` from those tests would
# build the core crate again for each, with fewer features: half a minute apiece), and
# handed to the tests through TILESLIDE_PROGRAMS. Without it they use `cargo run`.
programs=${CARGO_TARGET_DIR:-target}/debug
case $programs in /*) ;; *) programs=$PWD/$programs ;; esac
if part programs cargo build --workspace --bins --examples --tests --features "$test_features"; then
    export TILESLIDE_PROGRAMS=$programs
fi
# The C API's tests and example in C, under AddressSanitizer and UndefinedBehaviorSanitizer
# (the system's C compiler and make), against the C library of the Rust tests' build: the
# libraries and tests of the whole workspace with the same features, which Cargo finds built
# (the C library's own `cargo build -p tileslide-capi` would build the core crate again,
# with fewer features, for about a minute).
part c make -C examples/c test \
    CAPI_CARGO_ARGS="--workspace --lib --tests --features $test_features"
# The Python package's tests (crates/tileslide-py/test.sh: a virtual environment in
# target/py with maturin, NumPy and pytest from PyPI, the wheel built and installed, pytest).
part python crates/tileslide-py/test.sh
if ! command -v node >/dev/null 2>&1; then
    echo "error: the web tests need Node.js 20.19 or later (node)" >&2
    exit 1
fi
if part web-build sh web/build.sh; then
    # A test file at a time per core (Node's default leaves one core free: on two cores,
    # one file at a time).
    part web-node sh -c 'cd web && node --test --test-concurrency="$(nproc)" test/*.test.mjs'
    # The playground in Chromium (Debian's, /usr/bin/chromium; .ci/run installs it), driven
    # by playwright-core from web/node_modules.
    part browser sh -c 'cd web && npm ci --no-audit --no-fund && npm run test:browser'
fi
exit $status
