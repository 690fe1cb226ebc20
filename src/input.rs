//! From the bytes of a file to UTF-8 text, and from offsets in that text back to lines,
//! columns and byte offsets in the file.
//!
//! A [`Source`] is the decoded text of a file: all of it, borrowed, for a file in memory;
//! a window that moves forward in chunks for a UTF-8 file read from a path, so a load never
//! holds the whole file. Either way the text stops at the first byte that cannot be text
//! (invalid UTF-8, a NUL or another character XML does not allow, an unpaired UTF-16
//! surrogate, a read error) and the source says why, so a load reports the first problem
//! in the file whichever way it was read.
#![forbid(unsafe_code)]

use std::borrow::Cow;
use std::fs::File;
use std::io::{Read, Seek, SeekFrom};
use std::path::Path;

use crate::LoadOptions;
use crate::error::{Code, Error, Finding, Position};

/// How the file's bytes were encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Utf8 { bom: bool },
    Utf16 { big_endian: bool },
}

/// Bytes read from a file at a time.
const CHUNK: usize = 1 << 16;

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// The decoded text of a file (the byte-order mark removed), whole or a moving window.
pub struct Source<'a> {
    /// The text from `base` on that is at hand.
    text: Cow<'a, str>,
    base: usize,
    /// The rest of a file read from a path.
    file: Option<Stream>,
    /// Why the text ends early; None when it ends with the file.
    stop: Option<Finding>,
    encoding: Encoding,
    /// Where the text came from, for the message of a read error.
    origin: Origin<'a>,
}

#[derive(Clone)]
enum Origin<'a> {
    Memory,
    Path(&'a Path),
}

/// A UTF-8 file being read.
struct Stream {
    file: File,
    /// Its size when it was opened, and the bytes of its byte-order mark.
    len: u64,
    bom: u64,
    /// The bytes of a character split by the end of the last chunk.
    pending: Vec<u8>,
    /// Bytes read so far, against the input limit.
    read: u64,
    max: u64,
}

impl<'a> Source<'a> {
    /// The text of a file in memory. Errors are those found before any text: the size
    /// limit and UTF-16 without a byte-order mark.
    pub fn memory(bytes: &'a [u8], options: &LoadOptions) -> Result<Source<'a>, Error> {
        if bytes.len() as u64 > options.max_input_bytes {
            return Err(too_big(options.max_input_bytes));
        }
        let (text, encoding, stop) = match bytes {
            [0xFF, 0xFE, rest @ ..] => decode_utf16(rest, false),
            [0xFE, 0xFF, rest @ ..] => decode_utf16(rest, true),
            _ => {
                let bom = bytes.starts_with(UTF8_BOM);
                let body = if bom { &bytes[UTF8_BOM.len()..] } else { bytes };
                check_utf16_without_bom(body)?;
                let (text, stop) = valid_prefix(body, 0);
                (Cow::Borrowed(text), Encoding::Utf8 { bom }, stop)
            }
        };
        let (text, stop) = cut_at_non_char(text, 0, stop);
        Ok(Source { text, base: 0, file: None, stop, encoding, origin: Origin::Memory })
    }

    /// Where a second reader may read pieces of this text: a UTF-8 text in memory that is
    /// valid to its end, or a UTF-8 file being read (through a second handle on it).
    pub fn pieces(&self) -> Option<Pieces<'a>> {
        match (&self.text, &self.stop, &self.file) {
            (Cow::Borrowed(text), None, None) => {
                let bom = matches!(self.encoding, Encoding::Utf8 { bom: true });
                Some(Pieces::Memory { text, bom })
            }
            (_, None, Some(stream)) => Some(Pieces::File {
                file: second_handle(&stream.file)?,
                bom: stream.bom,
                len: usize::try_from(stream.len - stream.bom).ok()?,
            }),
            _ => None,
        }
    }

    /// The text of the file at `path`: UTF-8 is read a chunk at a time as the parser needs
    /// it; UTF-16 is read and converted whole.
    pub fn path(path: &'a Path, options: &LoadOptions) -> Result<Source<'a>, Error> {
        let io = |e: std::io::Error| io_error(path, &e);
        let mut file = File::open(path).map_err(io)?;
        if file.metadata().map_err(io)?.len() > options.max_input_bytes {
            return Err(too_big(options.max_input_bytes));
        }
        let mut head = Vec::with_capacity(CHUNK);
        (&mut file).take(CHUNK as u64).read_to_end(&mut head).map_err(io)?;
        if head.starts_with(&[0xFF, 0xFE]) || head.starts_with(&[0xFE, 0xFF]) {
            let mut bytes = head;
            file.read_to_end(&mut bytes).map_err(io)?;
            let source = Source::memory(&bytes, options)?;
            let (text, stop) = (Cow::Owned(source.text.into_owned()), source.stop);
            let origin = Origin::Path(path);
            return Ok(Source {
                text,
                base: 0,
                file: None,
                stop,
                encoding: source.encoding,
                origin,
            });
        }
        let bom = head.starts_with(UTF8_BOM);
        let body = if bom { &head[UTF8_BOM.len()..] } else { &head[..] };
        check_utf16_without_bom(body)?;
        let mut source = Source {
            text: Cow::Owned(String::new()),
            base: 0,
            file: Some(Stream {
                len: file.metadata().map_err(io)?.len(),
                bom: if bom { UTF8_BOM.len() as u64 } else { 0 },
                file,
                pending: Vec::new(),
                read: head.len() as u64,
                max: options.max_input_bytes,
            }),
            stop: None,
            encoding: Encoding::Utf8 { bom },
            origin: Origin::Path(path),
        };
        source.append(body, head.len() < CHUNK);
        Ok(source)
    }

    pub fn encoding(&self) -> Encoding {
        self.encoding
    }

    /// The text at hand, which starts at offset [`Source::base`].
    pub fn text(&self) -> &str {
        &self.text
    }

    pub fn base(&self) -> usize {
        self.base
    }

    /// The offset just past the text at hand.
    pub fn end(&self) -> usize {
        self.base + self.text.len()
    }

    /// Why the text ends early, once no more can be read.
    pub fn stop(&self) -> Option<&Finding> {
        self.stop.as_ref().filter(|_| self.file.is_none())
    }

    /// The text between two offsets, when it is at hand.
    pub fn slice(&self, from: usize, to: usize) -> &str {
        let (from, to) = (from.saturating_sub(self.base), to.saturating_sub(self.base));
        self.text.get(from..to).unwrap_or_default()
    }

    /// Reads more of the file, letting go of the text before offset `keep`. Returns false
    /// when the text at hand is all there is.
    pub fn more(&mut self, keep: usize) -> bool {
        let end = self.end();
        let Some(stream) = &mut self.file else {
            return false;
        };
        let text = self.text.to_mut();
        let drop = keep.saturating_sub(self.base).min(text.len());
        if drop >= text.len() / 2 {
            text.drain(..drop);
            self.base += drop;
        }
        let mut chunk = std::mem::take(&mut stream.pending);
        let had = chunk.len();
        let read = (&mut stream.file).take(CHUNK as u64).read_to_end(&mut chunk);
        match read {
            Ok(n) => {
                stream.read += n as u64;
                if stream.read > stream.max {
                    // The file grew past the limit since its size was checked.
                    let message = too_big(stream.max).message;
                    self.stop = Some(Finding {
                        position: None,
                        code: Code::LimitExceeded,
                        at: end,
                        message,
                    });
                    self.file = None;
                    return false;
                }
                let before = self.end();
                self.append(&chunk, n == 0 && had == chunk.len());
                self.end() > before || self.file.is_some() && self.more(keep)
            }
            Err(e) => {
                let message = match &self.origin {
                    Origin::Path(path) => io_error(path, &e).message,
                    Origin::Memory => e.to_string(),
                };
                self.stop = Some(Finding { position: None, code: Code::Io, at: end, message });
                self.file = None;
                false
            }
        }
    }

    /// Goes on reading a file at `offset`, past the text at hand, as if what lies between
    /// had been read (another reader read it); false when that cannot be done. A text that
    /// is all at hand has nothing to skip.
    pub fn skip_to(&mut self, offset: usize) -> bool {
        let end = self.end();
        let Some(stream) = &mut self.file else {
            return true;
        };
        let at = stream.bom + offset as u64;
        if offset < end || stream.file.seek(SeekFrom::Start(at)).is_err() {
            return false;
        }
        stream.pending.clear();
        stream.read = at;
        self.text.to_mut().clear();
        self.base = offset;
        true
    }

    /// Appends the valid text of `bytes`; `last` says the file ends with them.
    fn append(&mut self, bytes: &[u8], last: bool) {
        let at = self.end();
        let (valid, mut stop) = valid_prefix(bytes, at);
        // A character cut by the end of the chunk is completed by the next one.
        let tail = &bytes[valid.len()..];
        if stop.is_some() && !last && could_continue(tail) {
            if let Some(stream) = &mut self.file {
                stream.pending = tail.to_vec();
            }
            stop = None;
        }
        let (valid, stop) = cut_at_non_char(Cow::Borrowed(valid), at, stop);
        self.text.to_mut().push_str(&valid);
        if stop.is_some() || last {
            self.stop = stop;
            self.file = None;
        }
    }

    /// Whether all the text is at hand, from its start (and so stays at hand).
    pub fn is_whole(&self) -> bool {
        self.base == 0 && self.file.is_none()
    }
}

/// The text of a file as a second reader reads it: whole in memory, or a piece at a time
/// from the file that is being read, through a handle of its own.
pub enum Pieces<'a> {
    /// A text in memory, and whether its file began with a byte-order mark (for positions).
    Memory {
        text: &'a str,
        bom: bool,
    },
    File {
        file: File,
        bom: u64,
        len: usize,
    },
}

impl<'a> Pieces<'a> {
    /// The length of the text.
    pub fn len(&self) -> usize {
        match self {
            Pieces::Memory { text, .. } => text.len(),
            Pieces::File { len, .. } => *len,
        }
    }

    /// The bytes of the text from `from` to `to` (within it), which may cut a character.
    pub fn bytes(&self, from: usize, to: usize) -> Option<Cow<'a, [u8]>> {
        match self {
            Pieces::Memory { text, .. } => text.as_bytes().get(from..to).map(Cow::Borrowed),
            Pieces::File { file, bom, .. } => {
                let mut bytes = vec![0; to.checked_sub(from)?];
                read_exact_at(file, &mut bytes, bom + from as u64).ok()?;
                Some(Cow::Owned(bytes))
            }
        }
    }

    /// A source that holds the text from `from` to `to`, at its offsets in the whole (a text
    /// in memory, checked already, all of it up to `to`); None unless that is all text
    /// (valid UTF-8, only characters XML allows).
    pub fn source(&self, from: usize, to: usize) -> Option<Source<'a>> {
        let (text, base, encoding) = match self {
            Pieces::Memory { text, bom } => {
                (Cow::Borrowed(text.get(..to)?), 0, Encoding::Utf8 { bom: *bom })
            }
            Pieces::File { bom, .. } => {
                let text = String::from_utf8(self.bytes(from, to)?.into_owned()).ok()?;
                if first_non_char(text.as_bytes()).is_some() {
                    return None;
                }
                (Cow::Owned(text), from, Encoding::Utf8 { bom: *bom > 0 })
            }
        };
        // A piece is read whole: it has no file to read on from.
        Some(Source { text, base, file: None, stop: None, encoding, origin: Origin::Memory })
    }
}

/// A second handle on `file`, for the second thread: the very file the first reads (not
/// one opened anew by its path, which may have been replaced since), read at offsets of
/// its own that leave the first handle's position alone. Unix's positional reads promise
/// that; elsewhere a file is read on one thread.
#[cfg(unix)]
fn second_handle(file: &File) -> Option<File> {
    file.try_clone().ok()
}

#[cfg(not(unix))]
fn second_handle(_: &File) -> Option<File> {
    None
}

#[cfg(unix)]
fn read_exact_at(file: &File, bytes: &mut [u8], offset: u64) -> std::io::Result<()> {
    std::os::unix::fs::FileExt::read_exact_at(file, bytes, offset)
}

#[cfg(not(unix))]
fn read_exact_at(_: &File, _: &mut [u8], _: u64) -> std::io::Result<()> {
    Err(std::io::ErrorKind::Unsupported.into())
}

/// Whether `tail` is the start of a multi-byte UTF-8 character.
fn could_continue(tail: &[u8]) -> bool {
    let need = match tail.first() {
        Some(b) if b & 0xE0 == 0xC0 => 2,
        Some(b) if b & 0xF0 == 0xE0 => 3,
        Some(b) if b & 0xF8 == 0xF0 => 4,
        _ => return false,
    };
    tail.len() < need && tail[1..].iter().all(|b| b & 0xC0 == 0x80)
}

/// The longest valid UTF-8 prefix of `bytes`, and the `invalid-utf8` stop after it.
fn valid_prefix(bytes: &[u8], base: usize) -> (&str, Option<Finding>) {
    match std::str::from_utf8(bytes) {
        Ok(text) => (text, None),
        Err(e) => {
            let valid = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default();
            let stop = Finding {
                position: None,
                code: Code::InvalidUtf8,
                at: base + valid.len(),
                message: "the file is not valid UTF-8 here: save it as UTF-8 (a file in a legacy \
                          code page must be converted)"
                    .into(),
            };
            (valid, Some(stop))
        }
    }
}

/// `text` up to its first character that XML does not allow (outside the Char production
/// of XML 1.0: a control character other than tab, line feed and carriage return, U+FFFE,
/// U+FFFF), which stops the text there. A NUL has its own code: it usually means the file
/// is not text at all.
fn cut_at_non_char(
    text: Cow<'_, str>,
    base: usize,
    stop: Option<Finding>,
) -> (Cow<'_, str>, Option<Finding>) {
    let Some(at) = first_non_char(text.as_bytes()) else {
        return (text, stop);
    };
    let stop = match text.as_bytes()[at] {
        0 => Finding {
            position: None,
            code: Code::NulByte,
            at: base + at,
            message: "the file holds a NUL byte: it is not a text file (or it was truncated or \
                      padded)"
                .into(),
        },
        _ => {
            let c = text[at..].chars().next().unwrap_or_default();
            Finding {
                position: None,
                code: Code::MalformedXml,
                at: base + at,
                message: format!(
                    "malformed XML: the character U+{:04X} is not allowed in an XML document",
                    u32::from(c)
                ),
            }
        }
    };
    let text = match text {
        Cow::Borrowed(t) => Cow::Borrowed(&t[..at]),
        Cow::Owned(mut t) => {
            t.truncate(at);
            Cow::Owned(t)
        }
    };
    (text, Some(stop))
}

/// The offset of the first character of `text` outside XML's Char production (the writer
/// and the builder check names with it too). Blocks of
/// 64 bytes are screened by a loop the compiler vectorises for a suspect byte: a control
/// character other than tab, line feed and carriage return, or any byte past ASCII (0xEF
/// begins U+FFFE and U+FFFF). Only a block with one is looked at byte by byte; the usual
/// file, with no control characters and little text past ASCII, has few.
pub(crate) fn first_non_char(text: &[u8]) -> Option<usize> {
    let non_char = |&i: &usize| match text[i] {
        0xEF => matches!(text[i + 1..], [0xBF, 0xBE | 0xBF, ..]),
        b => b < 0x20 && !matches!(b, b'\t' | b'\n' | b'\r'),
    };
    let mut from = 0;
    while let Some(block) = text[from..].first_chunk::<64>() {
        // As a signed byte, every byte past ASCII is below 0x20 too.
        let suspect = |b: u8| ((b as i8) < 0x20) & (b != b'\t') & (b != b'\n') & (b != b'\r');
        if block.iter().fold(false, |any, &b| any | suspect(b))
            && let Some(at) = (from..from + block.len()).find(non_char)
        {
            return Some(at);
        }
        from += block.len();
    }
    (from..text.len()).find(non_char)
}

/// `<` followed or preceded by a zero byte: UTF-16 text that lost its byte-order mark.
fn check_utf16_without_bom(bytes: &[u8]) -> Result<(), Error> {
    if !matches!(bytes, [b'<', 0, ..] | [0, b'<', ..]) {
        return Ok(());
    }
    Err(Error {
        code: Code::UnsupportedEncoding,
        position: Position { line: 1, column: 1, byte_offset: 0 },
        message: "the file looks like UTF-16 without a byte-order mark; save it as UTF-8, or as \
                  UTF-16 with a byte-order mark"
            .into(),
    })
}

fn decode_utf16(bytes: &[u8], big_endian: bool) -> (Cow<'static, str>, Encoding, Option<Finding>) {
    let units = bytes.chunks_exact(2).map(|pair| {
        let pair = [pair[0], pair[1]];
        if big_endian { u16::from_be_bytes(pair) } else { u16::from_le_bytes(pair) }
    });
    let mut text = String::with_capacity(bytes.len() / 2);
    let mut valid = bytes.len() % 2 == 0;
    for unit in char::decode_utf16(units) {
        match unit {
            Ok(c) => text.push(c),
            Err(_) => {
                valid = false;
                break;
            }
        }
    }
    let stop = (!valid).then(|| Finding {
        position: None,
        code: Code::InvalidUtf8,
        at: text.len(),
        message: "the file is not valid UTF-16 here (an unpaired surrogate or an odd number of \
                  bytes)"
            .into(),
    });
    (Cow::Owned(text), Encoding::Utf16 { big_endian }, stop)
}

/// The `limit-exceeded` error of an input larger than `max` bytes.
pub fn too_big(max: u64) -> Error {
    Error {
        code: Code::LimitExceeded,
        position: Position::default(),
        message: format!("the file is larger than the input size limit (max_input_bytes = {max})"),
    }
}

pub fn io_error(path: &Path, e: &std::io::Error) -> Error {
    Error {
        code: Code::Io,
        position: Position::default(),
        message: format!("cannot read {}: {e}", path.display()),
    }
}

#[cfg(test)]
mod tests {
    use super::{Pieces, Source};
    use crate::LoadOptions;

    /// The second thread reads the file the first one opened, even when another file has
    /// been renamed over its path since (as editors save).
    #[cfg(unix)]
    #[test]
    fn pieces_of_a_file_come_from_the_file_opened_not_its_path() {
        let dir = std::env::temp_dir();
        let (path, other) = (
            dir.join(format!("box2scene-pieces-{}.xml", std::process::id())),
            dir.join(format!("box2scene-pieces-{}-new.xml", std::process::id())),
        );
        let text = |c: &str| format!("<World>{}</World>", c.repeat(200_000));
        std::fs::write(&path, text("a")).unwrap();
        std::fs::write(&other, text("b")).unwrap();
        let options = LoadOptions::default();
        let source = Source::path(&path, &options).unwrap();
        std::fs::rename(&other, &path).unwrap();
        let Some(pieces @ Pieces::File { .. }) = source.pieces() else {
            panic!("a UTF-8 file being read has pieces")
        };
        assert_eq!(pieces.len(), text("a").len());
        assert_eq!(&*pieces.bytes(150_000, 150_004).unwrap(), b"aaaa");
        let piece = pieces.source(100_000, 100_010).unwrap();
        assert_eq!(piece.slice(100_000, 100_010), "aaaaaaaaaa");
        std::fs::remove_file(&path).unwrap();
    }
}
