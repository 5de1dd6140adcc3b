//! The seed's image format: binary PPM (P6), 8-bit sRGB, streamed row by row.

use super::output_file::OutputFile;
use super::writeback::WritebackFile;
use crate::Error;
use crate::still::RowSink;
use std::io::{BufWriter, Write};
use std::path::Path;

pub struct PpmStill {
    file: OutputFile,
    writer: BufWriter<WritebackFile>,
}

impl PpmStill {
    pub fn create(path: &Path, (width, height): (u32, u32)) -> Result<PpmStill, Error> {
        let (file, handle) = OutputFile::create(path)?;
        let mut writer = BufWriter::new(WritebackFile::new(handle));
        write!(writer, "P6\n{width} {height}\n255\n").map_err(|e| Error::write(path, e))?;
        Ok(PpmStill { file, writer })
    }

    pub fn finish(mut self) -> Result<(), Error> {
        let path = self.file.destination().to_path_buf();
        self.writer.flush().map_err(|e| Error::write(&path, e))?;
        drop(self.writer);
        self.file.commit()
    }
}

impl RowSink for PpmStill {
    fn write_rows(&mut self, rgb: &[u8]) -> Result<(), String> {
        self.writer.write_all(rgb).map_err(|e| e.to_string())
    }
}
