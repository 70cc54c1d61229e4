//! tileslide for JavaScript: the library through wasm-bindgen, built into the ES module
//! `web/pkg/tileslide.js` (see `web/README.md`).
//!
//! The JavaScript API mirrors the Rust one in JavaScript's naming: `TileMap.fromAscii`,
//! `map.castRay`, `map.castRays`, `Bodies`, `Character`, `HitWorld`, `NavGrid` and
//! `FlowField`. Errors are thrown as `Error`s whose message is the Rust error's (file,
//! position, cause); a NaN or infinite number is an error naming the argument, never a
//! silent answer, and no input makes the package panic. Objects hold wasm memory until
//! `.free()` (or until the garbage collector runs a `FinalizationRegistry` callback, which
//! the build enables).
//!
//! What JavaScript calls is a thin layer (`map`, `bodies`, `character`, `hits`, `nav`) over
//! plain Rust (`rays`, `body_set`, `handles`, `args`), so the answers are tested natively
//! and in Node against the same checksums: wasm and native give the same bits.
#![forbid(unsafe_code)]

pub mod args;
pub mod bodies;
pub mod body_set;
pub mod character;
pub mod debug;
#[cfg(feature = "explain")]
pub mod explain;
pub mod handles;
pub mod hits;
pub mod map;
pub mod nav;
pub mod rays;
pub mod temporary;
pub mod values;
