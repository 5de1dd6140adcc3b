//! What a reloader rebuilds: a scene from files it can name.

use crate::Error;
use crate::scene::Scene;
use crate::scene::dependencies::scene_file_dependencies;
use std::path::PathBuf;

/// What the reloader rebuilds: a scene made from files, which it can name.
pub trait SceneSource: Send + 'static {
    /// Reads and compiles the scene from disk.
    fn load(&self) -> Result<Scene, Error>;

    /// The files `load` reads (not built-ins). Asked before every reload, so a scene edit that
    /// names a new file gets that file watched.
    fn dependencies(&self) -> Vec<PathBuf>;
}

/// A scene file and the pattern and image files it names.
#[derive(Clone, Debug)]
pub struct SceneFileSource {
    path: PathBuf,
}

impl SceneFileSource {
    pub fn new(path: impl Into<PathBuf>) -> Self {
        SceneFileSource { path: path.into() }
    }
}

impl SceneSource for SceneFileSource {
    fn load(&self) -> Result<Scene, Error> {
        crate::scene::load_scene_file(&self.path)
    }

    /// While the scene file cannot be parsed only it is watched: nothing else can change what
    /// is shown until it is fixed, and fixing it re-derives the rest.
    fn dependencies(&self) -> Vec<PathBuf> {
        scene_file_dependencies(&self.path).unwrap_or_else(|_| vec![self.path.clone()])
    }
}

/// Fixed files and a function that builds the scene from them: for example a bare pattern file
/// or image shown on a default scene.
pub struct FileSetSource<F> {
    files: Vec<PathBuf>,
    build: F,
}

impl<F> FileSetSource<F>
where
    F: Fn() -> Result<Scene, Error> + Send + 'static,
{
    pub fn new(files: Vec<PathBuf>, build: F) -> Self {
        FileSetSource { files, build }
    }
}

impl<F> SceneSource for FileSetSource<F>
where
    F: Fn() -> Result<Scene, Error> + Send + 'static,
{
    fn load(&self) -> Result<Scene, Error> {
        (self.build)()
    }

    fn dependencies(&self) -> Vec<PathBuf> {
        self.files.clone()
    }
}
