//! A scratch directory for one test, removed when the test ends, passing or failing (a panic
//! unwinds through the drop): test runs leave nothing behind in the temporary directory.
#![allow(dead_code)]

use std::ffi::OsStr;
use std::path::Path;

pub struct TestDir(tempfile::TempDir);

impl TestDir {
    /// A fresh, empty directory named `bumpwork-NAME-…` under the system's temporary directory.
    pub fn new(name: &str) -> TestDir {
        let dir = tempfile::Builder::new()
            .prefix(&format!("bumpwork-{name}-"))
            .tempdir()
            .expect("a temporary directory");
        TestDir(dir)
    }
}

impl std::ops::Deref for TestDir {
    type Target = Path;

    fn deref(&self) -> &Path {
        self.0.path()
    }
}

impl AsRef<Path> for TestDir {
    fn as_ref(&self) -> &Path {
        self.0.path()
    }
}

impl AsRef<OsStr> for TestDir {
    fn as_ref(&self) -> &OsStr {
        self.0.path().as_os_str()
    }
}
