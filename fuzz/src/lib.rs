//! The checks the fuzz targets run (`checks` for the loaders, `api` for the API surface),
//! shared with the stable regression test.

pub mod api;
pub mod checks;
