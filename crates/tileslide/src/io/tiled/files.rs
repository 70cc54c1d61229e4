//! Where a map's external files (tile sets, templates) come from: the disk, beside the map,
//! or memory, for a game with no disk to read (in the browser).

use std::collections::BTreeMap;
use std::io;
use std::path::{Component, Path};

/// External files given in memory, by the name the map writes them with (relative to the
/// map, `/`-separated: `"tiles.tsj"`, `"sets/walls.tsx"`). Empty: files are read from disk.
pub type TiledFiles = BTreeMap<String, Vec<u8>>;

/// The bytes of `file`, an external file that the map at `map` names: from `files` when it
/// holds any (by `file`'s path relative to the map's folder), else from disk.
///
/// # Errors
/// The disk's error, or `NotFound` for a file `files` lacks (naming the names it has).
pub(super) fn read_external(file: &Path, map: &Path, files: &TiledFiles) -> io::Result<Vec<u8>> {
    if files.is_empty() {
        return crate::io::read_limited(file);
    }
    let dir = map.parent().unwrap_or(Path::new(""));
    let relative = file.strip_prefix(dir).unwrap_or(file);
    let key = name(relative);
    files.get(&key).cloned().ok_or_else(|| {
        let given: Vec<&str> = files.keys().map(String::as_str).collect();
        io::Error::new(
            io::ErrorKind::NotFound,
            format!(
                "`{key}` is not among the files given ({})",
                given.join(", ")
            ),
        )
    })
}

/// `path` as the `/`-separated name a map writes, with `.` steps dropped and `..` steps
/// taken back where they can be.
fn name(path: &Path) -> String {
    let mut parts: Vec<String> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if parts.last().is_some_and(|p| p != "..") => {
                parts.pop();
            }
            other => parts.push(other.as_os_str().to_string_lossy().into_owned()),
        }
    }
    parts.join("/")
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn files_given_in_memory_are_found_by_the_name_the_map_writes() {
        let files: TiledFiles = [
            ("tiles.tsj".to_string(), b"a".to_vec()),
            ("sets/walls.tsx".to_string(), b"b".to_vec()),
        ]
        .into();
        let map = Path::new("levels/one.tmj");
        let read = |name: &str| read_external(&Path::new("levels").join(name), map, &files);
        assert_eq!(read("tiles.tsj").unwrap(), b"a");
        assert_eq!(read("./sets/walls.tsx").unwrap(), b"b");
        assert_eq!(read("other/../tiles.tsj").unwrap(), b"a");
        let e = read("missing.tsj").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::NotFound);
        assert!(e.to_string().contains("`missing.tsj`") && e.to_string().contains("tiles.tsj"));
    }
}
