#![no_main]
//! Fuzzes `checks::ldtk` (see src/checks.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::checks::ldtk(data));
