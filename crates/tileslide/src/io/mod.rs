//! Loaders. Each returns a [`LoadError`] naming the file, the position (line:column or byte
//! offset) and the cause; none panics or allocates from an unchecked size field.

mod any;
pub mod ascii;
pub mod baked;
#[cfg(feature = "png")]
pub mod bitmap;
mod bytes;
mod error;
#[cfg(any(feature = "tiled", feature = "ldtk"))]
mod json_text;
#[cfg(feature = "ldtk")]
pub mod ldtk;
#[cfg(feature = "ldtk")]
mod ldtk_faults;
pub mod replica;
mod replica_objects;
#[cfg(feature = "tiled")]
pub mod tiled;
mod tiled_faults;

pub use any::load_file;
pub use baked::BakedFault;
pub use error::{LoadError, LoadErrorKind, Location, MAX_FILE_BYTES, ParserError, read_limited};
#[cfg(feature = "ldtk")]
pub use ldtk_faults::LdtkFault;
pub use tiled_faults::{NotTiled, TilePlacement, Unsupported};
