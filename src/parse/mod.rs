//! The reader: the tokenizer's elements, values and attributes made into the arena's
//! records by one handler per object kind (`world`, `shape`, `fixture`, `body`, `joint`,
//! `user_data`), which are functions of the two. The reader also gives the writer what the
//! records do not hold (comments, ignored elements), and places findings at their lines
//! and columns before their text goes.
#![forbid(unsafe_code)]

mod body;
mod fixture;
mod joint;
mod names;
mod shape;
mod split;
mod user_data;
mod world;

use names::{Element, elements};

use crate::arena::Arena;
use crate::error::{Code, Finding, Parsed, Problem, Spot};
use crate::input::Source;
use crate::markup::{Attr, Node, Tag, Text, Tokenizer, shorten};
use crate::options::LoadOptions;
use crate::place::Placer;
use crate::rules;
use crate::scene::{Kept, KeptAt, KeptText, Object, PoolStr, Span};
use crate::text::{self, trim_xml};

/// Reads the whole document into an arena, in pieces on two threads when [`split`] finds
/// the text worth it. What it finds is placed at its line and column as it reads, or by the
/// [`Placer`] it gives back when the text stays in memory. A read that goes on past errors
/// (`recovering`, on one thread) keeps those it went on past (see [`Read`]).
pub(crate) fn read<'a>(source: Source<'a>, options: &'a LoadOptions, recovering: bool) -> Read<'a> {
    debug_assert!(!recovering || options.threads == 1, "a read that goes on is one thread's");
    match split::shared(&source, options) {
        Some(text) => split::read(source, text, options, None),
        None => read_whole(source, options, recovering),
    }
}

/// What [`read`] gives: the arena (holding the errors the read went on past) or what a read
/// that stopped had found, and what places the findings left for later.
pub(crate) type Read<'a> = (Result<Arena, Stopped>, Placer<'a>);

/// What a read that stopped at an error had found.
pub(crate) struct Stopped {
    /// The errors it went on past, then the one that stopped it.
    pub errors: Vec<Finding>,
    pub warnings: Vec<Finding>,
}

/// [`read`] of the whole text by one reader, on the calling thread.
fn read_whole<'a>(source: Source<'a>, options: &'a LoadOptions, recovering: bool) -> Read<'a> {
    let mut reader = Reader::new(Tokenizer::new(source, options), recovering);
    let read = reader.whole();
    let Reader { mut tok, mut arena, .. } = reader;
    let read = match read {
        Ok(()) => {
            arena.scene.pool_kept_text(|from, to| tok.slice(from, to));
            Ok(arena)
        }
        Err(problem) => {
            let mut errors = arena.findings.take_errors();
            errors.push(tok.place(*problem));
            Err(Stopped { errors, warnings: arena.findings.take_warnings() })
        }
    };
    (read, Placer::new(tok.into_source()))
}

/// Which of an object's known elements were already read (for `duplicate-element`).
#[derive(Default)]
pub(crate) struct Seen {
    bits: u64,
}

impl Seen {
    /// Whether the element was read.
    pub fn contains(&self, element: impl Element) -> bool {
        self.bits & (1 << element.index()) != 0
    }
}

/// The reader: the tokenizer's markup made into the arena's records by one handler per
/// object kind, with what the writer is given beyond the records.
struct Reader<'a> {
    pub tok: Tokenizer<'a>,
    /// What is built from what is read.
    pub arena: Arena,
    /// The object being read, the child element of it being read ("" for none): where the
    /// comments and ignored elements read go.
    object: Object,
    within: &'static str,
    /// Whether the text the records do not hold is kept for the writer: a check, which
    /// writes nothing, keeps none.
    for_writer: bool,
}

impl<'a> Reader<'a> {
    fn new(tok: Tokenizer<'a>, recovering: bool) -> Reader<'a> {
        let arena = Arena::new(tok.options().strict, recovering);
        Reader { for_writer: !recovering, ..Reader::with_arena(tok, arena) }
    }

    /// A reader that goes on filling `arena`, which a read that stops at its first error
    /// began.
    fn with_arena(tok: Tokenizer<'a>, arena: Arena) -> Reader<'a> {
        Reader { tok, arena, object: Object::World, within: "", for_writer: true }
    }

    /// The whole document.
    fn whole(&mut self) -> Parsed<()> {
        let mut seen = Seen::default();
        self.document(&mut seen)?;
        world::end_world(&mut self.arena, &seen)?;
        self.epilog()
    }

    /// An error the reading can go on past (see [`crate::arena::Findings::recover`]), placed
    /// at its line and column while its text is at hand.
    pub fn recover(&mut self, error: Finding) -> Parsed<()> {
        let error = self.tok.place(error);
        self.arena.findings.recover(Box::new(error))
    }

    /// What `checked` gives, or `otherwise` after its error when the reading goes on past
    /// it (see [`Reader::recover`]): for a check of a value already read.
    pub fn recovered<T>(&mut self, checked: Parsed<T>, otherwise: T) -> Parsed<T> {
        match checked {
            Ok(value) => Ok(value),
            Err(error) => self.recover(*error).map(|()| otherwise),
        }
    }

    /// Reads value element `tag` with `convert`. A value that does not convert is an error
    /// the reading goes on past (see [`Reader::recover`]), as if it were `T`'s default
    /// written where the error points: a check of it made later (an ID's) points there
    /// too, and is the same error.
    pub fn value<T: Default>(
        &mut self,
        tag: &Tag,
        convert: impl FnOnce(&str) -> Result<T, Finding>,
    ) -> Parsed<(T, usize)> {
        match self.tok.parsed(tag, convert)? {
            Ok(value) => Ok(value),
            Err(error) => {
                // Not placed yet: where in the text it points (the element's start, were it).
                let at = error.at.unplaced().unwrap_or(tag.at);
                self.recover(*error).map(|()| (T::default(), at))
            }
        }
    }

    pub fn float(&mut self, tag: &Tag) -> Parsed<f32> {
        Ok(self.value(tag, text::float)?.0)
    }

    pub fn vector(&mut self, tag: &Tag) -> Parsed<crate::scene::Vec2> {
        Ok(self.value(tag, text::vector2)?.0)
    }

    pub fn boolean(&mut self, tag: &Tag) -> Parsed<bool> {
        Ok(self.value(tag, text::boolean)?.0)
    }

    /// An ID value and its offset.
    pub fn id(&mut self, tag: &Tag) -> Parsed<(u32, usize)> {
        self.value(tag, text::id)
    }

    /// Records a warning at `at`, placed at its line and column while its text is at hand;
    /// its message, the words `words` give, is made only if the warning is kept (see
    /// [`Findings::note_worded`](crate::arena::Findings::note_worded)).
    pub fn warn<W: Into<String>>(
        &mut self,
        code: Code,
        at: usize,
        words: impl FnOnce() -> W,
    ) -> Parsed<()> {
        let warning = self.tok.place(Finding::new(code, at, String::new()));
        self.arena.findings.note_worded(warning, || words().into())
    }

    /// Records `warning`, placed at its line and column while its text is at hand (see
    /// [`Tokenizer::place`]).
    pub fn note(&mut self, warning: Finding) -> Parsed<()> {
        let warning = self.tok.place(warning);
        self.arena.findings.note(warning)
    }

    /// Warns that `what` needs Version 2 when the file says less (`what` is put in words
    /// only then).
    pub fn newer_construct(&mut self, at: usize, what: impl std::fmt::Display) -> Parsed<()> {
        if self.arena.version >= 2 {
            return Ok(());
        }
        let version = self.arena.version;
        self.warn(Code::ConstructNewerThanVersion, at, || {
            let said = match version {
                0 => "has no Version (legacy)".to_string(),
                v => format!("says Version {v}"),
            };
            format!("{what} is a Version 2 construct, but the file {said}")
        })
    }

    /// Where offset `at` is, for what is checked once the whole file is read.
    pub fn spot(&mut self, at: usize) -> Spot {
        self.tok.spot(at)
    }

    /// A float that must not be negative (error `negative-value`).
    /// An angle in radians, warned about where it reads as degrees
    /// ([`rules::angle_in_degrees`]).
    pub fn radians(&mut self, tag: &Tag) -> Parsed<f32> {
        let (v, at) = self.value(tag, text::float)?;
        if let Some(warning) = rules::angle_in_degrees(&tag.name, v, at) {
            self.note(warning)?;
        }
        Ok(v)
    }

    pub fn non_negative(&mut self, tag: &Tag) -> Parsed<f32> {
        let (v, at) = self.value(tag, text::float)?;
        let checked = rules::not_negative(format_args!("<{}>", tag.name), v, at);
        self.recovered(checked, 0.0)
    }

    /// A string value, stored in the scene's string pool.
    pub fn string(&mut self, tag: &Tag) -> Parsed<PoolStr> {
        let value = self.tok.value(tag)?;
        Ok(self.arena.scene.add_str(self.tok.text_of(&value.text)))
    }

    /// Warns about every attribute of `tag` except those named in `known` (in any case), with
    /// the nearest known name as a hint, and keeps them for the start tag of the object
    /// being read. Called by the `attributes!` macro when there are some: their names and
    /// text are copied, as the warnings take the reader.
    #[cold]
    pub fn unknown_attributes(&mut self, tag: &Tag, known: &[&str]) -> Parsed<()> {
        let keeping = self.keeping();
        let unknown: Vec<_> = (self.tok.attributes(tag)?.iter())
            .filter(|attr| !is_known(attr, known))
            .map(|attr| {
                (attr.key.to_owned(), attr.at, keeping.then(|| self.tok.verbatim(tag, attr)))
            })
            .collect();
        for (key, at, written) in unknown {
            self.warn(Code::UnknownElement, at, || {
                let hint = did_you_mean(&key, known);
                format!("unknown attribute {key} on <{}> ignored{hint}", tag.name())
            })?;
            if let Some(written) = written {
                self.keep_str(KeptAt::Attribute, &written);
            }
        }
        Ok(())
    }

    /// Warns that `child` is not part of `parent`, with the nearest of `parent`'s `known`
    /// elements as a hint, and skips it (see [`Reader::ignore`]).
    pub fn unknown(&mut self, parent: &Tag, child: &Tag, known: &[&str]) -> Parsed<()> {
        self.ignore(child, || {
            let hint = match names::nearest(child.name(), known) {
                Some(near) => format!(" (did you mean <{near}>?)"),
                None => String::new(),
            };
            format!("unknown element <{}> in <{}> ignored{hint}", child.name(), parent.name())
        })
    }

    /// Warns (`unknown-element`, in the words `words` give) and skips `child`, keeping its
    /// text for the writer at the end of where it was.
    pub fn ignore(&mut self, child: &Tag, words: impl FnOnce() -> String) -> Parsed<()> {
        self.discard(child, words)?;
        let place = KeptAt::Inside { within: self.within, before: "" };
        self.keep(self.object, place, child.at, self.tok.position());
        Ok(())
    }

    /// Warns (`unknown-element`, in the words `words` give) and skips `child`, comments
    /// inside it included, keeping nothing: for what the writer writes in another form.
    pub fn discard(&mut self, child: &Tag, words: impl FnOnce() -> String) -> Parsed<()> {
        self.warn(Code::UnknownElement, child.at, words)?;
        self.tok.check_attributes(child)?;
        self.tok.kept.pin(child.at);
        self.tok.skip(child)?;
        self.tok.kept.unpin();
        Ok(())
    }

    /// Whether text read now is kept for the writer: not by a check, nor inside text kept
    /// whole.
    fn keeping(&self) -> bool {
        self.for_writer && !self.tok.kept.pinned()
    }

    /// The text from `from` to `to`, for the writer: a span when the text stays at hand,
    /// else a copy.
    fn kept_text(&mut self, from: usize, to: usize) -> KeptText {
        match self.tok.is_whole() {
            true => KeptText::File(Span { from, to }),
            false => self.arena.scene.keep_str(self.tok.slice(from, to)),
        }
    }

    /// Keeps the file's text from `from` to `to` for the writer at `place` in `object`
    /// (unless it is not [`Reader::keeping`]): with the piece before it when that is at
    /// the same place, was kept from the file, and only white space lies between them,
    /// which the tokenizer holds at hand from where that piece ends (see the markup
    /// tokenizer's `Keeping::hold`), so that a load from a path joins what one from memory
    /// joins.
    fn keep(&mut self, object: Object, place: KeptAt, from: usize, to: usize) {
        if !self.keeping() {
            return;
        }
        if let Some(end) = self.tok.kept.held().filter(|&end| end <= from)
            && trim_xml(self.tok.slice(end, from)).is_empty()
            && let Some(last) =
                self.arena.scene.kept.last().filter(|k| k.object == object && k.place == place)
            && let Some(joined) = self.joined(last.text, end, to)
        {
            self.arena.scene.kept.last_mut().expect("the piece joined").text = joined;
        } else {
            let text = self.kept_text(from, to);
            self.arena.scene.kept.push(Kept { object, place, text });
        }
        self.tok.kept.hold(to);
    }

    /// The kept text `last`, which ends at offset `end` of the file, made to go on to `to`.
    fn joined(&mut self, last: KeptText, end: usize, to: usize) -> Option<KeptText> {
        match last {
            KeptText::File(Span { from, to: last_end }) => {
                (last_end == end).then_some(KeptText::File(Span { from, to }))
            }
            // Copied on into the pool, which the last piece ends.
            KeptText::Pooled(Span { from, to: pooled_to }) => {
                let text = self.tok.slice(end, to);
                match self.arena.scene.keep_str(text) {
                    KeptText::Pooled(Span { from: next, to }) if next == pooled_to => {
                        Some(KeptText::Pooled(Span { from, to }))
                    }
                    _ => unreachable!("the pool's text is appended where it ends"),
                }
            }
        }
    }

    /// Keeps `text` (not from the file's text as it stands) at `place` in the object being
    /// read, unless it is not [`Reader::keeping`].
    fn keep_str(&mut self, place: KeptAt, text: &str) {
        if self.keeping() {
            let text = self.arena.scene.keep_str(text);
            self.arena.scene.kept.push(Kept { object: self.object, place, text });
            self.tok.kept.release();
        }
    }

    /// Gives the comments read since the last element to `object`, at `place`. Inlined: it
    /// runs for nearly every element, and there are comments before few.
    #[inline(always)]
    pub fn place_comments(&mut self, object: Object, place: KeptAt) {
        if self.tok.kept.has_comments() {
            self.keep_comments(object, place);
        }
    }

    /// [`Reader::place_comments`] when there are some.
    #[inline(never)]
    fn keep_comments(&mut self, object: Object, place: KeptAt) {
        let Some(comments) = self.tok.kept.take_comments() else { return };
        for (from, to) in comments {
            self.keep(object, place, from, to);
        }
    }

    /// An item of a world container begins: the comments before it go before it.
    pub fn begin_object(&mut self, object: Object) {
        self.place_comments(object, KeptAt::Before);
        (self.object, self.within) = (object, "");
        // Nothing kept later joins what went before the object.
        self.tok.kept.release();
    }

    /// The item ends: the comments inside it not followed by an element go at its end.
    pub fn end_object(&mut self) {
        self.place_comments(self.object, KeptAt::Inside { within: "", before: "" });
        self.object = Object::World;
        self.tok.kept.release();
    }

    /// Reads a child element of the object's child `within` with `read`: the comments in
    /// it go before the element they precede, or at its end.
    pub fn within<T>(
        &mut self,
        within: &'static str,
        read: impl FnOnce(&mut Self) -> Parsed<T>,
    ) -> Parsed<T> {
        self.within = within;
        let read = read(self);
        self.place_comments(self.object, KeptAt::Inside { within, before: "" });
        self.within = "";
        self.tok.kept.release();
        read
    }

    /// Looks `child` up among an object's known elements `E` (any case). Returns which it
    /// is and whether the object already had it; None (after a warning and a skip) when it
    /// is not one of them.
    pub fn known<E: Element>(
        &mut self,
        parent: &Tag,
        child: &Tag,
        seen: &mut Seen,
    ) -> Parsed<Option<(E, bool)>> {
        let found = E::NAMES.find(child.name.key());
        if self.tok.kept.has_comments() {
            let before = found.map_or("", |index| E::ALL[index].name());
            self.keep_comments(self.object, KeptAt::Inside { within: self.within, before });
        }
        let Some(index) = found else {
            self.unknown(parent, child, E::NAMES.names)?;
            return Ok(None);
        };
        // A known element lies between what was kept and what is kept next.
        self.tok.kept.release();
        let bit = 1u64 << index;
        let repeated = seen.bits & bit != 0;
        seen.bits |= bit;
        Ok(Some((E::ALL[index], repeated)))
    }

    /// Warns that a scalar element was repeated (the last one wins).
    pub fn duplicate(&mut self, parent: &Tag, child: &Tag) -> Parsed<()> {
        self.warn(Code::DuplicateElement, child.at, || {
            format!("<{}> appears twice in <{}>; the last one wins", child.name(), parent.name())
        })
    }

    /// Reads every child of a container, each of which must be an `item` element (any
    /// letter case).
    pub fn items(
        &mut self,
        container: &Tag,
        item: &str,
        mut each: impl FnMut(&mut Self, &Tag) -> Parsed<()>,
    ) -> Parsed<()> {
        let key = crate::markup::key(item);
        let mut child = Tag::slot();
        while self.tok.child(container, &mut child)? {
            if child.name.key() != key {
                return Err(crate::error::problem(
                    Code::UnexpectedElement,
                    child.at,
                    format!(
                        "<{}> holds <{item}> elements, not <{}>",
                        container.name(),
                        child.name()
                    ),
                ));
            }
            each(self, &child)?;
        }
        Ok(())
    }
}

/// The attributes of `$tag` (see [`Tokenizer::attributes`]), read by the reader `$reader`
/// after a warning about each not named in `$known` (see [`Reader::unknown_attributes`]).
/// A macro, not a method: the attributes borrow the text at hand from the tokenizer, and
/// the warnings take the whole reader. When there are some to warn about, which is rare,
/// the attributes are read again after the warnings.
macro_rules! attributes {
    ($reader:expr, $tag:expr, $known:expr) => {{
        let (tag, known): (_, &[&str]) = ($tag, $known);
        let attrs = $reader.tok.attributes(tag)?;
        match attrs.iter().all(|attr| super::is_known(attr, known)) {
            true => attrs,
            false => {
                $reader.unknown_attributes(tag, known)?;
                $reader.tok.attributes(tag)?
            }
        }
    }};
}
use attributes;

/// Whether `attr` is named in `known`, in any case.
fn is_known(attr: &Attr, known: &[&str]) -> bool {
    known.iter().any(|k| attr.is(k))
}

/// " (did you mean NEAR?)" for the one of `known` nearest `name` in spelling
/// ([`names::nearest`]), or nothing when none is near: for an unknown attribute or `Type`.
pub(crate) fn did_you_mean(name: &str, known: &[&str]) -> String {
    match names::nearest(name, known) {
        Some(near) => format!(" (did you mean {near}?)"),
        None => String::new(),
    }
}

/// The bytes of `word` in ASCII lower case, made in `buffer` when it fits (the words it is
/// matched against are shorter), so that matching a Type attribute allocates nothing. Bytes,
/// not text: the words matched are ASCII, and text would be checked again for UTF-8.
pub(crate) fn lowercase<'b>(word: &'b str, buffer: &'b mut [u8; 16]) -> &'b [u8] {
    let Some(bytes) = buffer.get_mut(..word.len()) else {
        return word.as_bytes();
    };
    bytes.copy_from_slice(word.as_bytes());
    bytes.make_ascii_lowercase();
    bytes
}
