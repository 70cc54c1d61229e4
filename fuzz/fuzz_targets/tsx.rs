#![no_main]
//! Fuzzes `checks::tsx` (see src/checks.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::checks::tsx(data));
