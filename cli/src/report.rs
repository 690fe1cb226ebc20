//! How a warning or an error is shown: as compilers show one, with the line it points at
//! and a caret under the column, or as one JSON object a line for editors and pipelines.
//! Positions are the library's; the line they name is read back by [`Quoted`]. Every text
//! that may come from a file (the file's name, the message, the line) is escaped for the
//! output it goes to, so that no file can forge a report or drive a terminal.
//!
//! The text form is drawn here rather than by annotate-snippets (rustc's renderer, 0.12):
//! that crate takes the position it prints from the source it is handed, and a report
//! hands it only the window of the line that [`Quoted`] reads back, so on a long line it
//! would print the window's column (handing it the line from its start is what made a
//! one-line file's report quadratic); it writes a path's ESC and a message's C1 controls
//! raw, so the escaping here would stay; and its two-line `warning[code]: message` /
//! `--> file:line:column` header is not the one-line `file:line:column: warning[code]:`
//! that GCC-style matchers and grep read. What it would draw, the caret line, is a few
//! lines of [`Quoted::excerpt`].

use std::fmt::Write;
use std::io;

use anstyle::{AnsiColor, Style};
use box2scene::escape::{terminal_char, terminal_text};
use box2scene::{Error, Position, Severity};
use serde::Serialize;
use serde_json::ser::{CompactFormatter, Formatter, Serializer};

use super::quote::Quoted;

const BOLD: Style = Style::new().bold();

/// One warning or error, with the names of its severity and code.
pub struct Report {
    severity: String,
    code: String,
    message: String,
    position: Position,
}

impl Report {
    /// A finding of `severity`: its code, position and message.
    pub fn of(severity: Severity, found: &Error) -> Report {
        Report {
            severity: severity.name().to_owned(),
            code: found.code.name().to_owned(),
            message: found.message.clone(),
            position: found.position,
        }
    }

    /// The note that a check stopped at `position`, after a hundred errors, as JSON gives it
    /// beside the findings (severity `note`, code `check-stopped`).
    pub fn stopped(position: Position, message: &str) -> Report {
        Report {
            severity: "note".to_owned(),
            code: "check-stopped".to_owned(),
            message: message.to_owned(),
            position,
        }
    }

    pub fn of_error(error: &Error) -> Report {
        Report::of(Severity::Error, error)
    }

    /// Whether it is an error rather than a warning.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error.name()
    }

    /// `FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE`, leaving out the parts of the position
    /// that are unknown (0) as compilers do; then, when the line is known, the line and a
    /// caret line. With `colour`, for a terminal, styled as rustc styles its reports: the
    /// place bold, the severity, its code and the caret in the severity's colour, the
    /// message bold; the text is the same.
    pub fn text(&self, file: &str, quoted: &Quoted, colour: bool) -> String {
        let mut text = String::with_capacity(self.message.len() + file.len() + 300);
        // `write` onto the text, styled when the text is for a terminal.
        let paint = |text: &mut String, style: Style, write: &dyn Fn(&mut String)| {
            if colour {
                let _ = write!(text, "{style}");
            }
            write(text);
            if colour {
                let _ = write!(text, "{style:#}");
            }
        };
        let marked = self.marked();
        paint(&mut text, BOLD, &|text| {
            text.push_str(&terminal_text(file));
            match (self.position.line, self.position.column) {
                (0, _) => {}
                (line, 0) => {
                    let _ = write!(text, ":{line}");
                }
                (line, column) => {
                    let _ = write!(text, ":{line}:{column}");
                }
            }
        });
        text.push_str(": ");
        paint(&mut text, marked, &|text| {
            text.push_str(&terminal_text(&self.severity));
            text.push('[');
            text.push_str(&terminal_text(&self.code));
            text.push(']');
        });
        text.push_str(": ");
        paint(&mut text, BOLD, &|text| text.push_str(&terminal_text(&self.message)));
        text.push('\n');
        if let Some((line, caret)) = quoted.excerpt(self.position) {
            let under = caret.strip_suffix('^').unwrap_or(&caret);
            text.push_str(&line);
            text.push('\n');
            text.push_str(under);
            paint(&mut text, marked, &|text| text.push('^'));
            text.push('\n');
        }
        text
    }

    /// The style of the severity and the caret: red for an error, yellow for a warning.
    fn marked(&self) -> Style {
        let colour = match self.severity.as_str() {
            name if name == Severity::Error.name() => Some(AnsiColor::BrightRed.into()),
            name if name == Severity::Warning.name() => Some(AnsiColor::BrightYellow.into()),
            _ => None,
        };
        BOLD.fg_color(colour)
    }

    /// The report as one line of JSON; line and column are 0 when unknown, as in the
    /// library's diagnostics.
    pub fn json(&self, file: &str) -> String {
        let Position { line, column, byte_offset } = self.position;
        let fields = Json {
            file,
            line,
            column,
            byte_offset,
            severity: &self.severity,
            code: &self.code,
            message: &self.message,
        };
        let mut json = Vec::new();
        let written = fields.serialize(&mut Serializer::with_formatter(&mut json, TerminalSafe));
        written.expect("a report of strings and numbers serializes");
        json.push(b'\n');
        String::from_utf8(json).expect("serde_json writes UTF-8")
    }
}

/// A report's fields, in the order JSON lines give them.
#[derive(Serialize)]
struct Json<'a> {
    file: &'a str,
    line: u32,
    column: u32,
    byte_offset: u64,
    severity: &'a str,
    code: &'a str,
    message: &'a str,
}

/// serde_json's compact form, where a string also escapes, as `\uXXXX`, every character
/// that a terminal must not get raw and JSON allows raw (DEL, the C1 controls, the line
/// and paragraph separators, the direction marks and overrides), so that a record stays
/// one line on any terminal or log and shows them visibly.
struct TerminalSafe;

impl Formatter for TerminalSafe {
    fn write_string_fragment<W: ?Sized + io::Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        let mut shown = String::new();
        let mut raw_from = 0;
        for (at, c) in fragment.char_indices() {
            shown.clear();
            terminal_char(c, &mut shown);
            if shown.len() == c.len_utf8() {
                continue;
            }
            CompactFormatter.write_string_fragment(writer, &fragment[raw_from..at])?;
            for unit in c.encode_utf16(&mut [0; 2]) {
                write!(writer, "\\u{unit:04x}")?;
            }
            raw_from = at + c.len_utf8();
        }
        CompactFormatter.write_string_fragment(writer, &fragment[raw_from..])
    }
}

#[cfg(test)]
mod tests {
    use super::{Position, Quoted, Report};

    /// On a terminal a report is styled, and is the plain report once the styles are taken
    /// out: the same text, escaped the same way.
    #[test]
    fn a_coloured_report_is_the_plain_one_styled() {
        let report = Report {
            severity: "warning".to_owned(),
            code: "unknown-element".to_owned(),
            message: "unknown element <Foo\u{1b}[2J>".to_owned(),
            position: Position { line: 19, column: 32, byte_offset: 500 },
        };
        let plain = report.text("level.xml", &Quoted::nothing(), false);
        let coloured = report.text("level.xml", &Quoted::nothing(), true);
        assert!(coloured.contains("\u{1b}[1m\u{1b}[93mwarning[unknown-element]"), "{coloured:?}");
        let mut stripped = String::new();
        let mut rest = coloured.as_str();
        while let Some(at) = rest.find('\u{1b}') {
            stripped.push_str(&rest[..at]);
            let end = rest[at..].find('m').expect("an SGR sequence ends with m");
            rest = &rest[at + end + 1..];
        }
        stripped.push_str(rest);
        assert_eq!(stripped, plain);
        assert!(plain.starts_with("level.xml:19:32: warning[unknown-element]: "), "{plain}");
    }
}
