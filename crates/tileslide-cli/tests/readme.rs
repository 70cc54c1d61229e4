//! The README's command examples, run against the real binary: every ```console block of
//! README.md (and of any docs/*.md that has one), `$ tileslide ...` lines and what they
//! print (stdout and stderr together, as a terminal shows them), checked by trycmd.
//! Timings are elided in the README with `[..]` (part of a line) and `...` (lines).
//!
//! The examples name files from the repository root (`examples/maps/cave.txt`) and some
//! write files (`bake -o cave.tsm`), so they run in a scratch folder holding a copy of the
//! markdown files and of `examples/`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::{Path, PathBuf};

/// Copies the folder `from` into `to`, recursively.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let target = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_dir(&entry.path(), &target);
        } else {
            std::fs::copy(entry.path(), &target).unwrap();
        }
    }
}

/// The markdown files with console examples, relative to the repository root.
fn documents(root: &Path) -> Vec<PathBuf> {
    let mut found = vec![PathBuf::from("README.md")];
    let mut docs: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .filter(|p| std::fs::read_to_string(p).unwrap().contains("```console"))
        .map(|p| Path::new("docs").join(p.file_name().unwrap()))
        .collect();
    docs.sort();
    found.extend(docs);
    found
}

#[test]
fn readme_console_examples_print_what_the_binary_prints() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let work = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme-examples");
    if work.exists() {
        std::fs::remove_dir_all(&work).unwrap();
    }
    copy_dir(&root.join("examples"), &work.join("examples"));
    let documents = documents(&root);
    for doc in &documents {
        std::fs::create_dir_all(work.join(doc).parent().unwrap()).unwrap();
        std::fs::copy(root.join(doc), work.join(doc)).unwrap();
    }
    // trycmd runs a markdown file's commands in the current folder; this is the only test
    // of this file, so changing it affects nothing else.
    std::env::set_current_dir(&work).unwrap();
    let cases = trycmd::TestCases::new();
    cases.register_bin("tileslide", PathBuf::from(env!("CARGO_BIN_EXE_tileslide")));
    for doc in &documents {
        cases.case(work.join(doc));
    }
    cases.run();
}
