//! Reading one input with bounded work (docs/certificate-format.md §7, "Inputs"): regular files
//! only (a FIFO or a device is never opened), at most `max_bytes` read (a link to /dev/zero
//! cannot exhaust memory), gzip'd files decompressed (to at most `max_bytes`), and the text
//! must be UTF-8. Every refusal says why.

use super::files::describe;
use std::io::Read as _;
use std::path::Path;

/// What reading a file gave.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Input {
    /// The text, and whether it was gzip'd.
    Text {
        /// The (decompressed) text.
        text: String,
        /// Whether the file was gzip'd.
        gzip: bool,
    },
    /// Larger than the limit `max-file-size` (its size, or a lower bound).
    TooLarge {
        /// What was too large, in words.
        what: String,
    },
    /// Not readable as certificate text, and why.
    Unreadable(String),
}

/// What kind of non-regular file `m` is, in words.
fn kind(m: &std::fs::Metadata) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    let t = m.file_type();
    if t.is_dir() {
        "a directory"
    } else if t.is_fifo() {
        "a FIFO (named pipe)"
    } else if t.is_char_device() {
        "a character device"
    } else if t.is_block_device() {
        "a block device"
    } else if t.is_socket() {
        "a socket"
    } else {
        "not a regular file"
    }
}

/// At most `max + 1` bytes of `r` (one more than allowed shows that there are too many).
fn bounded(r: impl std::io::Read, max: u64) -> std::io::Result<Vec<u8>> {
    let mut buf = Vec::new();
    r.take(max.saturating_add(1)).read_to_end(&mut buf)?;
    Ok(buf)
}

/// Reads `path` as certificate (or proof) text, with at most `max_bytes` bytes read or
/// decompressed.
pub fn read_input(path: &Path, max_bytes: u64) -> Input {
    let meta = match std::fs::metadata(path) {
        Ok(m) => m,
        Err(e) => return Input::Unreadable(format!("cannot read: {}", describe(&e))),
    };
    if !meta.is_file() {
        return Input::Unreadable(format!("not a regular file: {}", kind(&meta)));
    }
    let too_large = |what: String| Input::TooLarge { what };
    if meta.len() > max_bytes {
        return too_large(format!("the file has {} bytes", meta.len()));
    }
    let bytes = match std::fs::File::open(path).and_then(|f| bounded(f, max_bytes)) {
        Ok(b) => b,
        Err(e) => return Input::Unreadable(format!("cannot read: {}", describe(&e))),
    };
    if bytes.len() as u64 > max_bytes {
        return too_large(format!("the file grew beyond {max_bytes} bytes while it was read"));
    }
    let gzip = bytes.starts_with(&[0x1f, 0x8b]);
    let bytes = if gzip {
        match bounded(flate2::read::GzDecoder::new(&bytes[..]), max_bytes) {
            Ok(b) if b.len() as u64 > max_bytes => {
                return too_large(format!("the gzip'd file decompresses to more than {max_bytes} bytes"));
            }
            Ok(b) => b,
            Err(e) => return Input::Unreadable(format!("a gzip'd file that does not decompress: {e}")),
        }
    } else {
        bytes
    };
    match String::from_utf8(bytes) {
        Ok(text) => Input::Text { text, gzip },
        Err(e) => Input::Unreadable(not_utf8(e.as_bytes(), e.utf8_error().valid_up_to())),
    }
}

/// Why bytes are not UTF-8 text, naming common binary formats.
fn not_utf8(bytes: &[u8], at: usize) -> String {
    let formats: [(&[u8], &str); 5] = [
        (b"PK\x03\x04", "a zip archive"),
        (b"\xfd7zXZ", "an xz archive"),
        (b"BZh", "a bzip2 archive"),
        (b"\x28\xb5\x2f\xfd", "a zstd archive"),
        (b"\xff\xfe", "UTF-16 text"),
    ];
    let hint =
        formats.iter().find(|(magic, _)| bytes.starts_with(magic)).map_or(String::new(), |(_, name)| {
            format!(" (it looks like {name}; certificates are UTF-8 text, plain or gzip'd)")
        });
    format!("not UTF-8 text: byte {at} (0x{:02x}) is not valid UTF-8{hint}", bytes[at])
}
