//! tileslide for JavaScript: the library's maps and ray casts through wasm-bindgen, built
//! into the ES module `web/pkg/tileslide.js` (see `web/README.md`).
//!
//! The JavaScript API mirrors the Rust one in JavaScript's naming: `TileMap.fromAscii`,
//! `map.castRay`, `map.castRays`. Errors are thrown as `Error`s whose message is the Rust
//! error's (file, position, cause); a NaN or infinite coordinate is an error, never a
//! silent answer. Objects hold wasm memory until `.free()` (or until the garbage collector
//! runs a `FinalizationRegistry` callback, which the build enables).
//!
//! What JavaScript calls is a thin layer ([`map`]) over plain Rust ([`rays`]), so the
//! answers are tested natively and in Node against the same checksum: wasm and native give
//! the same bits.

pub mod debug;
pub mod map;
pub mod rays;
