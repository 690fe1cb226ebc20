//! Where the reader is: positions placed, findings about elements, the text kept verbatim
//! taken back, and the ends and resumptions of pieces for the second thread.

use super::super::names::Name;
use super::{FoundEnds, Stop, Tag, Tokenizer};
use crate::error::{Code, Finding, Position, Problem, problem};
use crate::input::Source;
use crate::place::{Cursor, Spot};
use crate::scan::Index;

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
            self.source.end(),
            format!(
                "malformed XML: the file ends before </{}> (opened at byte {})",
                tag.name(),
                tag.at
            ),
        )
    }

    /// The offset the tokenizer has reached: just past the last node read.
    pub fn position(&self) -> usize {
        self.pos
    }

    /// The text from the last pinned offset to `to` (see [`Keeping::pin`](super::Keeping::pin)),
    /// and lets it go.
    pub fn unpin(&mut self, to: usize) -> String {
        let from = self.kept.unpin().unwrap_or(to);
        self.source.slice(from, to).to_owned()
    }

    /// Starts reading at `at`, the start tag of an item in the open elements `open` (the
    /// root and a container), as a reader of one piece of the text does. Positions are
    /// counted from there (see [`Cursor::start`]).
    pub fn start_item(&mut self, at: usize, open: Vec<(Name, usize)>) {
        (self.pos, self.started, self.last, self.open) = (at, at, at, open);
        self.index = Index::new(at);
        self.lines.resume(Cursor::start(at));
    }

    /// Where this tokenizer stands, at the end of a piece it read: the position of its offset
    /// counted from the piece's start, when it placed what it found (see [`Stop::end`]).
    pub fn stop(mut self) -> Stop {
        let end = (!self.is_whole()).then(|| self.locate(self.pos));
        let Tokenizer { pos, started, last, open, elements, .. } = self;
        Stop { pos, started, last, open, elements, end }
    }

    /// Goes on where `stop` left off, the end of a piece read by another tokenizer whose
    /// start is at `start` here, with `elements` read in all; false when a file cannot be
    /// read on from there.
    pub fn resume(&mut self, stop: Stop, start: Position, elements: u64) -> bool {
        if !self.source.skip_to(stop.pos) {
            return false;
        }
        let Stop { pos, started, last, open, end, .. } = stop;
        (self.pos, self.started, self.last, self.open) = (pos, started, last, open);
        self.index = Index::new(pos);
        self.elements = elements;
        // The other reading went past every end.
        self.next_end = self.ends.len();
        self.aim();
        // Positions are counted on from there; a text in memory counts its own.
        if let Some(end) = end {
            self.lines.resume(Cursor::at(pos, end.after(start)));
        }
        true
    }

    /// Ends the reading before the items at `ends` (offsets in order, each with the name
    /// of the container it is assumed to be in) where it can: the text at hand ends at each
    /// in turn, and where the reading reaches it directly in that container in the root,
    /// with nothing read waiting, it stops there with [`Halt::PieceEnd`](super::Halt::PieceEnd)
    /// before the item. Where it cannot, and at the ends it is already past, the reading
    /// goes on.
    pub fn end_before(&mut self, ends: Vec<(usize, Name)>) {
        let pos = self.pos;
        let passed = ends.partition_point(|&(at, _)| at <= pos);
        (self.ends, self.next_end) = (ends, passed);
        self.aim();
    }

    /// [`Tokenizer::end_before`] with ends that are still being found: `found` gives them
    /// once they are, and is asked each time more text is read until then.
    pub fn end_before_found(&mut self, found: FoundEnds<'a>) {
        self.found = Some(found);
        self.take_found_ends();
    }

    /// The ends of [`Tokenizer::end_before_found`], once they are found.
    pub(super) fn take_found_ends(&mut self) {
        if let Some(ends) = self.found.as_mut().and_then(|found| found()) {
            self.found = None;
            self.end_before(ends);
        }
    }

    /// The end the reading stopped at, by its index among them; the reading goes on past
    /// it.
    pub fn pass_end(&mut self) -> usize {
        let passed = self.next_end;
        self.next_end += 1;
        self.aim();
        passed
    }

    /// Ends the text at hand at the next end, passing those it reaches past already.
    fn aim(&mut self) {
        loop {
            self.end_at = self.ends.get(self.next_end).map_or(usize::MAX, |&(at, _)| at);
            self.source.end_at(self.end_at);
            if self.source.end() <= self.end_at {
                return;
            }
            self.next_end += 1;
        }
    }

    /// The start tags of the root and of the container open in it, when those two are
    /// open (as where the reading stopped before an item), as a reading that goes on from
    /// there assumes them.
    pub fn open_item(&self) -> Option<(Tag, Tag)> {
        let [(root, root_at), (container, at)] = &self.open[..] else { return None };
        Some((Tag::item(root.clone(), *root_at), Tag::item(container.clone(), *at)))
    }

    /// The elements read so far.
    pub fn elements(&self) -> u64 {
        self.elements
    }

    /// The source it read, all of it at hand again.
    pub fn into_source(mut self) -> Source<'a> {
        self.source.end_at(usize::MAX);
        self.source
    }

    /// Whether all the text is at hand, from its start, and stays so.
    pub fn is_whole(&self) -> bool {
        self.source.is_whole()
    }

    /// The text from `from` to `to`, which is at hand.
    pub fn slice(&self, from: usize, to: usize) -> &str {
        self.source.slice(from, to)
    }

    /// The line, column and byte offset of offset `at`, which is at hand: after the text
    /// last let go of, or in the object being read (see [`Tokenizer::open`]).
    pub fn locate(&mut self, at: usize) -> Position {
        self.lines.locate(self.source.text(), self.source.base(), at)
    }

    /// `finding` placed at its line and column, when its text will not stay at hand; a
    /// text that stays in memory places its findings once it is read (see
    /// [`super::Placer`]), and only if there are any.
    pub fn place(&mut self, mut finding: Finding) -> Finding {
        if finding.position.is_none() && !self.is_whole() {
            finding.position = Some(self.locate(finding.at));
        }
        finding
    }

    /// Where offset `at` is, for what is checked once the whole file is read (see
    /// [`Tokenizer::place`]).
    pub fn spot(&mut self, at: usize) -> Spot {
        match self.is_whole() {
            true => Spot::offset(at),
            false => Spot::placed(self.locate(at)),
        }
    }
}
