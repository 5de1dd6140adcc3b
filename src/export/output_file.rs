//! Where a still goes, as a plain write would put it there, but never half-written.
//!
//! - `-` is standard output.
//! - A regular file (or a name not yet taken) is written under a temporary name beside it and
//!   renamed over it when complete, keeping the old file's mode and owner: the destination holds
//!   the old file or the whole new one, never part of one. A symbolic link is followed and its
//!   target written so; a file with other hard links gets the finished bytes copied into it, so
//!   every name still shows the same file.
//! - A FIFO or a device is opened and written directly, never replaced.
//! - A directory, a socket, a missing or unwritable directory, or a file a plain write could not
//!   open is refused by [`check_destination`], which the commands call before rendering.
//!
//! Dropped before `commit` (an error, a panic, a cancelled render), the temporary file is removed.

use crate::Error;
use crate::diagnostic::sanitize;
use crate::unfinished_files::Unfinished;
use std::fs::{File, Metadata};
use std::io::ErrorKind;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use tempfile::TempPath;

/// The destination that means standard output.
pub const STANDARD_OUTPUT: &str = "-";

/// How long a still waits for a program to open the FIFO it is to be written into.
const FIFO_READER_WAIT: Duration = Duration::from_secs(30);

/// Symbolic links followed before giving up, as the kernel does.
const MAX_LINKS: usize = 40;

pub struct OutputFile {
    destination: PathBuf,
    commit: Commit,
}

enum Commit {
    /// The bytes went straight to standard output, a FIFO or a device.
    Direct,
    /// Synced, then renamed over `target`, or copied into its inode when it has other hard links.
    Replace {
        temporary: TempPath,
        target: PathBuf,
        sync: File,
        copy_into: bool,
        /// Removed by the shutdown watchdog if the process must exit before this is dropped.
        _tracked: Unfinished,
    },
}

/// What a destination is, once symbolic links are followed.
enum Target {
    StandardOutput,
    /// A regular file, or nothing yet: `existing` is its metadata if there is one.
    Regular {
        path: PathBuf,
        existing: Option<Metadata>,
    },
    /// A FIFO or a device.
    Special(PathBuf),
}

/// Writes `bytes` to `destination` whole, as a still is: the old file or the new one, never
/// part of one.
pub fn write_whole(destination: &Path, bytes: &[u8]) -> Result<(), Error> {
    use std::io::Write;
    let (file, mut handle) = OutputFile::create(destination)?;
    handle
        .write_all(bytes)
        .map_err(|e| Error::write(destination, io_words(&e)))?;
    drop(handle);
    file.commit()
}

/// Refuses, before any work is done, a destination the still could not be written to.
pub fn check_destination(destination: &Path) -> Result<(), Error> {
    classify(destination).map(|_| ())
}

impl OutputFile {
    /// Opens `destination` for a still; returns it and a handle to write into.
    pub fn create(destination: &Path) -> Result<(OutputFile, File), Error> {
        let output = |commit| OutputFile {
            destination: destination.to_path_buf(),
            commit,
        };
        match classify(destination)? {
            Target::StandardOutput => Ok((output(Commit::Direct), standard_output(destination)?)),
            Target::Special(path) => {
                Ok((output(Commit::Direct), open_special(&path, destination)?))
            }
            Target::Regular { path, existing } => {
                let (file, temporary) = temporary_beside(&path, existing.as_ref(), destination)?;
                let sync = file.try_clone().map_err(|e| Error::write(destination, e))?;
                let commit = Commit::Replace {
                    _tracked: crate::unfinished_files::track(&temporary),
                    temporary,
                    target: path,
                    sync,
                    copy_into: existing.as_ref().map_or(1, hard_links) > 1,
                };
                Ok((output(commit), file))
            }
        }
    }

    pub fn destination(&self) -> &Path {
        &self.destination
    }

    /// Makes the finished file appear at the destination.
    pub fn commit(self) -> Result<(), Error> {
        let fail = |e: std::io::Error| Error::write(&self.destination, io_words(&e));
        match self.commit {
            Commit::Direct => Ok(()),
            Commit::Replace {
                temporary,
                target,
                sync,
                copy_into: false,
                ..
            } => {
                sync.sync_all().map_err(fail)?;
                temporary.persist(&target).map_err(|e| fail(e.error))
            }
            Commit::Replace {
                temporary,
                target,
                sync,
                copy_into: true,
                ..
            } => {
                sync.sync_all().map_err(fail)?;
                let mut finished = File::open(&temporary).map_err(fail)?;
                let mut linked = std::fs::OpenOptions::new()
                    .write(true)
                    .truncate(true)
                    .open(&target)
                    .map_err(fail)?;
                std::io::copy(&mut finished, &mut linked).map_err(fail)?;
                linked.sync_all().map_err(fail)
            }
        }
    }
}

fn io_words(error: &std::io::Error) -> String {
    crate::bounded_read::io_words(error)
}

fn shown(path: &Path) -> String {
    sanitize(&path.display().to_string()).into_owned()
}

fn classify(destination: &Path) -> Result<Target, Error> {
    if destination.as_os_str() == STANDARD_OUTPUT {
        return standard_output_target(destination);
    }
    let path = follow_links(destination)?;
    let refuse = |reason: String| Err(Error::write(destination, reason));
    match std::fs::metadata(&path) {
        Err(e) if matches!(e.kind(), ErrorKind::NotFound | ErrorKind::NotADirectory) => {
            check_directory(&path, destination)?;
            Ok(Target::Regular {
                path,
                existing: None,
            })
        }
        Err(e) => refuse(io_words(&e)),
        Ok(m) if m.is_dir() => refuse("it is a directory; name a file in it".into()),
        Ok(m) if m.is_file() => {
            check_directory(&path, destination)?;
            if !may_write(&path) {
                return refuse("the file is read-only".into());
            }
            Ok(Target::Regular {
                path,
                existing: Some(m),
            })
        }
        Ok(m) if is_socket(&m) => refuse("it is a socket, not a file".into()),
        Ok(_) if !may_write(&path) => refuse("permission denied".into()),
        Ok(_) => Ok(Target::Special(path)),
    }
}

fn standard_output_target(destination: &Path) -> Result<Target, Error> {
    use std::io::IsTerminal;
    if std::io::stdout().is_terminal() {
        return Err(Error::write(
            destination,
            "standard output is a terminal; redirect it to a file or a program",
        ));
    }
    Ok(Target::StandardOutput)
}

/// The path a write to `destination` lands on: symbolic links followed, relative ones from the
/// link's own directory. A dangling link gives the path it points to.
fn follow_links(destination: &Path) -> Result<PathBuf, Error> {
    let mut path = destination.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&path) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&path)
                    .map_err(|e| Error::write(destination, io_words(&e)))?;
                path = match path.parent() {
                    Some(parent) if target.is_relative() => parent.join(target),
                    _ => target,
                };
            }
            _ => return Ok(path),
        }
    }
    Err(Error::write(
        destination,
        "too many levels of symbolic links",
    ))
}

/// The directory a new file would be made in exists and may be written.
fn check_directory(path: &Path, destination: &Path) -> Result<(), Error> {
    let directory = directory_of(path);
    let problem = match std::fs::metadata(directory) {
        Err(_) => format!("the directory {} does not exist", shown(directory)),
        Ok(m) if !m.is_dir() => format!("{} is not a directory", shown(directory)),
        Ok(_) if !may_write(directory) => {
            format!("the directory {} is not writable", shown(directory))
        }
        Ok(_) => return Ok(()),
    };
    Err(Error::write(destination, problem))
}

fn directory_of(path: &Path) -> &Path {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    }
}

/// Files as `File::create` makes them (0666 less the umask), not the temporary file's 0600.
#[cfg(unix)]
fn readable_by_all() -> std::fs::Permissions {
    use std::os::unix::fs::PermissionsExt;
    std::fs::Permissions::from_mode(0o666)
}

/// A temporary file in `path`'s directory, with the mode and owner of the file it replaces.
fn temporary_beside(
    path: &Path,
    existing: Option<&Metadata>,
    destination: &Path,
) -> Result<(File, TempPath), Error> {
    let directory = directory_of(path);
    let name = path
        .file_name()
        .map_or("still".into(), |n| n.to_string_lossy().into_owned());
    let (file, temporary) = tempfile::Builder::new()
        .prefix(&format!(".{name}."))
        .suffix(".tmp")
        .permissions(readable_by_all())
        .tempfile_in(directory)
        .map_err(|e| Error::write(destination, directory_problem(directory, &e)))?
        .into_parts();
    if let Some(existing) = existing {
        file.set_permissions(existing.permissions())
            .map_err(|e| Error::write(destination, io_words(&e)))?;
        keep_owner(&file, existing);
    }
    Ok((file, temporary))
}

/// Why the temporary file could not be made, said of the directory (the user never named the
/// temporary file, which tempfile's own message quotes).
fn directory_problem(directory: &Path, error: &std::io::Error) -> String {
    match error.kind() {
        ErrorKind::PermissionDenied => {
            format!("the directory {} is not writable", shown(directory))
        }
        // The directory is there (it was checked), yet creating in it says "not found": a
        // kernel file system such as /proc.
        ErrorKind::NotFound => format!(
            "cannot create a file in {}: it takes no new files",
            shown(directory)
        ),
        ErrorKind::ReadOnlyFilesystem => format!(
            "cannot create a file in {}: its file system is read-only",
            shown(directory)
        ),
        _ => format!(
            "cannot create a file in {}: {}",
            shown(directory),
            io_words(&std::io::Error::from(error.kind()))
        ),
    }
}

fn standard_output(destination: &Path) -> Result<File, Error> {
    use std::os::fd::AsFd;
    let handle = std::io::stdout()
        .as_fd()
        .try_clone_to_owned()
        .map_err(|e| Error::write(destination, io_words(&e)))?;
    Ok(File::from(handle))
}

/// Opens a FIFO or device for writing without blocking in `open` (a FIFO with no reader would
/// wait forever), waiting at most [`FIFO_READER_WAIT`] for a reader, then writes block as usual.
#[cfg(unix)]
fn open_special(path: &Path, destination: &Path) -> Result<File, Error> {
    use std::os::unix::fs::OpenOptionsExt;
    let deadline = Instant::now() + FIFO_READER_WAIT;
    loop {
        let opened = std::fs::OpenOptions::new()
            .write(true)
            .custom_flags(libc::O_NONBLOCK | libc::O_NOCTTY)
            .open(path);
        match opened {
            Ok(file) => return blocking(file, destination),
            Err(e) if e.raw_os_error() == Some(libc::ENXIO) && Instant::now() < deadline => {
                std::thread::sleep(Duration::from_millis(20));
            }
            Err(e) if e.raw_os_error() == Some(libc::ENXIO) => {
                return Err(Error::write(
                    destination,
                    format!(
                        "no program opened the named pipe for reading within {} s",
                        FIFO_READER_WAIT.as_secs()
                    ),
                ));
            }
            Err(e) => return Err(Error::write(destination, io_words(&e))),
        }
    }
}

#[cfg(not(unix))]
fn open_special(path: &Path, destination: &Path) -> Result<File, Error> {
    std::fs::OpenOptions::new()
        .write(true)
        .open(path)
        .map_err(|e| Error::write(destination, io_words(&e)))
}

/// Clears `O_NONBLOCK`, so a full pipe makes a write wait rather than fail.
#[cfg(unix)]
fn blocking(file: File, destination: &Path) -> Result<File, Error> {
    use std::os::fd::AsRawFd;
    let fd = file.as_raw_fd();
    // SAFETY: fcntl on a descriptor this function owns, with F_GETFL/F_SETFL and an int flag.
    let cleared = unsafe {
        let flags = libc::fcntl(fd, libc::F_GETFL);
        flags >= 0 && libc::fcntl(fd, libc::F_SETFL, flags & !libc::O_NONBLOCK) == 0
    };
    if !cleared {
        return Err(Error::write(
            destination,
            io_words(&std::io::Error::last_os_error()),
        ));
    }
    Ok(file)
}

/// Whether this process may write `path` (as `open` would judge it, by the effective user).
#[cfg(unix)]
fn may_write(path: &Path) -> bool {
    use std::os::unix::ffi::OsStrExt;
    let Ok(name) = std::ffi::CString::new(path.as_os_str().as_bytes()) else {
        return false;
    };
    // SAFETY: faccessat reads the NUL-terminated path; AT_FDCWD resolves it as open would.
    unsafe { libc::faccessat(libc::AT_FDCWD, name.as_ptr(), libc::W_OK, libc::AT_EACCESS) == 0 }
}

#[cfg(not(unix))]
fn may_write(path: &Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| !m.permissions().readonly())
}

#[cfg(unix)]
fn is_socket(metadata: &Metadata) -> bool {
    use std::os::unix::fs::FileTypeExt;
    metadata.file_type().is_socket()
}

#[cfg(not(unix))]
fn is_socket(_: &Metadata) -> bool {
    false
}

#[cfg(unix)]
fn hard_links(metadata: &Metadata) -> u64 {
    use std::os::unix::fs::MetadataExt;
    metadata.nlink()
}

#[cfg(not(unix))]
fn hard_links(_: &Metadata) -> u64 {
    1
}

/// Gives the replacement the old file's owner where this process may (as root); elsewhere the
/// new file is the writer's, as with any editor's save.
#[cfg(unix)]
fn keep_owner(file: &File, existing: &Metadata) {
    use std::os::unix::fs::MetadataExt;
    let _ = std::os::unix::fs::fchown(file, Some(existing.uid()), Some(existing.gid()));
}

#[cfg(not(unix))]
fn keep_owner(_: &File, _: &Metadata) {}
