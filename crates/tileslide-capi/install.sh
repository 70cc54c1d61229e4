#!/bin/sh
# Installs tileslide's C library under PREFIX: lib/libtileslide_capi.a and .so,
# include/tileslide.h and lib/pkgconfig/tileslide.pc, after building it with cargo
# (release; --debug for the debug build). Then:
#
#   cc app.c $(PKG_CONFIG_PATH=PREFIX/lib/pkgconfig pkg-config --cflags --libs tileslide)
#
# usage: crates/tileslide-capi/install.sh PREFIX [--debug]
#
# CAPI_CARGO_ARGS, when set, replaces `-p tileslide-capi` as what cargo builds: ./test.sh
# sets it to the workspace's test build, whose library (the same code, with the features the
# test build turns on) is then already built.
set -eu

if [ $# -lt 1 ]; then
    echo "usage: $0 PREFIX [--debug]" >&2
    exit 2
fi
prefix=$1
profile=release
if [ "${2:-}" = "--debug" ]; then
    profile=debug
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$prefix"
prefix=$(cd "$prefix" && pwd)

# Word-split on purpose: a list of cargo arguments.
# shellcheck disable=SC2086
if [ "$profile" = release ]; then
    cargo build --manifest-path "$root/Cargo.toml" --release ${CAPI_CARGO_ARGS:--p tileslide-capi}
else
    cargo build --manifest-path "$root/Cargo.toml" ${CAPI_CARGO_ARGS:--p tileslide-capi}
fi
target_dir=$(cargo metadata --manifest-path "$root/Cargo.toml" --format-version 1 --no-deps \
    | sed -n 's/.*"target_directory":"\([^"]*\)".*/\1/p')
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$root/Cargo.toml" | head -n 1)

mkdir -p "$prefix/lib/pkgconfig" "$prefix/include"
cp "$target_dir/$profile/libtileslide_capi.a" "$target_dir/$profile/libtileslide_capi.so" \
    "$prefix/lib/"
cp "$root/include/tileslide.h" "$prefix/include/"
# Libs.private: what the Rust standard library in the static library needs on Linux.
cat > "$prefix/lib/pkgconfig/tileslide.pc" <<PC
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include

Name: tileslide
Description: Collision detection and response for tile-based 2D games (C API)
Version: $version
Cflags: -I\${includedir}
Libs: -L\${libdir} -ltileslide_capi
Libs.private: -lgcc_s -lutil -lrt -lpthread -lm -ldl -lc
PC
echo "installed tileslide $version ($profile) in $prefix"
