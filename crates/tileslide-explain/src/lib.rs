//! The words of tileslide's explanations, written once: what the resolver did with a body
//! in one step ([`body`]), what a character's move did ([`character`]), and why each
//! segment of a map's cell is active or hidden and how its ends join ([`cell`]).
//!
//! `tileslide explain` prints them and labels its pictures with them; the browser
//! playground's build of `tileslide-wasm` (its `explain` feature) shows them when a body,
//! the character or a cell is clicked or hovered. Numbers are given to three decimals
//! ([`words::num`]), so the same trace reads the same everywhere.
//!
//! ```
//! use tileslide::{io::ascii, Bodies, BodyDesc, BodyShape, ResolveTrace, Vec2};
//!
//! let map = ascii::parse("#####\n#...#\n#####", "doc.txt", 1.0)?;
//! let mut bodies = Bodies::new();
//! let ball = bodies.add(BodyDesc::new(Vec2::new(1.5, 1.5), BodyShape::circle(0.4)?))?;
//! bodies.propose(ball, Vec2::new(3.0, 0.0))?;
//! let mut trace = ResolveTrace::new();
//! bodies.step_traced(&map, &mut trace);
//! let words = tileslide_explain::body::step_words("body 0, step 1", &trace.bodies[0], &|_| None);
//! assert!(words.starts_with("body 0, step 1: at (1.500, 1.500), proposed (3.000, 0.000)"));
//! assert!(words.contains("cell (4, 1) tile"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![forbid(unsafe_code)]

pub mod body;
pub mod cell;
pub mod character;
pub mod words;
