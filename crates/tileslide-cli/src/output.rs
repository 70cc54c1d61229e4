//! Output files, checked before a command does its work: a name with the right extension,
//! not a folder, in a folder that exists.

use std::path::Path;

use anyhow::{Result, bail};

/// What a command writes, for the messages.
#[derive(Clone, Copy, Debug)]
pub struct Kind {
    /// The extension the file must have (lowercase, no dot).
    pub extension: &'static str,
    /// What the file is, to say why the extension matters ("an animated GIF").
    pub what: &'static str,
}

/// An animated GIF (`demo`, `simulate --gif`).
pub const GIF: Kind = Kind {
    extension: "gif",
    what: "an animated GIF",
};

/// A PNG picture (`render`, and the final frame the demos write beside their GIF).
pub const PNG: Kind = Kind {
    extension: "png",
    what: "a PNG picture",
};

/// A baked map (`bake`): the other commands tell it by its extension.
pub const BAKED: Kind = Kind {
    extension: "tsm",
    what: "a baked map, which the other commands recognise by its .tsm name",
};

/// Refuses `path` (given with `flag`) unless a file of `kind` can be written there: its
/// name ends in `.EXT`, it is not a folder, and its folder exists.
pub fn check(path: &Path, flag: &str, kind: Kind) -> Result<()> {
    let shown = path.display();
    let named_as_folder = path.as_os_str().to_string_lossy().ends_with(['/', '\\']);
    if named_as_folder || path.is_dir() {
        bail!(
            "{flag} {shown}: is a folder; give a file name ending in .{}",
            kind.extension
        );
    }
    let extension = path
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase());
    if extension.as_deref() != Some(kind.extension) {
        bail!(
            "{flag} {shown}: this writes {}; give a file name ending in .{}",
            kind.what,
            kind.extension
        );
    }
    let folder = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    if !folder.is_dir() {
        bail!(
            "{flag} {shown}: the folder {} does not exist",
            folder.display()
        );
    }
    Ok(())
}

/// An error's message with its causes, each said once: `file: cannot write: cause`, not
/// `file: cannot write: cause: cause` when an error already quotes its source.
pub fn message(error: &anyhow::Error) -> String {
    let mut out = String::new();
    for cause in error.chain() {
        let text = cause.to_string();
        if out.contains(&text) {
            continue;
        }
        if !out.is_empty() {
            out.push_str(": ");
        }
        out.push_str(&text);
    }
    out
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn a_cause_already_quoted_is_not_repeated() {
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "gone");
        #[derive(Debug)]
        struct Quoting(std::io::Error);
        impl std::fmt::Display for Quoting {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                write!(f, "out.gif: cannot write: {}", self.0)
            }
        }
        impl std::error::Error for Quoting {
            fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
                Some(&self.0)
            }
        }
        let e = anyhow::Error::new(Quoting(io)).context("demo");
        assert_eq!(message(&e), "demo: out.gif: cannot write: gone");
        let plain = anyhow::anyhow!("inner").context("outer");
        assert_eq!(message(&plain), "outer: inner");
    }

    #[test]
    fn output_names_are_checked_for_extension_folder_and_parent() {
        let dir = std::env::temp_dir();
        let ok = dir.join("tileslide-output-check.GIF");
        assert!(check(&ok, "-o", GIF).is_ok());
        let png = check(&dir.join("out.png"), "-o", GIF)
            .unwrap_err()
            .to_string();
        assert!(png.contains("give a file name ending in .gif"), "{png}");
        let folder = check(&dir, "-o", GIF).unwrap_err().to_string();
        assert!(folder.contains("is a folder"), "{folder}");
        let missing = check(Path::new("no-such-folder/x.gif"), "-o", GIF)
            .unwrap_err()
            .to_string();
        assert!(
            missing.contains("the folder no-such-folder does not exist"),
            "{missing}"
        );
    }
}
