//! What can be wrong with a baked map's culled segments when its checksum is right.

use thiserror::Error;

/// Why a baked map's culled segments are not what its tiles make (see
/// [`LoadErrorKind::BakedSegments`](crate::io::LoadErrorKind::BakedSegments)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
#[non_exhaustive]
pub enum BakedFault {
    /// A segment's coordinate is not finite, or it has zero length.
    #[error("a coordinate is not finite, or it has zero length")]
    NotFinite,
    /// A link's neighbour number is not one of the nine.
    #[error("a link names no neighbour")]
    LinkToNoNeighbour,
    /// A link names a cell outside the map, or a segment its cell does not have.
    #[error("a link names a segment that is not there")]
    LinkToMissingSegment,
    /// A link names the segment it belongs to.
    #[error("a link names its own segment")]
    LinkToItself,
    /// A link names a segment that does not touch the end it links.
    #[error("a link names a segment that does not touch its end")]
    LinkNotTouching,
    /// A link joins two faces back to back.
    #[error("a link joins two faces back to back")]
    LinkBackToBack,
    /// A segment's caps are not what its links give.
    #[error("its caps are not what its links give")]
    WrongCaps,
    /// A piece of a partly hidden tile segment is not where its tile puts it.
    #[error("it is not the piece its tile makes there")]
    NotThePiece,
    /// A segment's end points, normal, flags or source are not what the tiles make there.
    #[error("its end points, normal, flags or source are not what its tiles make there")]
    NotWhatTheTilesMake,
    /// A cell holds another number of active segments than its tiles make there.
    #[error("it holds {stored} active segments, but its tiles make {made} there")]
    WrongCount {
        /// How many the file holds.
        stored: u64,
        /// How many the tiles make.
        made: u64,
    },
    /// A cell's kind byte is not the one its segments make.
    #[error("its kind {0} does not match its segments")]
    WrongKind(u8),
}
