//! Replacing a file with new bytes atomically: a write that fails, whatever the reason (a
//! full disk, a lost mount, a refused rename), leaves the file as it was.
#![forbid(unsafe_code)]

use std::fs::{self, File, Metadata, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};

/// Links followed at most on the way to the file written, as Linux follows at most 40.
const MAX_LINKS: usize = 40;

/// Writes `bytes` to a new file beside `path`, flushes it to disk, and renames it over
/// `path`. A link is followed, to a file that may not exist yet: its target is written, not
/// the link. An existing file's permissions, owner and group carry over (the owner and the
/// group where the writer may set them), and the new file has them before it holds a byte,
/// so that no one who may not read the file can read it while it is written. On failure
/// the new file is removed and `path` is untouched.
pub fn replace(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let target = followed(path)?;
    let (temporary, mut file) = create_beside(&target)?;
    let written = write_all_synced(&mut file, bytes).and_then(|()| fs::rename(&temporary, &target));
    if written.is_err() {
        let _ = fs::remove_file(&temporary);
    }
    written
}

/// The file a write to `path` replaces: `path`, or where its links lead, each link's text
/// read against the directory that holds it, whether or not the last one leads to a file.
fn followed(path: &Path) -> io::Result<PathBuf> {
    let mut path = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match fs::symlink_metadata(&path) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let to = fs::read_link(&path)?;
                path = path.parent().map_or_else(|| to.clone(), |dir| dir.join(&to));
            }
            _ => return Ok(path),
        }
    }
    Err(io::Error::other(format!("more than {MAX_LINKS} links lead from it")))
}

/// A new file in `target`'s directory (so the rename stays on one file system), named after
/// it, that no other process or thread is writing, with `target`'s permissions, owner and
/// group when it exists.
fn create_beside(target: &Path) -> io::Result<(PathBuf, File)> {
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let name = target
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "the path names no file"))?;
    let existing = fs::metadata(target).ok();
    let mut options = OpenOptions::new();
    options.write(true).create_new(true);
    if let Some(meta) = &existing {
        owner_only(&mut options, meta);
    }
    loop {
        let mut temporary_name = std::ffi::OsString::from(".");
        temporary_name.push(name);
        let unique = COUNTER.fetch_add(1, Ordering::Relaxed);
        temporary_name.push(format!(".{}.{unique}.tmp", std::process::id()));
        let temporary = target.with_file_name(temporary_name);
        match options.open(&temporary) {
            Ok(file) => {
                let carried = existing.as_ref().map_or(Ok(()), |meta| carry_over(&file, meta));
                if let Err(e) = carried {
                    let _ = fs::remove_file(&temporary);
                    return Err(e);
                }
                return Ok((temporary, file));
            }
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(e),
        }
    }
}

/// Creates the file readable by its creator alone (and by it only if the existing file is
/// readable by its owner), until the existing file's owner, group and mode are given to it:
/// the group it is created with may be another.
#[cfg(unix)]
fn owner_only(options: &mut OpenOptions, existing: &Metadata) {
    use std::os::unix::fs::{OpenOptionsExt, PermissionsExt};
    options.mode(existing.permissions().mode() & 0o600);
}

#[cfg(not(unix))]
fn owner_only(_: &mut OpenOptions, _: &Metadata) {}

/// Gives the new file the existing one's owner and group (only root may give a file away;
/// anyone may give it a group they belong to; what the writer may not set stays its own),
/// then its permissions, which a change of owner may have cleared bits of.
fn carry_over(file: &File, existing: &Metadata) -> io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt, fchown};
        if fchown(file, Some(existing.uid()), Some(existing.gid())).is_err() {
            let _ = fchown(file, None, Some(existing.gid()));
        }
    }
    file.set_permissions(existing.permissions())
}

fn write_all_synced(file: &mut File, bytes: &[u8]) -> io::Result<()> {
    file.write_all(bytes)?;
    file.sync_all()
}
#[cfg(test)]
mod tests;
