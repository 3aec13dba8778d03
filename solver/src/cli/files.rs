//! The files the command line reads and writes. One rule for output: a
//! file's folder must exist; an output folder (`figures --out`,
//! `accuracy --figures`) is created when missing, but its parent must exist
//! (as `mkdir` does: a mistyped path creates no tree). Every output path is
//! checked before the work starts and leaves nothing behind when a later one
//! fails; each file is written whole (a temporary file beside it, renamed
//! over it), so a run that fails half-way leaves no half-written file. An
//! input file is read up to a bound, checked before it is read whole.
//!
//! Owns: [`input`], [`check_file`], [`check_folder`], [`write_whole`],
//! [`quote`]. May use: `crate::Error`.

use crate::Error;
use std::io::Read;
use std::path::{Path, PathBuf};

/// At most `max` bytes of the file at `p` as text; a longer one (or a
/// device without end, such as /dev/zero) is refused after `max + 1` bytes.
pub(crate) fn input(p: &Path, max: u64) -> crate::Result<String> {
    let f = std::fs::File::open(p)
        .map_err(|e| Error::Io(format!("cannot read {}: {e}", p.display())))?;
    let mut bytes = Vec::new();
    f.take(max + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Error::Io(format!("cannot read {}: {e}", p.display())))?;
    if bytes.len() as u64 > max {
        return Err(Error::Io(format!(
            "{} is larger than {max} bytes, more than such a file can be",
            p.display()
        )));
    }
    String::from_utf8(bytes).map_err(|_| Error::Io(format!("{} is not UTF-8 text", p.display())))
}

/// At most `max` characters of `text` on one line, for a message that
/// quotes what a user wrote (or a parser's words around it).
pub(crate) fn quote(text: &str, max: usize) -> String {
    let one_line: String = text
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    match one_line.char_indices().nth(max) {
        Some((i, _)) => format!("{}…", &one_line[..i]),
        None => one_line,
    }
}

fn folder_of(p: &Path) -> PathBuf {
    match p.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// That a file can be written at `p` (its folder exists and takes a new
/// file), checked without touching `p` itself.
pub(crate) fn check_file(p: &Path) -> crate::Result<()> {
    if p.is_dir() {
        return Err(Error::Io(format!(
            "{} is a folder, not a file",
            p.display()
        )));
    }
    writable_folder(&folder_of(p), p)
}

/// That `dir` is an output folder or can be created as one (its parent
/// exists); created only by [`create_folder`], after every check passed.
pub(crate) fn check_folder(dir: &Path) -> crate::Result<()> {
    if dir.is_dir() {
        return writable_folder(dir, dir);
    }
    if dir.exists() {
        return Err(Error::Io(format!("{} is not a folder", dir.display())));
    }
    let parent = folder_of(dir);
    if !parent.is_dir() {
        return Err(Error::Io(format!(
            "cannot create the folder {}: {} does not exist",
            dir.display(),
            parent.display()
        )));
    }
    writable_folder(&parent, dir)
}

/// Create the output folder `dir` if it is missing (its parent exists).
pub(crate) fn create_folder(dir: &Path) -> crate::Result<()> {
    if dir.is_dir() {
        return Ok(());
    }
    std::fs::create_dir(dir)
        .map_err(|e| Error::Io(format!("cannot create the folder {}: {e}", dir.display())))
}

/// A probe file created and removed in `dir`: the one sure test that a
/// new file can be written there.
fn writable_folder(dir: &Path, for_path: &Path) -> crate::Result<()> {
    if !dir.is_dir() {
        return Err(Error::Io(format!(
            "cannot write {}: the folder {} does not exist",
            for_path.display(),
            dir.display()
        )));
    }
    let probe = dir.join(format!(".thinjkr-probe-{}", std::process::id()));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&probe)
        .map_err(|e| Error::Io(format!("cannot write {}: {e}", for_path.display())))?;
    let _ = std::fs::remove_file(&probe);
    Ok(())
}

/// Write `contents` to `p` whole: into a temporary file beside it, then
/// renamed over it.
pub(crate) fn write_whole(p: &Path, contents: &[u8]) -> crate::Result<()> {
    let name = p
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    let tmp = folder_of(p).join(format!(".{name}.thinjkr-{}", std::process::id()));
    let written = std::fs::write(&tmp, contents).and_then(|()| std::fs::rename(&tmp, p));
    written.map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        Error::Io(format!("cannot write {}: {e}", p.display()))
    })
}
