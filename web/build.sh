#!/bin/sh
# Builds web/pkg/: the ES module tileslide.js, its tileslide_bg.wasm and the TypeScript
# types tileslide.d.ts, from crates/tileslide-wasm; web/pkg/speed/: the same built for speed
# (`import … from "tileslide/speed"`); web/playground-pkg/: the speed build with the
# `explain` feature (the bodies' and cells' explanations in words), which the playground's
# sandbox uses and the npm package leaves out; and web/games-pkg/: the demo games
# (tileslide_games.js, DungeonGame and PlatformerGame, for the playground; not part of the
# npm package), from crates/tileslide-games-wasm. Installs what it needs and lacks: the
# wasm32 target (through rustup) and wasm-bindgen-cli at the exact version of the
# wasm-bindgen crate (the two must match).
set -eu

cd "$(dirname "$0")"
root=..

if ! command -v cargo >/dev/null 2>&1 && [ -f "${CARGO_HOME:-$HOME/.cargo}/env" ]; then
    . "${CARGO_HOME:-$HOME/.cargo}/env"
fi

# The version Cargo.lock pins for the crate.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' "$root/Cargo.lock")
if [ -z "$want" ]; then
    echo "error: Cargo.lock names no wasm-bindgen version" >&2
    exit 1
fi

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
    echo "installing the wasm32-unknown-unknown target (rustup)" >&2
    rustup target add wasm32-unknown-unknown
fi

have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }' || true)
if [ "$have" != "$want" ]; then
    echo "installing wasm-bindgen-cli $want (found: ${have:-none})" >&2
    # Without its default `rustls-tls` feature: only the test runner's downloads use TLS,
    # and leaving it out skips building rustls and ring.
    cargo install wasm-bindgen-cli --version "$want" --no-default-features
fi

# SIMD128 (every current browser and Node 16.4+ run it) unless TILESLIDE_SIMD=0: the ray
# batch's step is written in SIMD128 intrinsics (query/ray_batch_simd128.rs; at opt-level
# "s" LLVM does not vectorize the lane loops itself), and the rays scene takes about 40 %
# less time than without (npm run bench).
if [ "${TILESLIDE_SIMD:-1}" = 1 ]; then
    export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+simd128"
fi
# Size: the package stays under 400 KB gzipped only if tileslide, whose loaders are half of
# the code, is optimized for size at any cost ("z": about 374 KB; "s" gave 401 KB once the
# character's corner rolls were made exact, and 449 KB at the release profile's level 3),
# as are the loaders' crates and the JavaScript glue. The glue's few lines on a hot path (a
# castRays ray's check and answer) are inlined by hand, so "z" costs them nothing. What
# "z" costs tileslide's own code in time, `npm run bench` measures (see web/README.md);
# `tileslide/speed` is the build for speed. The Node tests fail at 400 KB.
set -- --config "profile.release.package.tileslide.opt-level=\"z\""
for crate in tileslide-wasm tiled quick-xml serde serde_core serde_json flate2 miniz_oxide adler2 \
    simd-adler32 base64 indexmap hashbrown memchr itoa zmij crc32fast js-sys wasm-bindgen; do
    set -- "$@" --config "profile.release.package.$crate.opt-level=\"z\""
done
target_dir=$(cargo metadata --manifest-path "$root/Cargo.toml" --format-version 1 --no-deps \
    | sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
# Prints the size of web/$1, and gzipped; $2 says what else it is.
size_of() {
    echo "web/$1: $(wc -c < "$1") bytes, $(gzip -9 -c "$1" | wc -c) gzipped${2:+ $2}"
}

# One build each, with the same settings: built together, Cargo would unify their features of
# the core crate, and the games' (PNG tracing among them) would grow the package. The games
# build at the same time as the packages, in a target directory of their own: each build of
# the core crate runs on one core (one codegen unit), so two at once use both of a
# two-core machine. Its output is shown once it is done.
games_target=$target_dir/wasm-games
mkdir -p "$games_target"
cargo build --manifest-path "$root/Cargo.toml" --release --target wasm32-unknown-unknown \
    -p tileslide-games-wasm --target-dir "$games_target" "$@" >"$games_target/build.log" 2>&1 &
games=$!
trap 'kill "$games" 2>/dev/null || true' EXIT
cargo build --manifest-path "$root/Cargo.toml" --release --target wasm32-unknown-unknown \
    -p tileslide-wasm "$@"
rm -rf pkg
# --weak-refs: objects the garbage collector drops free their wasm memory through a
# FinalizationRegistry, as well as through .free().
# --remove-name-section: the release profile's debug lines leave a 130 KB name section.
wasm-bindgen --target web --weak-refs --remove-name-section --out-dir pkg --out-name tileslide \
    "$target_dir/wasm32-unknown-unknown/release/tileslide_wasm.wasm"
size_of pkg/tileslide_bg.wasm

# Built for speed: tileslide at the release profile's level 3, everything else as above (so
# the dependencies built for the package serve these builds too; cargo keeps both builds of
# tileslide side by side, and each wasm file is bound as soon as it is built).
# - web/pkg/speed/: the same package (`import … from "tileslide/speed"`): about 50 KB more
#   gzipped, and the rays scene in about three fifths of the time, a crowd step in about
#   three quarters (npm run bench).
# - web/playground-pkg/: the same with `explain`, for the playground, whose sandbox steps
#   10,000 bodies a frame. It comes first: both write tileslide_wasm.wasm.
set -- "$@" --config 'profile.release.package.tileslide.opt-level=3'
cargo build --manifest-path "$root/Cargo.toml" --release --target wasm32-unknown-unknown \
    -p tileslide-wasm --features explain "$@"
rm -rf playground-pkg
wasm-bindgen --target web --weak-refs --remove-name-section --out-dir playground-pkg --out-name tileslide \
    "$target_dir/wasm32-unknown-unknown/release/tileslide_wasm.wasm"
size_of playground-pkg/tileslide_bg.wasm "(explain; not the npm package)"
cargo build --manifest-path "$root/Cargo.toml" --release --target wasm32-unknown-unknown \
    -p tileslide-wasm "$@"
wasm-bindgen --target web --weak-refs --remove-name-section --out-dir pkg/speed --out-name tileslide \
    "$target_dir/wasm32-unknown-unknown/release/tileslide_wasm.wasm"
size_of pkg/speed/tileslide_bg.wasm

if ! wait "$games"; then
    cat "$games_target/build.log" >&2
    echo "error: the games' build failed (above)" >&2
    exit 1
fi
trap - EXIT
cat "$games_target/build.log"
rm -rf games-pkg
wasm-bindgen --target web --weak-refs --remove-name-section --out-dir games-pkg --out-name tileslide_games \
    "$games_target/wasm32-unknown-unknown/release/tileslide_games_wasm.wasm"
size_of games-pkg/tileslide_games_bg.wasm
