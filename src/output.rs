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
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("box2scene-output-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().into_string().unwrap())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn a_file_is_replaced_whole_and_nothing_is_left_beside_it() {
        let dir = scratch("replace");
        let path = dir.join("level.xml");
        fs::write(&path, "old and longer than the new text").unwrap();
        replace(&path, b"new").unwrap();
        assert_eq!(fs::read(&path).unwrap(), b"new");
        assert_eq!(entries(&dir), ["level.xml"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_failed_rename_leaves_the_old_file_and_no_temporary() {
        let dir = scratch("refused");
        // A non-empty directory cannot be renamed over: the write fails at its last step.
        let path = dir.join("level.xml");
        fs::create_dir(&path).unwrap();
        fs::write(path.join("inside"), "kept").unwrap();
        assert!(replace(&path, b"new").is_err());
        assert_eq!(fs::read(path.join("inside")).unwrap(), b"kept");
        assert_eq!(entries(&dir), ["level.xml"]);
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_link_is_followed_and_permissions_carry_over() {
        let dir = scratch("link");
        let real = dir.join("real.xml");
        fs::write(&real, "old").unwrap();
        let original = fs::metadata(&real).unwrap().permissions();
        let mut permissions = original.clone();
        permissions.set_readonly(true);
        fs::set_permissions(&real, permissions).unwrap();
        #[cfg(unix)]
        {
            let link = dir.join("link.xml");
            std::os::unix::fs::symlink(&real, &link).unwrap();
            replace(&link, b"new").unwrap();
            assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
            assert_eq!(fs::read(&real).unwrap(), b"new");
            assert!(fs::metadata(&real).unwrap().permissions().readonly());
        }
        fs::set_permissions(&real, original).unwrap();
        fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_missing_directory_is_an_error_and_creates_nothing() {
        let dir = scratch("missing");
        let path = dir.join("no-such-dir").join("level.xml");
        assert_eq!(replace(&path, b"new").unwrap_err().kind(), io::ErrorKind::NotFound);
        assert!(entries(&dir).is_empty());
        fs::remove_dir_all(dir).unwrap();
    }

    /// The temporary file is created with the mode of the file it replaces (here 0600,
    /// tighter than the default 0644) before anything is written to it: another user never
    /// reads the scene while it is written.
    #[cfg(unix)]
    #[test]
    fn the_temporary_file_has_the_final_mode_before_its_first_write() {
        use std::os::unix::fs::PermissionsExt;
        let dir = scratch("mode");
        let path = dir.join("level.xml");
        fs::write(&path, "old").unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(0o600)).unwrap();
        let (temporary, file) = create_beside(&path).unwrap();
        let mode = |meta: fs::Metadata| meta.permissions().mode() & 0o7777;
        assert_eq!(file.metadata().unwrap().len(), 0, "nothing is written yet");
        assert_eq!(mode(file.metadata().unwrap()), 0o600);
        assert_eq!(mode(fs::metadata(&temporary).unwrap()), 0o600);
        drop(file);
        fs::remove_file(&temporary).unwrap();
        replace(&path, b"new").unwrap();
        assert_eq!(mode(fs::metadata(&path).unwrap()), 0o600);
        fs::remove_dir_all(dir).unwrap();
    }

    /// Root rewriting a user's file leaves it the user's, with its group and mode, so that
    /// the user can still save it; another writer keeps what it may set.
    #[cfg(unix)]
    #[test]
    fn the_owner_and_group_carry_over_when_the_writer_may_set_them() {
        use std::os::unix::fs::{MetadataExt, PermissionsExt, chown};
        let dir = scratch("owner");
        let path = dir.join("level.xml");
        fs::write(&path, "old").unwrap();
        let root = fs::metadata(&path).unwrap().uid() == 0;
        if !root {
            eprintln!("not run as root: a file cannot be given to another user here");
            fs::remove_dir_all(dir).unwrap();
            return;
        }
        chown(&path, Some(4242), Some(4343)).unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(0o640)).unwrap();
        let (temporary, file) = create_beside(&path).unwrap();
        let meta = file.metadata().unwrap();
        assert_eq!((meta.uid(), meta.gid(), meta.len()), (4242, 4343, 0), "before a byte");
        drop(file);
        fs::remove_file(&temporary).unwrap();
        replace(&path, b"new").unwrap();
        let meta = fs::metadata(&path).unwrap();
        assert_eq!((meta.uid(), meta.gid(), meta.mode() & 0o7777), (4242, 4343, 0o640));
        assert_eq!(fs::read(&path).unwrap(), b"new");
        fs::remove_dir_all(dir).unwrap();
    }

    /// A link to a file that does not exist yet is written through: its target is created,
    /// relative links read against the directory of each link; a loop of links is an error
    /// that creates nothing.
    #[cfg(unix)]
    #[test]
    fn a_link_whose_target_does_not_exist_yet_creates_the_target() {
        use std::os::unix::fs::symlink;
        let dir = scratch("dangling");
        fs::create_dir(dir.join("levels")).unwrap();
        symlink("levels/next.xml", dir.join("middle.xml")).unwrap();
        fs::create_dir(dir.join("links")).unwrap();
        symlink("../middle.xml", dir.join("links/level.xml")).unwrap();
        replace(&dir.join("links/level.xml"), b"new").unwrap();
        assert_eq!(fs::read(dir.join("levels/next.xml")).unwrap(), b"new");
        assert!(fs::symlink_metadata(dir.join("middle.xml")).unwrap().file_type().is_symlink());
        assert_eq!(entries(&dir.join("levels")), ["next.xml"]);

        symlink("b.xml", dir.join("a.xml")).unwrap();
        symlink("a.xml", dir.join("b.xml")).unwrap();
        assert!(replace(&dir.join("a.xml"), b"new").is_err());
        assert_eq!(entries(&dir), ["a.xml", "b.xml", "levels", "links", "middle.xml"]);
        fs::remove_dir_all(dir).unwrap();
    }
}
