//! Where a text that is a piece of the file starts and ends, for the reader of a piece:
//! where it starts reading, and where its reading ends before an item.

use super::super::name::Name;
use super::{Lexer, Tokenizer};
use crate::error::{Position, Spot};
use crate::place::Cursor;

impl<'a> Tokenizer<'a> {
    /// Starts reading at `at`, the start tag of an item in the open elements `open` (the
    /// root and a container), as a reader of one piece of the text does. Positions are
    /// counted on from `position`, where `at` is, when it is known; else from `at` (see
    /// [`Cursor::start`]).
    pub fn start_item(&mut self, at: usize, open: Vec<(Name, usize)>, position: Option<Position>) {
        self.lex = Lexer { elements: self.lex.elements, ..Lexer::at(at, open) };
        self.window.resume(position.map_or(Cursor::start(at), |position| Cursor::at(at, position)));
    }

    /// Whether the reading stands where a piece of the text ends before an item (see
    /// [`Source::ends_early`](crate::input::Source::ends_early)): at the end of its text, directly in an element of the root,
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
}
