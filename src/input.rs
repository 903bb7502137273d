//! Reading an input file (scene, history CSV, measurement, calibration,
//! study or sweep JSON, reference CSV) with a size cap, so that a huge file
//! or an endless one (`/dev/zero`) is refused at once in bounded memory
//! instead of being read whole.

use std::io::Read;
use std::path::Path;

/// Largest input file: 256 MiB. The largest inputs are the JSON shards of a
/// study for `merge` (about 1 KB per kept record at one evaluation point,
/// so 256 MiB holds some 250 000 records); parsing one takes a few times its
/// size in memory.
pub const MAX_INPUT_BYTES: u64 = 256 << 20;

/// The text of `path`, refused (an `InvalidData` error giving the size and
/// the bound) if it holds more than [`MAX_INPUT_BYTES`]: a regular file by
/// its size before anything is read, any other (a pipe, a device) once
/// more than the bound has arrived. A leading UTF-8 byte-order mark is
/// dropped. The file is noted as an input of the command
/// (`output::inputs`), which no output of it may replace.
pub fn read_to_string(path: impl AsRef<Path>) -> std::io::Result<String> {
    let file = std::fs::File::open(&path)?;
    let meta = file.metadata()?;
    if meta.is_file() {
        crate::output::inputs::register(path.as_ref(), &file);
    }
    if meta.is_file() && meta.len() > MAX_INPUT_BYTES {
        return Err(too_large(&format!("{} bytes", meta.len())));
    }
    let mut text = String::new();
    file.take(MAX_INPUT_BYTES + 1).read_to_string(&mut text)?;
    if text.len() as u64 > MAX_INPUT_BYTES {
        return Err(too_large(&format!("more than {MAX_INPUT_BYTES} bytes")));
    }
    if text.starts_with(BOM) {
        text.drain(..BOM.len_utf8());
    }
    Ok(text)
}

/// The UTF-8 byte-order mark some editors put at the start of a file.
const BOM: char = '\u{feff}';

/// `text` without a leading byte-order mark (a file's text passed as a
/// string: Python's `Study.from_json`, the delimited readers);
/// [`read_to_string`] drops it too, so that a scene, a CSV and a JSON
/// document read the same with or without.
pub fn without_bom(text: &str) -> &str {
    text.strip_prefix(BOM).unwrap_or(text)
}

fn too_large(size: &str) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        format!(
            "the file holds {size}, above the bound of {MAX_INPUT_BYTES} bytes (256 MiB) for an input file"
        ),
    )
}
