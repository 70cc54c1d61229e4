#![no_main]
//! Fuzzes `api::casts` (see src/api.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::api::casts(data));
