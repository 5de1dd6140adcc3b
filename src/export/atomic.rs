//! A file that appears whole or not at all: written under a temporary name in the destination's
//! directory and renamed over the destination only when complete. Dropped before `commit` (an
//! error, a panic, a cancelled render), the temporary file is removed.

use crate::Error;
use std::fs::File;
use std::path::{Path, PathBuf};
use tempfile::TempPath;

pub struct AtomicFile {
    temporary: TempPath,
    destination: PathBuf,
    /// A second handle on the temporary file, to sync it to disk before the rename.
    sync: File,
}

/// Files as `File::create` makes them (0666 less the umask), not the temporary file's 0600.
#[cfg(unix)]
fn readable_by_all() -> std::fs::Permissions {
    use std::os::unix::fs::PermissionsExt;
    std::fs::Permissions::from_mode(0o666)
}

/// Why the temporary file could not be made, said of the directory (the user never named the
/// temporary file, which tempfile's own message quotes).
fn directory_problem(directory: &Path, error: &std::io::Error) -> String {
    let shown = crate::diagnostic::sanitize(&directory.display().to_string()).into_owned();
    match error.kind() {
        std::io::ErrorKind::NotFound => format!("the directory {shown} does not exist"),
        std::io::ErrorKind::PermissionDenied => {
            format!("the directory {shown} is not writable")
        }
        std::io::ErrorKind::NotADirectory => format!("{shown} is not a directory"),
        _ => format!(
            "cannot create a file in {shown}: {}",
            std::io::Error::from(error.kind())
        ),
    }
}

impl AtomicFile {
    /// Creates the temporary file next to `destination`; returns it and a handle to write into.
    pub fn create(destination: &Path) -> Result<(AtomicFile, File), Error> {
        let directory = match destination.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let name = destination
            .file_name()
            .map_or("still".into(), |n| n.to_string_lossy().into_owned());
        let (file, temporary) = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .permissions(readable_by_all())
            .tempfile_in(directory)
            .map_err(|e| Error::write(destination, directory_problem(directory, &e)))?
            .into_parts();
        let sync = file.try_clone().map_err(|e| Error::write(destination, e))?;
        let atomic = AtomicFile {
            temporary,
            destination: destination.to_path_buf(),
            sync,
        };
        Ok((atomic, file))
    }

    pub fn destination(&self) -> &Path {
        &self.destination
    }

    /// Syncs the finished file and renames it over the destination.
    pub fn commit(self) -> Result<(), Error> {
        let destination = self.destination;
        self.sync
            .sync_all()
            .map_err(|e| Error::write(&destination, e))?;
        self.temporary
            .persist(&destination)
            .map_err(|e| Error::write(&destination, e.error))
    }
}
