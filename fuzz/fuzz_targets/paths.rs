#![no_main]
//! Fuzzes `api::paths` (see src/api.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::api::paths(data));
