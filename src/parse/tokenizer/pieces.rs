//! Where the reader is: positions placed, findings about elements, the text kept verbatim
//! taken back, and where a text that is a piece of the file starts and ends.

use super::super::names::Name;
use super::{Lexer, Tag, Tokenizer};
use crate::error::{Code, Finding, Position, Problem, Spot, problem};
use crate::input::Source;
use crate::place::Cursor;

impl<'a> Tokenizer<'a> {
    /// The error for a repeated container.
    #[cold]
    pub fn duplicate_container<E: From<Problem>>(&self, parent: &Tag, child: &Tag) -> E {
        problem(
            Code::DuplicateContainer,
            child.at,
            format!(
                "<{}> appears twice in <{}>: the indices of its items would be ambiguous",
                child.name(),
                parent.name()
            ),
        )
    }

    #[cold]
    pub fn missing<E: From<Problem>>(&self, tag: &Tag, what: &str) -> E {
        problem(Code::MissingElement, tag.at, format!("<{}> has no {what}", tag.name()))
    }

    #[cold]
    pub fn unclosed<E: From<Problem>>(&self, tag: &Tag) -> E {
        problem(
            Code::MalformedXml,
            self.window.end(),
            format!(
                "malformed XML: the file ends before </{}> (opened at byte {})",
                tag.name(),
                tag.at
            ),
        )
    }

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

    /// Starts reading at `at`, the start tag of an item in the open elements `open` (the
    /// root and a container), as a reader of one piece of the text does. Positions are
    /// counted on from `position`, where `at` is, when it is known; else from `at` (see
    /// [`Cursor::start`]).
    pub fn start_item(&mut self, at: usize, open: Vec<(Name, usize)>, position: Option<Position>) {
        self.lex = Lexer { elements: self.lex.elements, ..Lexer::at(at, open) };
        self.window.resume(position.map_or(Cursor::start(at), |position| Cursor::at(at, position)));
    }

    /// Whether the reading stands where a piece of the text ends before an item (see
    /// [`Source::ends_early`]): at the end of its text, directly in an element of the root,
    /// with nothing read waiting for the reader (text kept verbatim, comments, which would
    /// go with the item). There the reading of the piece ends, as the reading of a whole
    /// file would go on to the item.
    pub fn at_piece_end(&self) -> bool {
        self.window.ends_early()
            && self.lex.pos == self.window.end()
            && self.lex.open.len() == 2
            && self.kept.waits_for_nothing()
    }

    /// The element the reading stands in, directly in the root, at the end of a piece (see
    /// [`Tokenizer::at_piece_end`]).
    pub fn open_container(&self) -> Option<&Name> {
        self.lex.open.get(1).filter(|_| self.at_piece_end()).map(|(name, _)| name)
    }

    /// The position the reading reached, counted from where it started, when it places
    /// what it finds as it reads (a text that does not stay at hand).
    pub fn placed_end(&mut self) -> Option<Position> {
        match self.spot(self.lex.pos) {
            Spot::Placed(position) => Some(position),
            Spot::Offset(_) => None,
        }
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
