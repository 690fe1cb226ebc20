//! Where a byte is: the one owner of turning an offset of the decoded text into the line,
//! column and byte offset of the file that a [`Position`] reports. The reader counts lines
//! as it goes ([`Lines`], from a [`Cursor`]); what a later stage may report is kept as a
//! [`Spot`] (in [`Spots`], as small steps); what a text kept whole in memory left
//! unplaced is placed once the read is done ([`Placer`]). Nothing else counts lines.
#![forbid(unsafe_code)]

mod lines;
mod placer;
mod spots;

pub(crate) use lines::{Cursor, Lines};
pub(crate) use placer::Placer;
pub(crate) use spots::{Spot, Spots};

use crate::error::Position;

impl Position {
    /// This position, counted from the start of a piece of the text as line 1, column 1,
    /// placed in the whole text where the piece begins at `start`. Its byte offset is the
    /// file's already.
    pub(crate) fn after(self, start: Position) -> Position {
        let column = match self.line {
            1 => start.column.saturating_add(self.column - 1),
            _ => self.column,
        };
        Position { line: start.line.saturating_add(self.line - 1), column, ..self }
    }
}
