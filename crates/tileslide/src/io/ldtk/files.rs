//! The files a project names (`.ldtkl` level files, tile set images): found inside the
//! project's folder only, on disk or among files given in memory.

use std::collections::BTreeMap;
use std::io;
use std::path::{Path, PathBuf};

use crate::io::LdtkFault;

/// Files given in memory, by the path the project writes them with (relative to the
/// project, `/`-separated: `"platformer/Level_0.ldtkl"`). Empty: files are read from disk.
pub type LdtkFiles = BTreeMap<String, Vec<u8>>;

/// `rel`, a path the project writes, as the `/`-separated path inside the project's folder
/// it stands for (`.` steps dropped, `..` steps taken back); refused if it is absolute or
/// climbs above the folder.
pub(super) fn inside(rel: &str) -> Result<String, LdtkFault> {
    let outside = |why| LdtkFault::OutsideProject {
        path: rel.to_owned(),
        why,
    };
    // LDtk writes `/`; a `\` is taken as a separator too, so that no platform reads a
    // Windows path as one strange file name. A drive (`C:`) is absolute on Windows.
    let unified = rel.replace('\\', "/");
    if unified.starts_with('/')
        || unified
            .split('/')
            .next()
            .is_some_and(|first| first.contains(':'))
    {
        return Err(outside("an absolute path"));
    }
    let mut parts: Vec<&str> = Vec::new();
    for part in unified.split('/') {
        match part {
            "" | "." => {}
            ".." => {
                if parts.pop().is_none() {
                    return Err(outside("\"..\" climbs above the folder"));
                }
            }
            name => parts.push(name),
        }
    }
    if parts.is_empty() {
        return Err(outside("it names the folder itself"));
    }
    Ok(parts.join("/"))
}

/// The file at `rel` (already through [`inside`]) in the folder of the project at
/// `project`, on disk: refused, without being opened, if a symbolic link on the way leads
/// out of the folder.
pub(super) fn disk_path(project: &Path, rel: &str) -> Result<PathBuf, DiskFault> {
    let folder = project.parent().unwrap_or(Path::new(""));
    let folder = if folder.as_os_str().is_empty() {
        Path::new(".")
    } else {
        folder
    };
    let file = rel
        .split('/')
        .fold(folder.to_path_buf(), |path, part| path.join(part));
    // Both resolved, so that links (in the folder, or in the file's own path) are followed
    // before comparing: a file is inside only if its real path starts with the folder's.
    let real_folder = folder
        .canonicalize()
        .map_err(|e| DiskFault::Io(file.clone(), e))?;
    let real_file = file
        .canonicalize()
        .map_err(|e| DiskFault::Io(file.clone(), e))?;
    if !real_file.starts_with(&real_folder) {
        return Err(DiskFault::Outside(LdtkFault::OutsideProject {
            path: rel.to_owned(),
            why: "a symbolic link leads out",
        }));
    }
    Ok(real_file)
}

/// Why a file named by the project could not be read from disk.
#[derive(Debug)]
pub(super) enum DiskFault {
    /// It could not be read (its path as joined to the project's folder).
    Io(PathBuf, io::Error),
    /// It leads outside the folder.
    Outside(LdtkFault),
}

/// The bytes of `rel` (through [`inside`]) from `files`, or `NotFound` naming the names it
/// has.
pub(super) fn from_memory(rel: &str, files: &LdtkFiles) -> io::Result<Vec<u8>> {
    files.get(rel).cloned().ok_or_else(|| {
        let given: Vec<&str> = files.keys().map(String::as_str).collect();
        io::Error::new(
            io::ErrorKind::NotFound,
            format!(
                "`{rel}` is not among the files given ({})",
                given.join(", ")
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;

    #[test]
    fn paths_inside_the_folder_are_normalised_and_others_refused() {
        assert_eq!(
            inside("levels/Level_0.ldtkl").unwrap(),
            "levels/Level_0.ldtkl"
        );
        assert_eq!(inside("./a/../b.ldtkl").unwrap(), "b.ldtkl");
        assert_eq!(inside("a\\b.ldtkl").unwrap(), "a/b.ldtkl");
        let why = |rel: &str| match inside(rel).unwrap_err() {
            LdtkFault::OutsideProject { why, .. } => why,
            other => panic!("{other:?}"),
        };
        assert_eq!(why("/etc/passwd"), "an absolute path");
        assert_eq!(why("\\\\server\\share"), "an absolute path");
        assert_eq!(why("C:/levels/a.ldtkl"), "an absolute path");
        assert_eq!(why("../secret.ldtkl"), "\"..\" climbs above the folder");
        assert_eq!(why("a/../../b"), "\"..\" climbs above the folder");
        assert_eq!(why("."), "it names the folder itself");
    }
}
