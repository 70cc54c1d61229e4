//! The checks the fuzz targets run (`checks`), shared with the stable regression test.

pub mod checks;
