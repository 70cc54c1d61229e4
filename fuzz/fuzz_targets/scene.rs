#![no_main]
//! Fuzzes `scene::check` (see src/scene.rs).

libfuzzer_sys::fuzz_target!(|data: &[u8]| tileslide_fuzz::scene::check(data));
