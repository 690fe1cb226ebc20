use super::*;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("box2scene-output-{}-{name}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> =
        fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().into_string().unwrap()).collect();
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
