//! The lexer's own state: where the reading of markup into nodes stands in the text, the
//! elements open there, and the scan of the markup it does not read itself. The tokenizer reads the
//! nodes through it over the window, keeping at hand what [`Keeping`](super::Keeping) says.

use super::super::name::Name;
use crate::scan::Index;

pub(super) struct Lexer {
    /// The offset the next node starts at.
    pub pos: usize,
    /// Where the node being read and the one before it began: the text from the one
    /// before on stays at hand, so a value can be read after the end tag that ends it.
    pub started: usize,
    pub last: usize,
    /// The open elements, outermost first, with the offsets of their start tags: the text
    /// of the third (an item of a world container, an object) stays at hand while it is
    /// open, so that its offsets can be placed until it ends.
    pub open: Vec<(Name, usize)>,
    /// The elements read so far, for `max_elements`.
    pub elements: u64,
    /// The scan of the markup the reading does not read itself: asked for the mark of the
    /// markup the reading stands at, it scans from there.
    pub index: Index,
}

impl Lexer {
    /// A lexer at offset `at`, the start of the text, or the start tag of an item in the
    /// open elements `open` (the root and a container) as the reader of a piece begins.
    pub fn at(at: usize, open: Vec<(Name, usize)>) -> Lexer {
        Lexer { pos: at, started: at, last: at, open, elements: 0, index: Index::new(at) }
    }

    /// A node begins at `at`: the one before it stays at hand.
    #[inline(always)]
    pub fn begin_node(&mut self, at: usize) {
        (self.last, self.started) = (self.started, at);
    }

    /// The first offset the reading may still look at: the node before the one being read,
    /// and the object being read while it is open.
    pub fn first_needed(&self) -> usize {
        self.open.get(2).map_or(self.last, |&(_, object)| self.last.min(object))
    }

    /// Whether the reading stands directly in the root or in an element of it, where
    /// nothing read before it is looked at again.
    pub fn outside_items(&self) -> bool {
        self.open.len() <= 2
    }
}
