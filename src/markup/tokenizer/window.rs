//! The window: the text at hand, which refills as the reading needs more and keeps what the
//! reading may still look at, and the lines and columns counted over the text it lets go.

use crate::error::{Finding, Parsed, Spot};
use crate::input::{Encoding, Source};
use crate::place::{Cursor, Lines};

/// The text at hand of a source, and where its offsets are.
pub(super) struct Window<'a> {
    source: Source<'a>,
    /// Lines and columns, counted over the text as it is let go.
    lines: Lines,
}

impl<'a> Window<'a> {
    pub fn new(source: Source<'a>) -> Window<'a> {
        let lines = Lines::new(source.encoding(), Cursor::start(source.base()));
        Window { source, lines }
    }

    /// The text at hand from offset `from` on (empty when `from` is past it).
    #[inline(always)]
    pub fn rest(&self, from: usize) -> &[u8] {
        self.text().get(from - self.source.base()..).unwrap_or_default()
    }

    /// The text at hand, which starts at offset [`Window::base`].
    #[inline(always)]
    pub fn text(&self) -> &[u8] {
        self.source.text().as_bytes()
    }

    #[inline(always)]
    pub fn base(&self) -> usize {
        self.source.base()
    }

    /// The offset just past the text at hand.
    pub fn end(&self) -> usize {
        self.source.end()
    }

    /// The text from `from` to `to`, which is at hand: the reading keeps what it looks at
    /// again (see [`Lexer::first_needed`](super::Lexer::first_needed) and
    /// [`Keeping`](super::Keeping)).
    #[inline]
    pub fn slice(&self, from: usize, to: usize) -> &str {
        debug_assert!(
            self.base() <= from && from <= to && to <= self.end(),
            "{from}..{to} is not at hand ({}..{})",
            self.base(),
            self.end()
        );
        self.source.slice(from, to)
    }

    /// Reads more text, letting go of what lies before `keep`: Ok(false) at the end of the
    /// text; the problem that ends the text early, when that is why.
    pub fn refill(&mut self, keep: usize) -> Parsed<bool> {
        // A text in memory stays at hand: nothing is let go, so nothing is counted yet.
        if !self.source.is_whole() {
            self.lines.release(self.source.text(), self.source.base(), keep);
        }
        if self.source.more(keep) {
            return Ok(true);
        }
        match self.source.stop() {
            Some(stop) => Err(Box::new(stop.clone())),
            None => Ok(false),
        }
    }

    /// Counts positions on from `cursor`: what lies before it was counted elsewhere.
    pub fn resume(&mut self, cursor: Cursor) {
        self.lines.resume(cursor);
    }

    pub fn encoding(&self) -> Encoding {
        self.source.encoding()
    }

    /// Whether all the text is at hand, from its start, and stays so.
    pub fn is_whole(&self) -> bool {
        self.source.is_whole()
    }

    /// Whether the text ends before the file does, where a piece of it ends.
    pub fn ends_early(&self) -> bool {
        self.source.ends_early()
    }

    /// Where offset `at` is, which is at hand (after the text last let go of): the one route
    /// from an offset of the text read to a line and column. Placed now, when its text will
    /// not stay at hand; a text that stays in memory places what it found once it is read
    /// (see [`crate::place::Placer`]), and only if a finding needs it.
    pub fn spot(&mut self, at: usize) -> Spot {
        match self.is_whole() {
            true => Spot::offset(at),
            false => Spot::placed(self.lines.locate(self.source.text(), self.source.base(), at)),
        }
    }

    /// `finding` where [`Window::spot`] puts it.
    pub fn place(&mut self, mut finding: Finding) -> Finding {
        if let Spot::Offset(at) = finding.at {
            finding.at = self.spot(at);
        }
        finding
    }

    /// The source it holds.
    pub fn into_source(self) -> Source<'a> {
        self.source
    }
}
