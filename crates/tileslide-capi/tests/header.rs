//! `include/tileslide.h` is what cbindgen makes of this crate: regenerated here and compared,
//! so a change to the API that leaves the header stale fails. `TILESLIDE_BLESS=1` rewrites
//! the header instead.

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;

#[test]
fn the_checked_in_header_is_what_cbindgen_generates() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen could not read the crate");
    let mut fresh = Vec::new();
    bindings.write(&mut fresh);
    let header = crate_dir.join("../../include/tileslide.h");
    if std::env::var_os("TILESLIDE_BLESS").is_some() {
        std::fs::write(&header, &fresh).unwrap();
        return;
    }
    let checked_in = std::fs::read(&header).unwrap_or_default();
    assert!(
        checked_in == fresh,
        "include/tileslide.h is stale: run `TILESLIDE_BLESS=1 cargo test -p tileslide-capi --test header` and commit it"
    );
}
