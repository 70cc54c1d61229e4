#![no_main]
//! Fuzzes `checks::replica_level` (see src/checks.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::checks::replica_level(data));
