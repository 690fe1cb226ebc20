//! The line a report quotes, read back from the file that was loaded: only the few hundred
//! bytes around the position, whatever the length of the line or of the file, so that a
//! report costs the same on a one-line file as on any other.

use std::cell::OnceCell;
use std::fs::{File, OpenOptions};
use std::io::{self, Read, Seek, SeekFrom, Write};
use std::path::PathBuf;
use std::sync::atomic::{AtomicU32, Ordering};

use box2scene::Position;
use box2scene::escape::terminal_char;
use unicode_width::UnicodeWidthStr;

/// Characters of a long line shown around the column: a file written on one line still
/// gives a report that fits a terminal.
const SHOWN: usize = 120;

/// The most bytes a character takes, in UTF-8 and in UTF-16.
const MAX_CHAR: u64 = 4;

/// How a file's text is encoded, from its first bytes, as the loader reads it.
#[derive(Clone, Copy)]
enum Encoding {
    Utf8,
    Utf16 { big_endian: bool },
}

/// Where lines are read back from: the file loaded, or the copy of a stream as it was read.
pub struct Quoted {
    file: Option<File>,
    /// The copy's name, removed when the run no longer needs it.
    spooled: Option<PathBuf>,
    /// The encoding and the length of the byte-order mark, read once.
    encoding: OnceCell<(Encoding, u64)>,
}

impl Quoted {
    /// Quotes `file` (read at offsets of its own), or nothing.
    pub fn from(file: Option<File>) -> Quoted {
        Quoted { file, spooled: None, encoding: OnceCell::new() }
    }

    /// Quotes nothing: no line is shown.
    pub fn nothing() -> Quoted {
        Quoted::from(None)
    }

    /// A new file of this run's own, readable by it alone, into which a stream is copied
    /// (see [`Quoted::copying`]); nothing when none can be made, and then no line is shown.
    pub fn spool() -> Quoted {
        static COUNTER: AtomicU32 = AtomicU32::new(0);
        let mut options = OpenOptions::new();
        options.read(true).write(true).create_new(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::mode(&mut options, 0o600);
        for _ in 0..100 {
            let unique = COUNTER.fetch_add(1, Ordering::Relaxed);
            let name = format!(".box2scene-{}-{unique}.input", std::process::id());
            let path = std::env::temp_dir().join(name);
            match options.open(&path) {
                Ok(file) => {
                    return Quoted {
                        file: Some(file),
                        spooled: Some(path),
                        encoding: OnceCell::new(),
                    };
                }
                Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
                Err(_) => break,
            }
        }
        Quoted::nothing()
    }

    /// `stream`, whose bytes are copied as they are read into the file lines are quoted
    /// from. A copy that fails stops there, and lines past it are not shown.
    pub fn copying<'q, R: Read + 'q>(&'q self, stream: R) -> impl Read + 'q {
        Copying { from: stream, to: self.file.as_ref() }
    }

    /// The line `at` points into, as much of it around the column as is shown, escaped for
    /// a terminal, and a caret line under the column; None when the position is unknown or
    /// the line cannot be read back. Tabs are kept in the caret line so that the caret
    /// lines up however wide a terminal draws them. Lines end at LF, CR LF and a lone CR,
    /// as the loader counts them.
    pub fn excerpt(&self, at: Position) -> Option<(String, String)> {
        if at.line == 0 || at.column == 0 {
            return None;
        }
        let (encoding, bom) = *self.encoding.get_or_init(|| self.encoding());
        let offset = at.byte_offset;
        // Far enough back and ahead for SHOWN characters either side, whatever they are.
        let span = SHOWN as u64 * MAX_CHAR;
        let mut start = offset.checked_sub(span).map_or(bom, |start| start.max(bom));
        if matches!(encoding, Encoding::Utf16 { .. }) {
            start += (offset - start) % 2;
        }
        let bytes = self.read(start, offset.checked_sub(start)? + span + MAX_CHAR)?;
        let split = usize::try_from(offset - start).ok()?.min(bytes.len());
        let (mut before, mut after) = bytes.split_at(split);
        let mut cut = start > bom;
        if let Encoding::Utf8 = encoding {
            // Only the line is decoded: in UTF-8 a line end is never part of a character.
            let line_end = |b: &u8| matches!(b, b'\n' | b'\r');
            if let Some(end) = before.iter().rposition(line_end) {
                (before, cut) = (&before[end..], false);
            }
            after = &after[..after.iter().position(line_end).unwrap_or(after.len())];
        }
        let before = decode(before, encoding, cut);
        let after = decode(after, encoding, false);
        let line_start = before.rfind(['\n', '\r']).map(|at| at + 1);
        let before: Vec<char> = before[line_start.unwrap_or(0)..].chars().collect();
        let after: Vec<char> = after.chars().take_while(|&c| c != '\n' && c != '\r').collect();
        let whole_start = line_start.is_some() || start == bom;
        Some(shown(&before, whole_start, &after))
    }

    /// Reads the first bytes of the file for its byte-order mark.
    fn encoding(&self) -> (Encoding, u64) {
        match self.read(0, 3).as_deref() {
            Some([0xFF, 0xFE, ..]) => (Encoding::Utf16 { big_endian: false }, 2),
            Some([0xFE, 0xFF, ..]) => (Encoding::Utf16 { big_endian: true }, 2),
            Some([0xEF, 0xBB, 0xBF]) => (Encoding::Utf8, 3),
            _ => (Encoding::Utf8, 0),
        }
    }

    /// Up to `len` bytes of the file from offset `from`.
    fn read(&self, from: u64, len: u64) -> Option<Vec<u8>> {
        let mut file = self.file.as_ref()?;
        file.seek(SeekFrom::Start(from)).ok()?;
        let mut bytes = Vec::new();
        file.take(len).read_to_end(&mut bytes).ok()?;
        Some(bytes)
    }
}

impl Drop for Quoted {
    fn drop(&mut self) {
        if let Some(path) = &self.spooled {
            let _ = std::fs::remove_file(path);
        }
    }
}

/// A stream whose bytes are copied to a file as they are read.
struct Copying<'f, R> {
    from: R,
    to: Option<&'f File>,
}

impl<R: Read> Read for Copying<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.from.read(buf)?;
        if let Some(mut to) = self.to
            && to.write_all(&buf[..n]).is_err()
        {
            self.to = None;
        }
        Ok(n)
    }
}

/// The text of `bytes`, bytes that are not text as U+FFFD; without the rest of a
/// character that `cut` says the bytes begin inside.
fn decode(bytes: &[u8], encoding: Encoding, cut: bool) -> String {
    match encoding {
        Encoding::Utf8 => {
            let skip =
                if cut { bytes.iter().take_while(|&&b| b & 0xC0 == 0x80).count() } else { 0 };
            String::from_utf8_lossy(&bytes[skip.min(3)..]).into_owned()
        }
        Encoding::Utf16 { big_endian } => {
            let units = bytes.chunks_exact(2).map(|pair| {
                let pair = [pair[0], pair[1]];
                if big_endian { u16::from_be_bytes(pair) } else { u16::from_le_bytes(pair) }
            });
            let low_surrogate = |unit: &u16| (0xDC00..0xE000).contains(unit);
            let units = units.skip_while(|unit| cut && low_surrogate(unit));
            char::decode_utf16(units).map(|c| c.unwrap_or(char::REPLACEMENT_CHARACTER)).collect()
        }
    }
}

/// Characters escaped for a terminal, all in one text: where each one's escape ends there
/// and how many columns a terminal draws it in (a report escapes a few hundred of them,
/// once each).
struct Escaped {
    text: String,
    ends: Vec<usize>,
    widths: Vec<usize>,
}

impl Escaped {
    fn of(chars: &[char]) -> Escaped {
        let mut escaped = Escaped {
            text: String::with_capacity(chars.len()),
            ends: Vec::new(),
            widths: Vec::new(),
        };
        for &c in chars {
            let start = escaped.text.len();
            terminal_char(c, &mut escaped.text);
            // As a terminal draws it: an East Asian wide character takes two columns, a
            // combining mark none, an escape (ASCII) one a character; a tab counts one, as
            // the caret line keeps it.
            let width = match &escaped.text[start..] {
                "\t" => 1,
                shown => shown.width(),
            };
            escaped.ends.push(escaped.text.len());
            escaped.widths.push(width);
        }
        escaped
    }

    /// Where the escape of character `i` starts in the text (the text's end past the last).
    fn start(&self, i: usize) -> usize {
        if i == 0 { 0 } else { self.ends[i - 1] }
    }
}

/// The shown part of a line, of which `before` are the characters before the column (all
/// of them from the line's start, when `whole_start` says so) and `after` those from it on,
/// escaped, and its caret line. SHOWN columns at most are shown (an escaped character
/// takes the columns of its escape), half of them before the column unless the line ends
/// sooner.
fn shown(before: &[char], whole_start: bool, after: &[char]) -> (String, String) {
    let (before, after) = (Escaped::of(before), Escaped::of(after));
    let after_width: usize = after.widths.iter().sum();
    let mut room = (SHOWN / 2).max(SHOWN.saturating_sub(after_width));
    let mut first = before.widths.len();
    while first > 0 && before.widths[first - 1] <= room {
        first -= 1;
        room -= before.widths[first];
    }
    let mut room = SHOWN - before.widths[first..].iter().sum::<usize>();
    let mut end = 0;
    while end < after.widths.len() && after.widths[end] <= room {
        room -= after.widths[end];
        end += 1;
    }
    let (mut line, mut caret) = match first > 0 || !whole_start {
        true => ("...".to_owned(), "   ".to_owned()),
        false => (String::new(), String::new()),
    };
    line.push_str(&before.text[before.start(first)..]);
    for i in first..before.widths.len() {
        match &before.text[before.start(i)..before.ends[i]] {
            "\t" => caret.push('\t'),
            _ => caret.extend(std::iter::repeat_n(' ', before.widths[i])),
        }
    }
    line.push_str(&after.text[..after.start(end)]);
    if end < after.widths.len() {
        line.push_str("...");
    }
    caret.push('^');
    (line, caret)
}

#[cfg(test)]
mod tests {
    use super::{SHOWN, shown};

    /// A line of escaped characters fits the columns shown as a plain one does, half before
    /// the column, and the caret stands under the character at the column.
    #[test]
    fn an_escaped_line_fits_the_columns_shown() {
        let before: Vec<char> = "\u{1b}".repeat(200).chars().collect();
        let after: Vec<char> = "b\u{1b}".repeat(100).chars().collect();
        let (line, caret) = shown(&before, true, &after);
        let core = line.strip_prefix("...").unwrap().strip_suffix("...").unwrap();
        assert!(core.chars().count() <= SHOWN, "{line}");
        assert!(core.starts_with("\\u{1b}") && core.contains("\\u{1b}b\\u{1b}"), "{line}");
        let at = caret.len() - 1;
        assert_eq!(&line[at..at + 1], "b", "{line}\n{caret}");
        assert!((SHOWN / 2..SHOWN / 2 + 6).contains(&at), "{caret:?}");

        let (line, caret) = shown(&['\t', 'a'], true, &['b', '\n']);
        assert_eq!((line.as_str(), caret.as_str()), ("\tab\\u{a}", "\t ^"));
    }
}
