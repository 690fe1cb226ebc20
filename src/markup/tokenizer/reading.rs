//! What the reader asks of the tokenizer beside its nodes: where the reading stands, the
//! text at hand and kept verbatim taken back, and where an offset is.

use super::Tokenizer;
use crate::error::{Finding, Spot};
use crate::input::Source;

impl<'a> Tokenizer<'a> {
    /// The offset the tokenizer has reached: just past the last node read.
    pub fn position(&self) -> usize {
        self.lex.pos
    }

    /// The text from the last pinned offset to `to` (see [`Keeping::pin`](super::Keeping::pin)),
    /// and lets it go.
    pub fn unpin(&mut self, to: usize) -> String {
        let from = self.kept.unpin().unwrap_or(to);
        self.window.slice(from, to).to_owned()
    }

    /// The elements read so far.
    pub fn elements(&self) -> u64 {
        self.lex.elements
    }

    /// The source it read.
    pub fn into_source(self) -> Source<'a> {
        self.window.into_source()
    }

    /// Whether all the text is at hand, from its start, and stays so.
    pub fn is_whole(&self) -> bool {
        self.window.is_whole()
    }

    /// The text from `from` to `to`, which is at hand.
    pub fn slice(&self, from: usize, to: usize) -> &str {
        self.window.slice(from, to)
    }

    /// `finding` placed at its line and column, when its text will not stay at hand (see
    /// [`Window::place`](super::window::Window::place)).
    pub fn place(&mut self, finding: Finding) -> Finding {
        self.window.place(finding)
    }

    /// Where offset `at` is, for what is checked once the whole file is read.
    pub fn spot(&mut self, at: usize) -> Spot {
        self.window.spot(at)
    }
}
