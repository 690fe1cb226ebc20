//! Lines and columns, counted as the tokenizer goes. A cursor stands at an offset of the
//! decoded text with the line, column and UTF-16 units there; it moves to each offset a
//! finding or an origin needs, counting the bytes in between, which are at hand: the text
//! never goes before the cursor has passed it (see [`Lines::release`]). Nothing is read a
//! second time, so a position is that of the text the load read.
#![forbid(unsafe_code)]

use crate::error::Position;
use crate::input::Encoding;

const UTF8_BOM_LEN: u64 = 3;

/// A place in the text: its offset, line, column (characters from 1), the UTF-16 code
/// units before it (for UTF-16 files), and whether the byte before it is a carriage return
/// (so that a line feed after it ends no second line).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Cursor {
    offset: usize,
    line: u32,
    column: u64,
    units: u64,
    after_cr: bool,
}

impl Cursor {
    /// The start of a text read from `offset` on, as line 1, column 1. For a piece read
    /// apart from the start of the file, its positions are counted from the piece and
    /// placed by [`Position::after`] once the piece is taken.
    pub fn start(offset: usize) -> Cursor {
        Cursor { offset, line: 1, column: 1, units: 0, after_cr: false }
    }

    /// The cursor at `offset` of a UTF-8 text with `position`, as a piece read before it on
    /// the same thread ends there, before the `<` of an item.
    pub fn at(offset: usize, position: Position) -> Cursor {
        let column = u64::from(position.column);
        Cursor { offset, line: position.line, column, units: 0, after_cr: false }
    }
}

/// The cursors of one reader: `mark`, where the last offset was placed, and `base`, where
/// the text at hand may begin (no earlier offset is placed any more).
pub(crate) struct Lines {
    encoding: Encoding,
    mark: Cursor,
    base: Cursor,
}

impl Lines {
    pub fn new(encoding: Encoding, start: Cursor) -> Lines {
        Lines { encoding, mark: start, base: start }
    }

    /// Goes on from `cursor`: what lies before it was counted elsewhere.
    pub fn resume(&mut self, cursor: Cursor) {
        (self.mark, self.base) = (cursor, cursor);
    }

    /// The position of offset `at`, which lies in `text` (the text at hand, from offset
    /// `from` on) at or after the last offset released.
    pub fn locate(&mut self, text: &str, from: usize, at: usize) -> Position {
        self.mark = self.cursor(text.as_bytes(), from, at);
        self.position(&self.mark)
    }

    /// The cursor at `at`, which the text before `keep` is about to go: no offset before it
    /// is placed any more.
    pub fn release(&mut self, text: &str, from: usize, keep: usize) {
        if keep > self.base.offset {
            self.mark = self.cursor(text.as_bytes(), from, keep);
            self.base = self.mark;
        }
    }

    /// The cursor at `at`, counted from the mark forward, or backward from it to the start
    /// of `at`'s line (from the base when that line starts before the text at hand).
    fn cursor(&self, text: &[u8], from: usize, at: usize) -> Cursor {
        let (mark, base) = (self.mark, self.base);
        let byte = |offset: usize| text.get(offset.wrapping_sub(from)).copied();
        let span = |a: usize, b: usize| text.get(a - from..b - from).unwrap_or_default();
        if at >= mark.offset {
            return self.advance(mark, span(mark.offset, at));
        }
        debug_assert!(at >= base.offset, "{at} was released (at {})", base.offset);
        let at = at.max(base.offset);
        let after_cr = match at {
            at if at == base.offset => base.after_cr,
            at => byte(at - 1) == Some(b'\r'),
        };
        let between = span(at, mark.offset);
        let units = mark.units - self.units(between);
        if memchr::memchr2(b'\n', b'\r', between).is_none() {
            let column = mark.column - characters(between);
            return Cursor { offset: at, column, units, after_cr, ..mark };
        }
        let line = mark.line - line_ends(between, after_cr);
        match memchr::memrchr2(b'\n', b'\r', span(base.offset, at)) {
            Some(end) => {
                let start = base.offset + end + 1;
                let column = 1 + characters(span(start, at));
                Cursor { offset: at, line, column, units, after_cr }
            }
            None => self.advance(base, span(base.offset, at)),
        }
    }

    /// `cursor` moved past `bytes`.
    fn advance(&self, cursor: Cursor, bytes: &[u8]) -> Cursor {
        let column = match memchr::memrchr2(b'\n', b'\r', bytes) {
            Some(end) => 1 + characters(&bytes[end + 1..]),
            None => cursor.column + characters(bytes),
        };
        Cursor {
            offset: cursor.offset + bytes.len(),
            line: cursor.line.saturating_add(line_ends(bytes, cursor.after_cr)),
            column,
            units: cursor.units + self.units(bytes),
            after_cr: bytes.last().map_or(cursor.after_cr, |&b| b == b'\r'),
        }
    }

    /// The UTF-16 code units of `bytes` (UTF-8 text) in a UTF-16 file; 0 otherwise.
    fn units(&self, bytes: &[u8]) -> u64 {
        match self.encoding {
            // A character of four UTF-8 bytes is two units; every other is one.
            Encoding::Utf16 { .. } => {
                characters(bytes) + bytes.iter().filter(|&&b| b >= 0xF0).count() as u64
            }
            Encoding::Utf8 { .. } => 0,
        }
    }

    fn position(&self, cursor: &Cursor) -> Position {
        let byte_offset = match self.encoding {
            Encoding::Utf8 { bom } => cursor.offset as u64 + if bom { UTF8_BOM_LEN } else { 0 },
            Encoding::Utf16 { .. } => 2 + 2 * cursor.units,
        };
        let column = u32::try_from(cursor.column).unwrap_or(u32::MAX - 1);
        Position { line: cursor.line, column, byte_offset }
    }
}

/// The lines `bytes` end, as editors end them: at LF, at CR LF and at a lone CR. An LF first
/// in `bytes` after a CR just before them (`after_cr`) ends none.
fn line_ends(bytes: &[u8], after_cr: bool) -> u32 {
    let (feeds, returns) = feeds_and_returns(bytes);
    let mut ends = feeds + returns;
    if after_cr && bytes.first() == Some(&b'\n') {
        ends -= 1;
    }
    if returns > 0 {
        let pairs = memchr::memchr_iter(b'\r', bytes).filter(|&r| bytes.get(r + 1) == Some(&b'\n'));
        ends -= pairs.count() as u64;
    }
    u32::try_from(ends).unwrap_or(u32::MAX)
}

/// How many bytes of `bytes` are line feeds and carriage returns. A load from a path counts
/// every byte it lets go this way, and a load from memory with warnings every byte up to
/// the last one: bytecount counts them with the vector instructions the machine has (32
/// bytes at a time where a byte-by-byte loop the compiler vectorises took 16), which the
/// crate's own code may not use without unsafe.
fn feeds_and_returns(bytes: &[u8]) -> (u64, u64) {
    (bytecount::count(bytes, b'\n') as u64, bytecount::count(bytes, b'\r') as u64)
}

/// The characters of UTF-8 `bytes`: every byte that does not continue a sequence.
fn characters(bytes: &[u8]) -> u64 {
    bytecount::num_chars(bytes) as u64
}

#[cfg(test)]
mod tests;
