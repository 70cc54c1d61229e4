//! The checks the fuzz targets run (`checks` for the loaders, `api` for the API surface,
//! `scene` for the CLI's scene files), shared with the stable regression tests.

pub mod api;
pub mod checks;
pub mod scene;
