//! # tileslide-render
//!
//! Pictures of [`tileslide`] maps and what happens in them, for documentation, bug reports
//! and eyeballing a simulation: solid material, active segments with their normals,
//! bodies, rays with their hits, paths, attack and vulnerability volumes, hit events —
//! as PNG images or animated GIFs, with legends, HUDs and labels in bitmap text.
//!
//! ## How it fits together
//!
//! - A [`Canvas`] is a map drawn once at a scale ([`RenderOptions::pixels_per_cell`],
//!   default 16) and orientation ([`YAxis`]).
//! - A [`Picture`] collects what to draw over it, in world coordinates.
//! - [`Canvas::render`] gives an [`Image`], which encodes as PNG; an [`Animation`] renders a
//!   picture per frame into an animated GIF.
//! - [`Canvas::framed`] draws part of a map ([`Framing`]) and leaves room beside it; a
//!   [`Camera`] frames an area that grows; an [`ImageAnimation`] takes images rendered
//!   on any canvas. [`Image::text`] and [`Panel`] (legends, HUDs) draw text;
//!   [`categorical()`] colours things by number.
//!
//! ## Conventions
//!
//! - Colours come from a [`Style`]: solid fill grey, solid segments near-black, one-way
//!   platforms orange, temporary segments purple, normal ticks teal, bodies green, rays
//!   magenta, paths amber, attack volumes red, vulnerability volumes blue.
//! - [`YAxis::Down`] (the default) draws row 0 at the top, for maps whose "up" is −y (ASCII
//!   and Tiled maps); [`YAxis::Up`] draws it at the bottom, for Replica Island levels.
//! - Images are refused above [`MAX_PIXELS`] pixels ([`RenderError::TooLarge`]), and a scale
//!   that is not a positive finite number is refused ([`RenderError::BadScale`]).
//! - Overlays with a NaN or infinite coordinate are skipped and counted
//!   ([`Picture::skipped`]); nothing panics.
//!
//! See [`Picture`] for an example, and `docs/render.md` in the repository.
#![forbid(unsafe_code)]

mod animation;
mod camera;
mod canvas;
mod categorical;
mod color;
mod error;
mod image;
mod image_animation;
mod lines;
mod options;
mod palette;
mod panel;
mod pen;
mod picture;
mod text;
mod view;

pub use animation::{Animation, DEFAULT_FRAME_DELAY};
pub use camera::{Camera, Framing};
pub use canvas::Canvas;
pub use categorical::{CATEGORICAL, categorical};
pub use color::{Rgba, Style};
pub use error::RenderError;
pub use image::Image;
pub use image_animation::ImageAnimation;
pub use options::{
    DEFAULT_LAYERS, DEFAULT_PIXELS_PER_CELL, MAX_GIF_BYTES, MAX_PIXELS, RenderOptions, YAxis,
};
pub use panel::{Panel, Swatch};
pub use picture::{Picture, VolumeKind};
pub use text::{Anchor, FontSize};
