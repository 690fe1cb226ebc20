//! Where a byte is: the one owner of turning an offset of the decoded text into the line,
//! column and byte offset of the file that a [`Position`] reports. The reader counts lines
//! as it goes ([`Lines`], from a [`Cursor`]): every offset a load reports is made a
//! [`Spot`](crate::error::Spot) there, placed while its text is at hand, or once the read
//! is done ([`Placer`]) when the whole text stays in memory; what a later stage may report
//! is kept small in [`Spots`]. Nothing else counts lines.
#![forbid(unsafe_code)]

mod lines;
mod placer;
mod spots;

pub(crate) use lines::{Cursor, Lines};
pub(crate) use placer::Placer;
pub(crate) use spots::Spots;

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
