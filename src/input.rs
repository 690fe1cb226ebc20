//! From the bytes of a file to UTF-8 text, and from offsets in that text back to lines,
//! columns and byte offsets in the file.
//!
//! A [`Source`] is the decoded text of a file: all of it, borrowed, for a file in memory
//! (at hand as far as it was checked for characters XML does not allow, a chunk at a time
//! as it is read); a window that moves forward in chunks for a UTF-8 file read from a path
//! or a stream, so a load never holds the whole file. Either way the text stops at the first
//! byte that cannot be text (invalid UTF-8, a NUL or another character XML does not allow,
//! an unpaired UTF-16 surrogate, a read error) or at the input limit, and the source says
//! why, so a load reports the first problem in the file whichever way it was read.
#![forbid(unsafe_code)]

use std::borrow::Cow;
use std::fs::File;
use std::io::Read;
use std::path::Path;

use crate::bytes::first_non_char;

mod shared;

use crate::error::{Code, Error, Finding, Position};
use crate::options::LoadOptions;
pub use shared::Shared;

/// How the file's bytes were encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Utf8 { bom: bool },
    Utf16 { big_endian: bool },
}

/// Bytes read from a file at a time.
const CHUNK: usize = 1 << 16;

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// The most bytes a character takes in UTF-8.
const MAX_CHAR: usize = 4;

/// The decoded text of a file (the byte-order mark removed), whole or a moving window.
pub struct Source<'a> {
    /// The text from `base` on that is at hand.
    text: Cow<'a, str>,
    base: usize,
    /// A text that is borrowed (in memory, or a piece read into a reader's buffer): all of
    /// it from `base` on, of which `text` is what lies before `checked`.
    whole: Option<&'a str>,
    /// Whether the text stays at hand once read (see [`Source::is_whole`]): not a piece of a
    /// file read into a buffer that the next piece reuses.
    stays: bool,
    /// Whether the text ends before the file does, where a piece of it ends (see
    /// [`Source::ends_early`]).
    ends_early: bool,
    /// How far a text in memory was checked for characters XML does not allow: it is
    /// checked as it is read, a chunk at a time, by the reader that reads it (see
    /// [`Source::more`]), so that each of two threads checks what it reads.
    checked: usize,
    /// The rest of a file (or a stream) being read.
    file: Option<Stream<'a>>,
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

/// What a text is read from: a file, or a stream read once from where it stands (a pipe, or
/// a piece of a file read at its offsets).
enum Reader<'a> {
    File(File),
    Stream(Box<dyn Read + 'a>),
}

impl Reader<'_> {
    fn read(&mut self) -> &mut dyn Read {
        match self {
            Reader::File(file) => file,
            Reader::Stream(stream) => stream,
        }
    }
}

/// A UTF-8 file being read.
struct Stream<'a> {
    file: Reader<'a>,
    /// Its size when it was opened, for a regular file (whose pieces a second reader may
    /// read), and the bytes of its byte-order mark.
    len: Option<u64>,
    bom: u64,
    /// Bytes read so far, against the input limit.
    read: u64,
    max: u64,
}

impl Stream<'_> {
    /// Reads `want` bytes of the file onto the end of `bytes`, straight into its spare
    /// room, and then the rest of a character they cut, so that the bytes end where a
    /// character ends (or where the file does). True when the file ended. Never more than
    /// one byte past the input limit (and the rest of a character): enough to see that
    /// the file goes past it.
    fn read_onto(&mut self, bytes: &mut Vec<u8>, want: usize) -> std::io::Result<bool> {
        let within = self.max.saturating_add(1).saturating_sub(self.read);
        let want = want.min(usize::try_from(within).unwrap_or(usize::MAX));
        bytes.reserve(want + MAX_CHAR - 1);
        let before = bytes.len();
        let mut read_to_end = |bytes: &mut Vec<u8>, n: usize| {
            let got = self.file.read().take(n as u64).read_to_end(bytes)?;
            // `read_to_end` stops short only at the end of the file.
            Ok::<_, std::io::Error>(got < n)
        };
        let mut ended = read_to_end(bytes, want)?;
        let missing = missing_of_last_char(&bytes[before..]);
        if !ended && missing > 0 {
            ended = read_to_end(bytes, missing)?;
        }
        self.read += (bytes.len() - before) as u64;
        Ok(ended)
    }
}

impl<'a> Source<'a> {
    /// The text of a file in memory. Errors are those found before any text: the size
    /// limit and UTF-16 without a byte-order mark.
    pub fn memory(bytes: &'a [u8], options: &LoadOptions) -> Result<Source<'a>, Error> {
        if bytes.len() as u64 > options.max_input_bytes {
            return Err(too_big(bytes.len() as u64, options.max_input_bytes));
        }
        let (text, encoding, stop) = match bytes {
            [0xFF, 0xFE, ..] | [0xFE, 0xFF, ..] => decode_utf16_within(bytes, u64::MAX),
            _ => {
                let bom = bytes.starts_with(UTF8_BOM);
                let body = if bom { &bytes[UTF8_BOM.len()..] } else { bytes };
                check_utf16_without_bom(body)?;
                let (text, stop) = valid_prefix(body, 0);
                // Checked as it is read, from the first chunk on.
                let encoding = Encoding::Utf8 { bom };
                let mut source = Source {
                    checked: 0,
                    ..Source::holding(Cow::Borrowed(text), 0, stop, encoding)
                };
                source.check_on(0);
                return Ok(source);
            }
        };
        Ok(Source::holding(text, 0, stop, encoding))
    }

    /// The whole text, any piece of which a reader of its own may read: a UTF-8 text in
    /// memory that is valid to its end, or a UTF-8 file being read (through a second handle
    /// on it). None for any other.
    pub fn shared(&self) -> Option<Shared<'a>> {
        match (self.whole, &self.stop, &self.file) {
            (Some(text), None, None) => {
                let bom = matches!(self.encoding, Encoding::Utf8 { bom: true });
                Some(Shared::Memory { text, bom })
            }
            (_, None, Some(Stream { file: Reader::File(file), len: Some(len), bom, .. })) => {
                Some(Shared::File {
                    file: shared::second_handle(file)?,
                    bom: *bom,
                    len: usize::try_from(len.checked_sub(*bom)?).ok()?,
                })
            }
            _ => None,
        }
    }

    /// The text of the file at `path`: UTF-8 is read a chunk at a time as the parser needs
    /// it; UTF-16 is read and converted whole, within the input limit.
    pub fn path(path: &'a Path, options: &LoadOptions) -> Result<Source<'a>, Error> {
        let file = File::open(path).map_err(|e| Error::cannot_read(path, &e))?;
        Source::file(file, path, options)
    }

    /// The text of an open file, read from its start, as [`Source::path`] reads it; `name`
    /// is its name in messages. A regular file larger than the input limit is refused
    /// from its size; a pipe or a device is read until it goes past the limit.
    pub fn file(file: File, name: &'a Path, options: &LoadOptions) -> Result<Source<'a>, Error> {
        let meta = file.metadata().map_err(|e| Error::cannot_read(name, &e))?;
        let len = meta.is_file().then_some(meta.len());
        if let Some(len) = len.filter(|&len| len > options.max_input_bytes) {
            return Err(too_big(len, options.max_input_bytes));
        }
        Source::read(Reader::File(file), len, name, options)
    }

    /// The text of a stream, read once from where it stands, as a pipe is; `name` is its
    /// name in messages.
    pub fn stream(
        stream: impl Read + 'a,
        name: &'a Path,
        options: &LoadOptions,
    ) -> Result<Source<'a>, Error> {
        Source::read(Reader::Stream(Box::new(stream)), None, name, options)
    }

    /// The text of `file`, of size `len` when it is known. No more than the input limit is
    /// read: past it, the text stops where the limit is, which the error names.
    fn read(
        mut file: Reader<'a>,
        len: Option<u64>,
        path: &'a Path,
        options: &LoadOptions,
    ) -> Result<Source<'a>, Error> {
        let io = |e: std::io::Error| Error::cannot_read(path, &e);
        let max = options.max_input_bytes;
        // The byte-order mark alone first, so that the text is read in place after it; room
        // for a chunk and what is kept of the one before, so the buffer seldom grows.
        let mut bytes = Vec::with_capacity(2 * CHUNK);
        file.read().take(UTF8_BOM.len() as u64).read_to_end(&mut bytes).map_err(io)?;
        if bytes.starts_with(&[0xFF, 0xFE]) || bytes.starts_with(&[0xFE, 0xFF]) {
            let room = max.saturating_sub(bytes.len() as u64).saturating_add(1);
            file.read().take(room).read_to_end(&mut bytes).map_err(io)?;
            let (text, encoding, stop) = decode_utf16_within(&bytes, max);
            let origin = Origin::Path(path);
            return Ok(Source { origin, ..Source::holding(text, 0, stop, encoding) });
        }
        let bom = bytes == UTF8_BOM;
        let mut stream = Stream {
            len,
            bom: if bom { UTF8_BOM.len() as u64 } else { 0 },
            file,
            read: bytes.len() as u64,
            max,
        };
        if bom {
            bytes.clear();
        }
        // The first chunk ends CHUNK bytes into the file, byte-order mark or not.
        let last = stream.read_onto(&mut bytes, CHUNK - stream.read as usize).map_err(io)?;
        check_utf16_without_bom(&bytes)?;
        let mut source = Source {
            origin: Origin::Path(path),
            ..Source::holding(Cow::Owned(String::new()), 0, None, Encoding::Utf8 { bom })
        };
        source.file = Some(stream);
        source.take_read(bytes, 0, last);
        Ok(source)
    }

    /// The text of a piece of a file from offset `base` on, which `piece` reads, through a
    /// window as [`Source::read`] reads a whole file (the file began with a byte-order mark
    /// when `bom`). None when its first chunk cannot be read.
    fn piece(piece: Box<dyn Read + 'a>, base: usize, bom: u64) -> Option<Source<'a>> {
        let file = Reader::Stream(piece);
        let mut stream = Stream { file, len: None, bom, read: 0, max: u64::MAX };
        let mut bytes = Vec::with_capacity(2 * CHUNK);
        let last = stream.read_onto(&mut bytes, CHUNK).ok()?;
        let encoding = Encoding::Utf8 { bom: bom > 0 };
        let mut source = Source {
            stays: false,
            ..Source::holding(Cow::Owned(String::new()), base, None, encoding)
        };
        source.file = Some(stream);
        source.take_in(bytes, 0, last);
        Some(source)
    }

    /// A source whose text at hand is `text`, from offset `base` on, checked, ending early
    /// for the reason `stop`; a text in memory, unless the caller gives it a file to read on
    /// from.
    fn holding(
        text: Cow<'a, str>,
        base: usize,
        stop: Option<Finding>,
        encoding: Encoding,
    ) -> Source<'a> {
        let whole = match text {
            Cow::Borrowed(text) => Some(text),
            Cow::Owned(_) => None,
        };
        let (file, origin, checked) = (None, Origin::Memory, usize::MAX);
        let (stays, ends_early) = (true, false);
        Source { text, base, whole, stays, ends_early, checked, file, stop, encoding, origin }
    }

    pub fn encoding(&self) -> Encoding {
        self.encoding
    }

    /// A text in memory at hand up to where it is checked.
    fn cut_whole(&mut self) {
        if let Some(whole) = self.whole {
            let cut = self.checked.checked_sub(self.base);
            self.text = Cow::Borrowed(cut.and_then(|cut| whole.get(..cut)).unwrap_or(whole));
        }
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

    /// The text between two offsets, when it is at hand; empty when it is not. Inlined:
    /// every value the reader converts is taken through it.
    #[inline]
    pub fn slice(&self, from: usize, to: usize) -> &str {
        // Before the text at hand, an offset wraps past its end, and the text is empty.
        let (from, to) = (from.wrapping_sub(self.base), to.wrapping_sub(self.base));
        self.text.get(from..to).unwrap_or_default()
    }

    /// Reads more of the file, letting go of the text before offset `keep`. Returns false
    /// when the text at hand is all there is.
    ///
    /// The file's bytes are read into the very buffer of the text, after what is kept; a
    /// byte is moved again only while it is kept, to the front when half the text can go.
    pub fn more(&mut self, keep: usize) -> bool {
        let Some(stream) = &mut self.file else {
            return self.check_on(keep);
        };
        let mut bytes = std::mem::take(self.text.to_mut()).into_bytes();
        let drop = keep.saturating_sub(self.base).min(bytes.len());
        if drop >= bytes.len() / 2 {
            bytes.drain(..drop);
            self.base += drop;
        }
        let kept = bytes.len();
        let end = self.base + kept;
        // At least as much as is kept, so that a long node that holds the text is checked
        // again at most as many times over as it is long.
        let read = stream.read_onto(&mut bytes, CHUNK.max(kept));
        let stop = match read {
            Ok(last) => {
                self.take_read(bytes, kept, last);
                return self.end() > end;
            }
            Err(e) => {
                let message = match &self.origin {
                    Origin::Path(path) => Error::cannot_read(path, &e).message,
                    Origin::Memory => e.to_string(),
                };
                Finding::new(Code::Io, end, message)
            }
        };
        bytes.truncate(kept);
        self.take_in(bytes, kept, true);
        self.stop = Some(stop);
        false
    }

    /// Checks more of a text in memory for characters XML does not
    /// allow: at least a chunk, and at least as much as is kept from `keep` on (as
    /// [`Source::more`] reads a file). The text at hand stops before the first one found,
    /// for that reason. Returns false when no more text came to hand.
    fn check_on(&mut self, keep: usize) -> bool {
        let Some(whole) = self.whole else {
            return false;
        };
        let (from, end) = (self.checked, self.end());
        if from >= whole.len() {
            return false;
        }
        let mut to = from.saturating_add(CHUNK.max(from.saturating_sub(keep))).min(whole.len());
        while !whole.is_char_boundary(to) {
            to += 1;
        }
        self.checked = match first_non_char(&whole.as_bytes()[from..to]) {
            Some(at) => {
                self.stop = Some(non_char(whole, from + at, 0));
                from + at
            }
            None => to,
        };
        self.cut_whole();
        self.end() > end
    }

    /// [`Source::take_in`] of the bytes just read from the file, or of those of them within
    /// the input limit when the file goes past it (a stream, or a file that grew since its
    /// size was checked): the text then stops at the limit.
    fn take_read(&mut self, mut bytes: Vec<u8>, kept: usize, last: bool) {
        let Some(stream) = self.file.as_ref().filter(|stream| stream.read > stream.max) else {
            return self.take_in(bytes, kept, last);
        };
        let max = stream.max;
        let within = usize::try_from(max.saturating_sub(stream.bom)).unwrap_or(usize::MAX);
        cut_to_char(&mut bytes, within.saturating_sub(self.base).max(kept));
        self.take_in(bytes, kept, true);
        self.stop = self.stop.take().or_else(|| Some(stopped_at_limit(self.end(), max)));
    }

    /// Makes `bytes` the text at hand, the first `kept` of which were the text at hand
    /// already: the rest is checked, once, to be UTF-8 of characters XML allows, and the
    /// text stops before the first problem. `last` says the file ends with them.
    fn take_in(&mut self, bytes: Vec<u8>, kept: usize, last: bool) {
        // Owning the bytes, the check makes them a string without copying them; it goes
        // over the kept bytes again, which the window keeps few (see `more`).
        let (mut text, mut stop) = match String::from_utf8(bytes) {
            Ok(text) => (text, None),
            Err(e) => {
                let valid = e.utf8_error().valid_up_to();
                let mut bytes = e.into_bytes();
                bytes.truncate(valid);
                (
                    String::from_utf8(bytes).unwrap_or_default(),
                    Some(invalid_utf8(self.base + valid)),
                )
            }
        };
        if let Some(at) = first_non_char(&text.as_bytes()[kept..]) {
            stop = Some(non_char(&text, kept + at, self.base));
            text.truncate(kept + at);
        }
        self.text = Cow::Owned(text);
        if stop.is_some() || last {
            self.stop = stop;
            self.file = None;
        }
    }

    /// Whether all the text is at hand, from its start, and stays so: what a reader finds
    /// in it can be placed once the reading is done.
    pub fn is_whole(&self) -> bool {
        self.base == 0 && self.file.is_none() && self.stays
    }

    /// Whether the text ends before the file does: the text of a piece, which ends before
    /// an item (see [`Shared::source`]).
    pub fn ends_early(&self) -> bool {
        self.ends_early
    }
}

/// How many bytes the character that `bytes` ends with lacks: none when they end with a
/// whole one, or with bytes that begin none (which the UTF-8 check reports).
fn missing_of_last_char(bytes: &[u8]) -> usize {
    let tail = &bytes[bytes.len().saturating_sub(MAX_CHAR - 1)..];
    let Some(first) = tail.iter().rposition(|b| b & 0xC0 != 0x80) else {
        return 0;
    };
    let need: usize = match tail[first] {
        b if b & 0xE0 == 0xC0 => 2,
        b if b & 0xF0 == 0xE0 => 3,
        b if b & 0xF8 == 0xF0 => 4,
        _ => 1,
    };
    need.saturating_sub(tail.len() - first)
}

/// The longest valid UTF-8 prefix of `bytes`, and the `invalid-utf8` stop after it.
fn valid_prefix(bytes: &[u8], base: usize) -> (&str, Option<Finding>) {
    if let Ok(text) = utf8(bytes) {
        return (text, None);
    }
    // simdutf8 says only that the text goes wrong; the standard library says where.
    match std::str::from_utf8(bytes) {
        Ok(text) => (text, None),
        Err(e) => {
            let valid = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default();
            (valid, Some(invalid_utf8(base + valid.len())))
        }
    }
}

/// `bytes` as a `str`, when they are UTF-8, checked by simdutf8 with the vector
/// instructions the machine has. The whole text of a load from memory is checked before a
/// second thread can begin: on the 10 MB benchmark scene, the standard library's check
/// takes 2.5 times the instructions and 1.7 times the time.
fn utf8(bytes: &[u8]) -> Result<&str, simdutf8::basic::Utf8Error> {
    simdutf8::basic::from_utf8(bytes)
}

/// The `invalid-utf8` stop at offset `at`.
fn invalid_utf8(at: usize) -> Finding {
    Finding::new(
        Code::InvalidUtf8,
        at,
        "the file is not valid UTF-8 here: save it as UTF-8 (a file in a legacy code page must \
         be converted)",
    )
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
    let stop = non_char(&text, at, base);
    let text = match text {
        Cow::Borrowed(t) => Cow::Borrowed(&t[..at]),
        Cow::Owned(mut t) => {
            t.truncate(at);
            Cow::Owned(t)
        }
    };
    (text, Some(stop))
}

/// The stop at the character at `at` in `text` (`base` is the offset of `text`), which
/// XML does not allow.
fn non_char(text: &str, at: usize, base: usize) -> Finding {
    match text.as_bytes()[at] {
        0 => Finding::new(
            Code::NulByte,
            base + at,
            "the file holds a NUL byte: it is not a text file (or it was truncated or padded)",
        ),
        _ => {
            let c = text[at..].chars().next().unwrap_or_default();
            let message = format!(
                "malformed XML: the character U+{:04X} is not allowed in an XML document",
                u32::from(c)
            );
            Finding::new(Code::MalformedXml, base + at, message)
        }
    }
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

/// The text of UTF-16 `bytes` (from their byte-order mark on), up to the first character
/// XML does not allow, and no further than the first `max` bytes: when there are more, the
/// text stops at the last character within them, for that reason.
fn decode_utf16_within(bytes: &[u8], max: u64) -> (Cow<'static, str>, Encoding, Option<Finding>) {
    let big_endian = bytes.starts_with(&[0xFE, 0xFF]);
    let over = bytes.len() as u64 > max;
    let mut body = bytes.get(2..).unwrap_or_default();
    if over {
        let within = usize::try_from(max).unwrap_or(usize::MAX).saturating_sub(2) & !1;
        body = &body[..within];
        // Without a high surrogate whose pair lies past the limit.
        let last = body.len().checked_sub(2).map(|at| [body[at], body[at + 1]]);
        let last =
            last.map(
                |pair| if big_endian { u16::from_be_bytes(pair) } else { u16::from_le_bytes(pair) },
            );
        if last.is_some_and(|unit| (0xD800..0xDC00).contains(&unit)) {
            body = &body[..body.len() - 2];
        }
    }
    let (text, encoding, stop) = decode_utf16(body, big_endian);
    let (text, stop) = cut_at_non_char(text, 0, stop);
    let stop = stop.or_else(|| over.then(|| stopped_at_limit(text.len(), max)));
    (text, encoding, stop)
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
    let stop = (!valid).then(|| {
        Finding::new(
            Code::InvalidUtf8,
            text.len(),
            "the file is not valid UTF-16 here (an unpaired surrogate or an odd number of bytes)",
        )
    });
    (Cow::Owned(text), Encoding::Utf16 { big_endian }, stop)
}

/// The `limit-exceeded` error of an input of `len` bytes, larger than `max`: refused from
/// its size, before a byte of it is read.
pub fn too_big(len: u64, max: u64) -> Error {
    Error {
        code: Code::LimitExceeded,
        position: Position::default(),
        message: format!(
            "the file is {len} bytes, larger than the input size limit (max_input_bytes = \
             {max}): nothing of it was read"
        ),
    }
}

/// The `limit-exceeded` stop of an input that goes on past `max` bytes, at offset `at` of
/// the text, where the limit is: the text read stops there.
fn stopped_at_limit(at: usize, max: u64) -> Finding {
    let message = format!(
        "the input goes on past the input size limit (max_input_bytes = {max}): it was read \
         up to here, its byte {max}, and no further"
    );
    Finding::new(Code::LimitExceeded, at, message)
}

/// Cuts `bytes` to their first `at` (when they are longer), less the start of a character
/// cut there.
fn cut_to_char(bytes: &mut Vec<u8>, at: usize) {
    bytes.truncate(at);
    if missing_of_last_char(bytes) > 0 {
        let lead = bytes.iter().rposition(|b| b & 0xC0 != 0x80).unwrap_or(0);
        bytes.truncate(lead);
    }
}

#[cfg(test)]
mod tests;
