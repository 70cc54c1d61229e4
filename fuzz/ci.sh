#!/bin/sh
# Runs every fuzz target of fuzz/ for FUZZ_SECONDS seconds each (10 unless set), from its
# committed seeds, with debug assertions and overflow checks, and fails on the first input
# that breaks a target's checks (libFuzzer writes it under fuzz/artifacts/TARGET/). What
# each run adds to its corpus is kept in target/fuzz-corpus/TARGET/, so runs on the same
# checkout go on from where the last one stopped. Needs the nightly toolchain (rustup);
# installs cargo-fuzz from crates.io when it is missing. See docs/fuzzing.md.
#
# CI builds without a sanitizer and with 16 codegen units, for build time: the targets are
# safe Rust over the library, whose unsafe blocks are a call (the AVX2 ray batch, which the
# `casts` target reaches) and a hint (the resolver's prefetch); a longer
# campaign (docs/fuzzing.md) runs with AddressSanitizer. With FUZZ_DEV=1 (as .ci/run sets
# it) the targets are built without optimisation: in about 60 s rather than 150 on two
# cores, for runs of a few seconds that try fewer inputs. With FUZZ_BUILD_ONLY=1 it builds
# the targets and stops (.ci/run builds them so beside its other steps).
set -eu

cd "$(dirname "$0")"
seconds=${FUZZ_SECONDS:-10}

if ! rustup toolchain list | grep -q '^nightly'; then
    echo "error: the fuzz targets need the nightly toolchain (rustup toolchain install nightly)" >&2
    exit 1
fi
# cargo-fuzz only runs cargo and the targets: built without optimisation, it installs in
# about half the time.
if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "installing cargo-fuzz (crates.io)" >&2
    cargo install --locked --debug cargo-fuzz --version 0.13.2
fi

if [ "${FUZZ_DEV:-0}" = 1 ]; then
    set -- --dev -a -s none
else
    set -- -O -a -s none
fi
cargo +nightly fuzz build "$@" --codegen-units 16
if [ "${FUZZ_BUILD_ONLY:-0}" = 1 ]; then
    exit 0
fi

logs=../target/fuzz-logs
rm -rf "$logs"
mkdir -p "$logs"
# The dictionary of target $1's text format (dict/), if it has one.
dictionary() {
    case $1 in
    ascii) echo ascii ;;
    tmx | tsx) echo tiled-xml ;;
    tmj | tsj) echo tiled-json ;;
    ldtk) echo ldtk ;;
    scene) echo scene ;;
    esac
}
# Runs target $1, writing its log and, when it fails, a file saying so.
run_one() {
    corpus=../target/fuzz-corpus/$1
    mkdir -p "$corpus"
    dict=$(dictionary "$1")
    if ! cargo +nightly fuzz run "$@" "$corpus" "corpus/$1" -- \
        -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
        ${dict:+-dict=dict/$dict.dict} >"$logs/$1.log" 2>&1; then
        touch "$logs/$1.failed"
    fi
}
# libFuzzer runs on one core: as many targets at a time as there are cores.
jobs=${FUZZ_JOBS:-$(nproc 2>/dev/null || echo 1)}
targets=$(cargo +nightly fuzz list)
echo "fuzzing $(echo "$targets" | wc -w) targets for $seconds s each, $jobs at a time"
running=0
for target in $targets; do
    run_one "$target" "$@" --codegen-units 16 &
    running=$((running + 1))
    if [ "$running" -ge "$jobs" ]; then
        wait
        running=0
    fi
done
wait
failed=""
for target in $targets; do
    done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$logs/$target.log" | tail -n 1 || true)
    echo "$target: ${done_line:-no final statistics}"
    if [ -e "$logs/$target.failed" ]; then
        # The finding: the check that failed, and where libFuzzer wrote the input.
        grep -vE '^(#[0-9]+[[:space:]]|INFO:|MS:|base unit:|0x|\\x)' "$logs/$target.log" | tail -n 40 >&2
        echo "fuzz $target: FAILED (the whole log: target/fuzz-logs/$target.log)" >&2
        failed="$failed $target"
    fi
done
if [ -n "$failed" ]; then
    echo "fuzz targets with findings:$failed" >&2
    exit 1
fi
echo "every fuzz target ran $seconds s without a finding"
