//! The limits of what tileslide accepts: the range of coordinates, the sizes of maps, tile
//! shapes, compound bodies, navigation grids and hit volumes, and how many edits a map's journal keeps. Each entry point
//! refuses what is past them with an error naming the value; a game reads them to size what
//! it builds.
//!
//! ```
//! use tileslide::limits::{MAX_CELLS, MAX_COORD};
//! assert_eq!(MAX_COORD, 16_777_216.0); // 2²⁴ map units from the origin
//! assert_eq!(MAX_CELLS, 1 << 26); // 8192 × 8192, say
//! ```

pub use crate::bodies::MAX_COMPOUND_CIRCLES;
pub use crate::geometry::limits::MAX_COORD;
pub use crate::io::MAX_FILE_BYTES;
pub use crate::path::MAX_NAV_NODES;
pub use crate::tiles::{JOURNAL_EDITS, MAX_CELLS, MAX_SHAPE_SEGMENTS, MAX_TEMPORARIES};
pub use crate::volumes::{MAX_FRAME_VOLUMES, MAX_HIT_OBJECTS, MAX_OBJECT_VOLUMES};
