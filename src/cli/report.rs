//! How a warning or an error is shown: as compilers show one, with the line it points at
//! and a caret under the column, or as one JSON object a line for editors and pipelines.
//! Positions are the library's; this module only finds the line they name.

use std::borrow::Cow;
use std::cell::OnceCell;
use std::char::REPLACEMENT_CHARACTER;

use box2scene::{Diagnostic, Error, Position, Scene, Severity};

/// Characters of a long line shown around the column: a file written on one line still
/// gives a report that fits a terminal.
const SHOWN: usize = 120;

/// One warning or error, with the names of its severity and code.
pub struct Report {
    severity: String,
    code: String,
    message: String,
    position: Position,
}

impl Report {
    pub fn of_error(error: &Error) -> Report {
        Report {
            severity: Severity::Error.name().to_owned(),
            code: error.code.name().to_owned(),
            message: error.message.clone(),
            position: error.position,
        }
    }

    pub fn of_diagnostic(scene: &Scene, d: &Diagnostic) -> Report {
        // A loaded scene's diagnostics carry known codes and severities; a value without a
        // name is shown as its number rather than guessed.
        Report {
            severity: d.severity().map_or_else(|| d.severity.to_string(), |s| s.name().to_owned()),
            code: d.code().map_or_else(|| d.code.to_string(), |c| c.name().to_owned()),
            message: scene.text(d.message).unwrap_or_default().to_owned(),
            position: d.position(),
        }
    }

    /// `FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE`, leaving out the parts of the position
    /// that are unknown (0) as compilers do; then, when the line is known, the line and a
    /// caret line.
    pub fn text(&self, file: &str, source: &Source<'_>) -> String {
        let place = match (self.position.line, self.position.column) {
            (0, _) => file.to_owned(),
            (line, 0) => format!("{file}:{line}"),
            (line, column) => format!("{file}:{line}:{column}"),
        };
        let mut text = format!("{place}: {}[{}]: {}\n", self.severity, self.code, self.message);
        if let Some((line, caret)) = source.excerpt(self.position) {
            text.push_str(&format!("{line}\n{caret}\n"));
        }
        text
    }

    /// The report as one line of JSON; line and column are 0 when unknown, as in the
    /// library's diagnostics.
    pub fn json(&self, file: &str) -> String {
        let Position { line, column, byte_offset } = self.position;
        format!(
            "{{\"file\":{},\"line\":{line},\"column\":{column},\"byte_offset\":{byte_offset},\
             \"severity\":{},\"code\":{},\"message\":{}}}\n",
            json_string(file),
            json_string(&self.severity),
            json_string(&self.code),
            json_string(&self.message),
        )
    }
}

/// The bytes a scene was loaded from, read back as text only when a report needs a line.
pub struct Source<'b> {
    bytes: &'b [u8],
    /// The decoded text and the offset in it where each line starts.
    lines: OnceCell<(Cow<'b, str>, Vec<usize>)>,
}

impl<'b> Source<'b> {
    pub fn new(bytes: &'b [u8]) -> Source<'b> {
        Source { bytes, lines: OnceCell::new() }
    }

    /// Line `number` (from 1) without its line break. Lines end at each `\n`, where the
    /// loader counts them.
    fn line(&self, number: u32) -> Option<&str> {
        let (text, starts) = self.lines.get_or_init(|| {
            let text = decode(self.bytes);
            let breaks = text.match_indices('\n').map(|(at, _)| at + 1);
            let starts = std::iter::once(0).chain(breaks).collect();
            (text, starts)
        });
        let index = usize::try_from(number.checked_sub(1)?).ok()?;
        let start = *starts.get(index)?;
        let end = starts.get(index + 1).map_or(text.len(), |next| next - 1);
        let line = &text[start..end];
        Some(line.strip_suffix('\r').unwrap_or(line))
    }

    /// The line `at` points into and a caret line under its column; None when the
    /// position is unknown or is not in the text. Tabs are kept in the caret line so that
    /// the caret lines up however wide a terminal draws them; control characters are
    /// shown as U+FFFD so that the line cannot move the cursor.
    fn excerpt(&self, at: Position) -> Option<(String, String)> {
        let before = usize::try_from(at.column.checked_sub(1)?).ok()?;
        let chars: Vec<char> = self.line(at.line)?.chars().map(visible).collect();
        if before > chars.len() {
            return None;
        }
        let first = before.saturating_sub(SHOWN / 2).min(chars.len().saturating_sub(SHOWN));
        let end = chars.len().min(first + SHOWN);
        let (mut line, mut caret) = match first {
            0 => (String::new(), String::new()),
            _ => ("...".to_owned(), "   ".to_owned()),
        };
        line.extend(&chars[first..end]);
        if end < chars.len() {
            line.push_str("...");
        }
        let lead = chars[first..before].iter().map(|&c| if c == '\t' { '\t' } else { ' ' });
        caret.extend(lead);
        caret.push('^');
        Some((line, caret))
    }
}

/// The text as the loader decodes it: UTF-16 after its byte-order mark, else UTF-8
/// without one. Bytes that are not text (the loader stops at the first) become U+FFFD.
fn decode(bytes: &[u8]) -> Cow<'_, str> {
    let utf16 = |rest: &[u8], unit: fn([u8; 2]) -> u16| {
        let units = rest.chunks_exact(2).map(|pair| unit([pair[0], pair[1]]));
        Cow::Owned(char::decode_utf16(units).map(|c| c.unwrap_or(REPLACEMENT_CHARACTER)).collect())
    };
    match bytes {
        [0xFF, 0xFE, rest @ ..] => utf16(rest, u16::from_le_bytes),
        [0xFE, 0xFF, rest @ ..] => utf16(rest, u16::from_be_bytes),
        _ => String::from_utf8_lossy(bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)),
    }
}

fn visible(c: char) -> char {
    if c.is_control() && c != '\t' { REPLACEMENT_CHARACTER } else { c }
}

/// A JSON string literal, control characters escaped so that a report stays on its line.
fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => out.push_str(&format!("\\u{:04x}", u32::from(c))),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}
