//! How a warning or an error is shown: as compilers show one, with the line it points at
//! and a caret under the column, or as one JSON object a line for editors and pipelines.
//! Positions are the library's; the line they name is read back by [`Quoted`]. Every text
//! that may come from a file (the file's name, the message, the line) is escaped for the
//! output it goes to, so that no file can forge a report or drive a terminal.

use std::io;

use box2scene::escape::{terminal_char, terminal_text};
use box2scene::{Diagnostic, Error, Position, Scene, Severity};
use serde::Serialize;
use serde_json::ser::{CompactFormatter, Formatter, Serializer};

use super::quote::Quoted;

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

    /// Whether it is an error rather than a warning.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error.name()
    }

    /// `FILE:LINE:COLUMN: SEVERITY[CODE]: MESSAGE`, leaving out the parts of the position
    /// that are unknown (0) as compilers do; then, when the line is known, the line and a
    /// caret line.
    pub fn text(&self, file: &str, quoted: &Quoted) -> String {
        let file = terminal_text(file);
        let place = match (self.position.line, self.position.column) {
            (0, _) => file.to_owned(),
            (line, 0) => format!("{file}:{line}"),
            (line, column) => format!("{file}:{line}:{column}"),
        };
        let (severity, code) = (terminal_text(&self.severity), terminal_text(&self.code));
        let mut text = format!("{place}: {severity}[{code}]: {}\n", terminal_text(&self.message));
        if let Some((line, caret)) = quoted.excerpt(self.position) {
            text.push_str(&format!("{line}\n{caret}\n"));
        }
        text
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
