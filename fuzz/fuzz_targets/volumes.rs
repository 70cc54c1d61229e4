#![no_main]
//! Fuzzes `api::volumes` (see src/api.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::api::volumes(data));
