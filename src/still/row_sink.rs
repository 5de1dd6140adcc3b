//! Where a still's finished rows go.

/// Where finished rows go (a PNG or PPM encoder): 3 bytes per pixel, top row first. `Send`, so
/// whichever rendering thread finishes the next strip can write it.
pub trait RowSink: Send {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String>;
}
