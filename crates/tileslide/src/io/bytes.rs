//! A little-endian reader over a byte slice whose errors name the field and its offset.

use std::path::Path;

use super::{LoadError, LoadErrorKind, Location};

pub(crate) struct ByteReader<'a> {
    data: &'a [u8],
    pos: usize,
    path: &'a Path,
}

impl<'a> ByteReader<'a> {
    pub fn new(data: &'a [u8], path: &'a Path) -> Self {
        Self { data, pos: 0, path }
    }

    pub fn offset(&self) -> u64 {
        self.pos as u64
    }

    pub fn remaining(&self) -> usize {
        self.data.len() - self.pos
    }

    pub fn error_at(&self, offset: u64, kind: LoadErrorKind) -> LoadError {
        LoadError::new(self.path, Location::Byte(offset), kind)
    }

    pub fn take(&mut self, n: usize, field: &'static str) -> Result<&'a [u8], LoadError> {
        if self.remaining() < n {
            return Err(self.error_at(
                self.offset(),
                LoadErrorKind::Truncated {
                    field,
                    needed: (n - self.remaining()) as u64,
                },
            ));
        }
        let out = &self.data[self.pos..self.pos + n];
        self.pos += n;
        Ok(out)
    }

    fn array<const N: usize>(&mut self, field: &'static str) -> Result<[u8; N], LoadError> {
        let mut out = [0u8; N];
        out.copy_from_slice(self.take(N, field)?);
        Ok(out)
    }

    pub fn u8(&mut self, field: &'static str) -> Result<u8, LoadError> {
        Ok(self.array::<1>(field)?[0])
    }

    pub fn i8(&mut self, field: &'static str) -> Result<i8, LoadError> {
        Ok(i8::from_le_bytes(self.array(field)?))
    }

    pub fn i32(&mut self, field: &'static str) -> Result<i32, LoadError> {
        Ok(i32::from_le_bytes(self.array(field)?))
    }

    pub fn u32(&mut self, field: &'static str) -> Result<u32, LoadError> {
        Ok(u32::from_le_bytes(self.array(field)?))
    }

    pub fn u64(&mut self, field: &'static str) -> Result<u64, LoadError> {
        Ok(u64::from_le_bytes(self.array(field)?))
    }

    pub fn f32(&mut self, field: &'static str) -> Result<f32, LoadError> {
        Ok(f32::from_le_bytes(self.array(field)?))
    }
}
