//! The tokenizer: a pull reader of markup over the decoded text (whole, or a window moving
//! over a streamed file). It enforces the limits, counts lines as it goes, and hands whole
//! elements, values and attributes to the reader; it builds nothing.
//!
//! The usual markup it reads itself, without the scan stage: tags with short names, tags
//! whose attributes are plain `name="value"` pairs, values up to the `<` of their end tag,
//! and that end tag. For the rest it asks the scan stage ([`Index`](crate::scan::Index))
//! for the mark of the markup it stands at: where another tag, a comment, CDATA or a
//! processing instruction ends, and where text ends, is that mark; it looks for no other
//! delimiter. Anything else goes to quick-xml: its attribute iterator reads and checks the
//! other attributes, its reference and declaration types resolve entities and read the XML
//! declaration, and its errors are the messages.
//! The loop is ours because quick-xml 0.42's `Reader` checks every event's bytes as UTF-8
//! again; the text here was checked once by its source, and slices of it at ASCII markup
//! are text by construction.
#![forbid(unsafe_code)]

use std::borrow::Cow;

use quick_xml::errors::{IllFormedError, SyntaxError};
use quick_xml::events::{BytesDecl, BytesStart};
use quick_xml::parser::{ElementParser, Parser as _};

use super::name::{Name, SHORT};
use crate::error::{Code, Parsed, Problem, problem};
use crate::input::Source;
use crate::options::LoadOptions;
use crate::scan::Mark;
use crate::text::{self};

mod findings;
mod keeping;
mod lexer;
mod pieces;
mod reading;
mod values;
mod window;

use crate::bytes::{ENDS_NAME, is_plain, is_xml_space_byte, short_name_len, space_len};
pub(crate) use keeping::Keeping;
use lexer::Lexer;
use values::{plain_tag_end, resolve_text};
use window::Window;

#[cfg(test)]
mod tests;

#[cold]
fn malformed<E: From<Problem>>(at: usize, e: impl Into<quick_xml::Error>) -> E {
    problem(Code::MalformedXml, at, format!("malformed XML: {}", e.into()))
}

/// A start tag (`<Name ...>` or `<Name .../>`) and where it begins. Its name is copied;
/// its attributes are read where they are written (see [`Tokenizer::attributes`]), while
/// the text at hand holds them: right after the tag, or while the object it opens is open
/// (see [`Lexer::first_needed`]).
pub(crate) struct Tag {
    pub name: Name,
    /// Offset just past what lies between `<` and `>` (or `/>`): its name, then its
    /// attributes when it has more than its name.
    end: usize,
    /// Offset of its `<`.
    pub at: usize,
    /// `<Name/>`: it has no children and no text.
    pub empty: bool,
}

impl Tag {
    /// A start tag with its name alone, open: as a reading that goes on from inside the
    /// element assumes it.
    pub fn item(name: Name, at: usize) -> Tag {
        Tag { end: at + 1 + name.len(), name, at, empty: false }
    }

    /// A tag that names no element, for a reader's loop to read its children into (see
    /// [`Tokenizer::child`]).
    pub fn slot() -> Tag {
        Tag { name: Name::Short(0, [0; SHORT]), end: 1, at: 0, empty: true }
    }

    pub fn name(&self) -> &str {
        self.name.as_str()
    }

    /// Where what lies between `<` and `>` (or `/>`) starts and ends, when the tag has
    /// more than its name.
    fn content(&self) -> Option<(usize, usize)> {
        let from = self.at + 1;
        (self.end > from + self.name.len()).then_some((from, self.end))
    }

    /// Names compare case-insensitively (spec section 2).
    #[inline]
    pub fn is(&self, name: &str) -> bool {
        self.name.key() == super::name::key(name)
    }
}

/// A piece of text: a range of the decoded text, or its resolved form when it held
/// references or carriage returns. Read it with [`Tokenizer::text_of`] before the next node.
pub(crate) struct Text {
    pub at: usize,
    end: usize,
    resolved: Option<Resolved>,
}

impl Text {
    /// Its text, from `window` when it is a range of it.
    fn read<'t>(&'t self, window: &'t Window) -> &'t str {
        match &self.resolved {
            Some(resolved) => &resolved.text,
            None => window.slice(self.at, self.end),
        }
    }

    /// Where the character at `offset` of its text is written in the file's text.
    fn written_at(&self, offset: usize) -> usize {
        match &self.resolved {
            Some(resolved) => resolved.written_at(self.at, offset),
            None => self.at + offset,
        }
    }
}

/// Text that is not as written: its references resolved, its line ends normalised, or
/// pieces written apart (around a comment, as CDATA) joined.
#[derive(Default)]
pub(super) struct Resolved {
    text: String,
    /// Where its pieces are written, for positions in messages: at each offset of `text`
    /// listed, the offset in the file's text it was read from, and from there on one byte
    /// for one up to the next listed (from the text's start, one for one from where it is).
    written: Vec<(usize, usize)>,
}

impl Resolved {
    /// Where the character at `offset` of the text, which starts at `at`, is written.
    fn written_at(&self, at: usize, offset: usize) -> usize {
        let after = self.written.partition_point(|&(piece, _)| piece <= offset);
        let (piece, from) = after.checked_sub(1).map_or((0, at), |last| self.written[last]);
        from + (offset - piece)
    }

    /// Appends `text`, written from `at` on.
    fn push(&mut self, text: &str, at: usize) {
        self.written.push((self.text.len(), at));
        self.text.push_str(text);
    }

    /// Appends `other`, whose text starts at `at`.
    fn append(&mut self, other: &Resolved, at: usize) {
        let base = self.text.len();
        self.push(&other.text, at);
        self.written.extend(other.written.iter().map(|&(piece, from)| (base + piece, from)));
    }

    /// Keeps the text from `start` to `end` only (white space trimmed).
    fn keep(&mut self, start: usize, end: usize) {
        self.text.truncate(end);
        self.text.drain(..start);
        self.written.retain(|&(piece, _)| piece > start);
        for (piece, _) in &mut self.written {
            *piece -= start;
        }
    }
}

/// The trimmed text of a value element and the offset of its first character. Read it
/// with [`Tokenizer::text_of`] before the next node.
pub(crate) struct Value {
    pub text: Text,
    pub at: usize,
}

/// An attribute of a [`Tag`], borrowed from it: lowercase comparisons go through
/// [`Attr::is`].
#[derive(Default)]
pub(crate) struct Attr<'t> {
    pub key: &'t str,
    pub value: Cow<'t, str>,
    pub at: usize,
}

impl Attr<'_> {
    /// Whether the attribute is named `name`, in any case. Inlined: it is called with a
    /// literal name, against which the comparison folds.
    #[inline]
    pub fn is(&self, name: &str) -> bool {
        self.key.eq_ignore_ascii_case(name)
    }
}

/// How many attributes [`Attrs`] holds in place: a tag that has any has one or two.
const IN_PLACE: usize = 2;

/// The attributes of a tag, read as a slice: the usual one or two held in place, so that
/// reading them allocates nothing; more in a vector.
#[derive(Default)]
pub(crate) struct Attrs<'t> {
    in_place: [Attr<'t>; IN_PLACE],
    len: usize,
    more: Vec<Attr<'t>>,
}

impl<'t> Attrs<'t> {
    fn push(&mut self, attr: Attr<'t>) {
        if self.len < IN_PLACE {
            self.in_place[self.len] = attr;
            self.len += 1;
            return;
        }
        if self.more.is_empty() {
            self.more.extend(self.in_place.iter_mut().map(std::mem::take));
        }
        self.more.push(attr);
    }
}

impl<'t> std::ops::Deref for Attrs<'t> {
    type Target = [Attr<'t>];

    fn deref(&self) -> &[Attr<'t>] {
        match self.more.is_empty() {
            true => &self.in_place[..self.len],
            false => &self.more,
        }
    }
}

pub(crate) enum Node {
    Open(Tag),
    Text(Text),
    /// An end tag, at the offset of its `<`.
    Close(usize),
    Eof,
}

/// The reader of markup, made of its three parts: the window of the text at hand, the
/// lexer's state that turns the markup into nodes, and what is kept at hand for the reader.
pub(crate) struct Tokenizer<'a> {
    /// The text at hand.
    window: Window<'a>,
    /// Where the reading stands, the open elements, the marks ahead.
    lex: Lexer,
    /// What stays at hand for the reader: text kept verbatim, comments, the text after
    /// what it kept for the writer.
    pub kept: Keeping,
    options: &'a LoadOptions,
}

impl<'a> Tokenizer<'a> {
    pub fn new(source: Source<'a>, options: &'a LoadOptions) -> Tokenizer<'a> {
        let lex = Lexer::at(source.base(), Vec::new());
        Tokenizer { window: Window::new(source), lex, kept: Keeping::default(), options }
    }

    pub fn options(&self) -> &LoadOptions {
        self.options
    }

    // ---- the tokenizer

    /// The text at hand from offset `from` on (empty when `from` is past it).
    #[inline(always)]
    fn rest(&self, from: usize) -> &[u8] {
        self.window.rest(from)
    }

    /// Reads more text, keeping what the current node and the last one need. Ok(false)
    /// at the end of the text; the problem that ends the text early, when that is why.
    fn more(&mut self) -> Parsed<bool> {
        // The scan need not keep what the reading read itself.
        self.lex.index.catch_up(self.lex.pos);
        let needed = self.lex.first_needed();
        let keep = self.kept.first().map_or(needed, |kept| kept.min(needed));
        // The scan goes on from where it stands.
        self.window.refill(keep.min(self.lex.index.scanned()))
    }

    /// The index's next mark, that of the markup at `at` (whose first `skip` bytes the
    /// reading has seen), reading more text until the text at hand holds its end; None at
    /// the end of the file. A node longer than `max_text_bytes` is refused before it is all
    /// read: measured, while its end is not at hand, up to the last byte that cannot begin
    /// its closing delimiter of `overlap + 1` bytes.
    fn mark(&mut self, at: usize, skip: usize, overlap: usize) -> Parsed<Option<Mark>> {
        loop {
            if let Some(mark) = self.lex.index.next(at, self.window.text(), self.window.base()) {
                debug_assert_eq!(mark.at, at, "the reading is at the markup marked next");
                return Ok(Some(mark));
            }
            self.within_text_limit(at, self.window.end().saturating_sub(overlap).max(at + skip))?;
            if !self.more()? {
                return Ok(None);
            }
        }
    }

    /// `end`, unless the node from `start` to it is longer than `max_text_bytes`. Every node
    /// is held to it, measured from its first byte to its closing delimiter, whether it lies
    /// in the text at hand or crosses the end of a window: a load from a path refuses
    /// exactly what a load from memory refuses.
    fn within_text_limit(&self, start: usize, end: usize) -> Parsed<usize> {
        if (end - start) as u64 > self.options.max_text_bytes {
            return Err(self.limit(start, "max_text_bytes", self.options.max_text_bytes));
        }
        Ok(end)
    }

    /// Skips the white space before the next node, reading on when it reaches the end of
    /// the text at hand: blank text between elements is never a node of its own where
    /// only elements may follow, however it falls across a window.
    #[inline(always)]
    pub fn skip_space(&mut self) -> Parsed<()> {
        let rest = self.rest(self.lex.pos);
        let (space, all) = (space_len(rest), rest.len());
        self.lex.pos += space;
        match space < all {
            true => Ok(()),
            false => self.skip_space_on(),
        }
    }

    /// [`Tokenizer::skip_space`] once the white space reaches the end of the text at hand:
    /// apart, so that the usual skip is a few instructions where it is inlined.
    #[cold]
    #[inline(never)]
    fn skip_space_on(&mut self) -> Parsed<()> {
        loop {
            // Directly in the root or in a container, nothing read before the white space
            // is looked at again (an item's text is kept while it is open): neither it nor
            // the white space stays at hand, however long it runs.
            if self.lex.outside_items() {
                (self.lex.last, self.lex.started) = (self.lex.pos, self.lex.pos);
            }
            if !self.more()? {
                break;
            }
            let rest = self.rest(self.lex.pos);
            let (space, all) = (space_len(rest), rest.len());
            self.lex.pos += space;
            if space < all {
                break;
            }
        }
        Ok(())
    }

    pub fn next_node(&mut self) -> Parsed<Node> {
        self.lex.begin_node(self.lex.pos);
        loop {
            let at = self.lex.pos;
            let second = match *self.rest(at) {
                [b'<', second, ..] => second,
                [first, ..] if first != b'<' => return self.text_node(at),
                // `<` or nothing at the end of the text at hand.
                ref end => {
                    let lone = !end.is_empty();
                    if self.more()? {
                        continue;
                    }
                    return match lone {
                        true => Err(malformed(at, SyntaxError::UnclosedTag)),
                        false => Ok(Node::Eof),
                    };
                }
            };
            match second {
                b'/' => return self.end_tag(at),
                b'?' => self.processing_instruction(at)?,
                b'!' => match self.bang(at)? {
                    Some(node) => return Ok(node),
                    None => continue,
                },
                _ => return self.start_tag(at),
            }
        }
    }

    /// Text up to the next markup, its references resolved and its line ends normalised.
    fn text_node(&mut self, at: usize) -> Parsed<Node> {
        let end = loop {
            let (text, base) = (self.window.text(), self.window.base());
            if let Some(mark) = self.lex.index.next(at, text, base) {
                break mark.at;
            }
            if let Some(start) = self.lex.index.next_start(text, base) {
                break start;
            }
            self.within_text_limit(at, self.window.end())?;
            if !self.more()? {
                break self.window.end();
            }
        };
        self.lex.pos = self.within_text_limit(at, end)?;
        let text = self.window.slice(at, end);
        // `]]>` ends CDATA only: in text, XML wants its `>` escaped.
        if let Some(i) = memchr::memmem::find(text.as_bytes(), b"]]>") {
            return Err(problem(
                Code::MalformedXml,
                at + i,
                "malformed XML: `]]>` in text outside CDATA (write `]]&gt;`)",
            ));
        }
        let resolved = match is_plain(text.as_bytes()) {
            true => None,
            false => Some(resolve_text(text, at)?),
        };
        Ok(Node::Text(Text { at, end, resolved }))
    }

    /// The end of a tag that starts at `at`: the offset of its `>`.
    fn tag_end(&mut self, at: usize) -> Parsed<usize> {
        let Some(mark) = self.mark(at, 1, 0)? else {
            // The end of the file: quick-xml tells whether a quoted value is open.
            let mut parser = ElementParser::Outside;
            let _ = parser.feed(self.rest(at + 1));
            return Err(malformed(at, parser.eof_error(&[])));
        };
        self.lex.index.take();
        self.within_text_limit(at, mark.end)
    }

    fn start_tag(&mut self, at: usize) -> Parsed<Node> {
        let tag = match self.short_tag(at) {
            Some(tag) => tag,
            None => {
                // Plain attributes are read past without the scan, as the scan reads them.
                let end = match plain_tag_end(self.rest(at)) {
                    Some(len) => self.within_text_limit(at, at + len)?,
                    None => self.tag_end(at)?,
                };
                self.lex.pos = end + 1;
                let content = self.window.slice(at + 1, end);
                let (content, empty) = match content.strip_suffix('/') {
                    Some(content) => (content, true),
                    None => (content, false),
                };
                let name_len = content.bytes().position(is_xml_space_byte).unwrap_or(content.len());
                let name = Name::new(&content[..name_len]);
                Tag { name, end: at + 1 + content.len(), at, empty }
            }
        };
        self.opened(&tag)?;
        Ok(Node::Open(tag))
    }

    /// Reads the usual end tag of the innermost open element, if it is next; whether it
    /// was.
    #[inline(always)]
    fn closes_parent(&mut self) -> bool {
        let at = self.lex.pos;
        let closed = self.usual_end_tag(at);
        if closed {
            self.lex.begin_node(at);
        }
        closed
    }

    /// Reads the end tag at `at` when it is the usual `</Name>` of the innermost open
    /// element, closing it; whether it was.
    #[inline(always)]
    fn usual_end_tag(&mut self, at: usize) -> bool {
        let Some(len) = self.usual_end_tag_len(self.rest(at)) else {
            return false;
        };
        self.lex.pos = at + len;
        self.lex.open.pop();
        true
    }

    /// How long the usual end tag of the innermost open element is, when `text` starts
    /// with it.
    #[inline(always)]
    fn usual_end_tag_len(&self, text: &[u8]) -> Option<usize> {
        let (expected, _) = self.lex.open.last()?;
        let len = expected.end_tag_len(text)?;
        // Longer than the limit (measured up to its `>`): the ordinary reading refuses it.
        ((len - 1) as u64 <= self.options.max_text_bytes).then_some(len)
    }

    /// Counts a start tag just read against the limits and opens its element.
    #[inline(always)]
    fn opened(&mut self, tag: &Tag) -> Parsed<()> {
        let at = tag.at;
        self.lex.elements += 1;
        if self.lex.elements > self.options.max_elements {
            return Err(self.limit(at, "max_elements", self.options.max_elements));
        }
        if !tag.empty {
            if self.lex.open.len() as u64 >= u64::from(self.options.max_depth) {
                return Err(self.limit(at, "max_depth", self.options.max_depth.into()));
            }
            self.lex.open.push((tag.name.clone(), at));
        }
        Ok(())
    }

    /// `<Name>` or `<Name/>` with a short name, the usual tags, read without looking
    /// for quotes. None for any other tag, or when too little text is at hand to tell.
    #[inline(always)]
    fn short_tag(&mut self, at: usize) -> Option<Tag> {
        let [b'<', head @ ..] = self.rest(at).first_chunk::<{ SHORT + 3 }>()? else {
            return None;
        };
        if matches!(head[0], b'/' | b'?' | b'!') {
            return None;
        }
        let (sixteen, after) = head.split_first_chunk::<SHORT>()?;
        let len = match short_name_len(sixteen) {
            Some(len) => len,
            None if ENDS_NAME[usize::from(after[0])] => SHORT,
            None => return None,
        };
        let empty = match head[len..] {
            [b'>', ..] => false,
            [b'/', b'>', ..] => true,
            _ => return None,
        };
        if (1 + len + usize::from(empty)) as u64 > self.options.max_text_bytes {
            return None;
        }
        let name = Name::from_head(head.first_chunk()?, len);
        self.lex.pos = at + 2 + len + usize::from(empty);
        Some(Tag { name, end: at + 1 + len, at, empty })
    }

    fn end_tag(&mut self, at: usize) -> Parsed<Node> {
        if self.usual_end_tag(at) {
            return Ok(Node::Close(at));
        }
        let end = self.tag_end(at)?;
        self.lex.pos = end + 1;
        let found = self.window.slice(at + 2, end).trim_end_matches(text::XML_SPACE);
        let Some((expected, _)) = self.lex.open.pop() else {
            return Err(malformed(at, IllFormedError::UnmatchedEndTag(found.to_owned())));
        };
        if expected.as_str() != found {
            let expected = expected.as_str().to_owned();
            let found = found.to_owned();
            return Err(malformed(at, IllFormedError::MismatchedEndTag { expected, found }));
        }
        Ok(Node::Close(at))
    }

    /// `<?...?>`: the XML declaration is checked, other processing instructions skipped.
    fn processing_instruction(&mut self, at: usize) -> Parsed<()> {
        let Some(mark) = self.mark(at, 2, 1)? else {
            let unclosed = quick_xml::parser::PiParser(false).eof_error(self.rest(at));
            return Err(malformed(at, unclosed));
        };
        // `end` is the `?` of `?>`.
        let end = self.within_text_limit(at, mark.end - 1)?;
        self.lex.index.take();
        self.lex.pos = end + 2;
        let content = self.window.slice(at + 2, end);
        let is_declaration = content.starts_with("xml")
            && content.as_bytes().get(3).is_none_or(|&b| is_xml_space_byte(b));
        if is_declaration {
            if at != 0 {
                return Err(problem(
                    Code::MalformedXml,
                    at,
                    "malformed XML: an XML declaration (<?xml ...?>) is allowed only at the very \
                     start of the file",
                ));
            }
            let decl = BytesDecl::from_start(BytesStart::from_content(content, 3));
            self.check_declared_encoding(&decl, at)?;
        }
        Ok(())
    }

    /// `<!...`: a comment (kept for the writer: None), CDATA (its text), or a DOCTYPE (refused).
    fn bang(&mut self, at: usize) -> Parsed<Option<Node>> {
        while self.rest(at).len() < 9 && self.more()? {}
        let head = self.rest(at);
        if head.starts_with(b"<!--") {
            // XML allows `--` in a comment only as the start of its `-->`: the scan stops at
            // any other.
            let mark = self.mark(at, 4, 2)?;
            let mark =
                mark.ok_or_else(|| malformed::<Problem>(at, SyntaxError::UnclosedComment))?;
            // `end` is the first `--`.
            let end = match mark.stops {
                true => mark.end,
                false => mark.end - 2,
            };
            let end = self.within_text_limit(at, end)?;
            if mark.stops {
                return Err(problem(
                    Code::MalformedXml,
                    end,
                    "malformed XML: `--` inside a comment (a comment ends at the first `--`, \
                     which must be followed by `>`)",
                ));
            }
            self.lex.index.take();
            self.lex.pos = end + 3;
            self.kept.comment(at, self.lex.pos);
            return Ok(None);
        }
        if head.starts_with(b"<![CDATA[") {
            let mark = self.mark(at, 9, 2)?;
            let mark = mark.ok_or_else(|| malformed::<Problem>(at, SyntaxError::UnclosedCData))?;
            // `end` is the `]]>`.
            let end = self.within_text_limit(at, mark.end - 2)?;
            self.lex.index.take();
            self.lex.pos = end + 3;
            return Ok(Some(Node::Text(Text { at: at + 9, end, resolved: None })));
        }
        if matches!(head.get(2), Some(b'D' | b'd')) {
            return Err(problem(
                Code::DoctypeForbidden,
                at,
                "a <!DOCTYPE> is not allowed in a scene file: box2scene never expands entities \
                 or fetches DTDs",
            ));
        }
        Err(malformed(at, SyntaxError::InvalidBangMarkup))
    }
}
