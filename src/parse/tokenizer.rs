//! The tokenizer: a pull reader of markup over the decoded text (whole, or a window moving
//! over a streamed file). It enforces the limits, counts lines as it goes, and hands whole
//! elements, values and attributes to the reader; it builds nothing.
//!
//! The usual markup is read here: tags with short names and plain `name="value"`
//! attributes, values followed by their end tag. Anything else goes to quick-xml: its
//! element parser finds where a tag ends when the text at hand does not show it, its
//! attribute iterator reads and checks the other attributes, its reference and declaration
//! types resolve entities and read the XML declaration, and its errors are the messages.
//! The loop is ours because quick-xml 0.42's `Reader` checks every event's bytes as UTF-8
//! again; the text here was checked once by its source, and slices of it at ASCII markup
//! are text by construction.
#![forbid(unsafe_code)]

use std::borrow::Cow;

use quick_xml::errors::{IllFormedError, SyntaxError};
use quick_xml::events::attributes::AttrError;
use quick_xml::events::{BytesDecl, BytesRef, BytesStart};
use quick_xml::parser::{ElementParser, Parser as _};

use super::lines::{Cursor, Lines};
use super::names::{Name, SHORT};
use super::shorten;
use crate::error::{Code, Finding, Parsed, Position, Problem, Spot, problem};
use crate::input::{Encoding, Source, first_non_char};
use crate::options::LoadOptions;
use crate::text::{self, trim_xml, trim_xml_at};

/// How a reading stops where its text ends before an item (see
/// [`Tokenizer::end_before`]): not a finding of the file, so it has the code of none.
#[cold]
pub(super) fn end_of_piece() -> Problem {
    problem(Code::Ok, 0, "the reading ends before an item here")
}

/// Whether a reading stopped with [`end_of_piece`].
pub(super) fn is_end_of_piece(problem: &Problem) -> bool {
    problem.code == Code::Ok
}

#[cold]
fn malformed(at: usize, e: impl Into<quick_xml::Error>) -> Problem {
    problem(Code::MalformedXml, at, format!("malformed XML: {}", e.into()))
}

/// A start tag (`<Name ...>` or `<Name .../>`) and where it begins. It owns what it needs,
/// so it outlives the text window it was read from.
pub(super) struct Tag {
    pub name: Name,
    /// What lies between `<` and `>` (or `/>`), when the tag has more than its name.
    content: Option<Box<str>>,
    /// Offset of its `<`.
    pub at: usize,
    /// `<Name/>`: it has no children and no text.
    pub empty: bool,
}

impl Tag {
    /// A start tag with its name alone, open: as a reading that goes on from inside the
    /// element assumes it.
    pub fn item(name: Name, at: usize) -> Tag {
        Tag { name, content: None, at, empty: false }
    }

    /// A tag that names no element, for a reader's loop to read its children into (see
    /// [`Tokenizer::child`]).
    pub fn slot() -> Tag {
        Tag { name: Name::Short(0, [0; SHORT]), content: None, at: 0, empty: true }
    }

    pub fn name(&self) -> &str {
        self.name.as_str()
    }

    /// Names compare case-insensitively (spec section 2).
    #[inline]
    pub fn is(&self, name: &str) -> bool {
        self.name.key() == super::names::key(name)
    }
}

/// A piece of text: a range of the decoded text, or its resolved form when it held
/// references or carriage returns. Read it with [`Tokenizer::text_of`] before the next node.
pub(super) struct Text {
    pub at: usize,
    end: usize,
    resolved: Option<Resolved>,
}

impl Text {
    /// Its text, from `source` when it is a range of it.
    fn read<'t>(&'t self, source: &'t Source) -> &'t str {
        match &self.resolved {
            Some(resolved) => &resolved.text,
            None => source.slice(self.at, self.end),
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
pub(super) struct Value {
    pub text: Text,
    pub at: usize,
}

/// An attribute of a [`Tag`], borrowed from it: lowercase comparisons go through
/// [`Attr::is`].
pub(super) struct Attr<'t> {
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

pub(super) enum Node {
    Open(Tag),
    Text(Text),
    /// An end tag, at the offset of its `<`.
    Close(usize),
    Eof,
}

/// The reader of markup: where it is in the text, which elements are open, and the
/// comments it passed since the reader last took them.
pub(super) struct Tokenizer<'a> {
    source: Source<'a>,
    options: &'a LoadOptions,
    /// The tokenizer's offset: the next node starts here.
    pos: usize,
    /// Where the node being read and the one before it began: the text from the one
    /// before on stays at hand, so a value can be read after the end tag that ends it.
    started: usize,
    last: usize,
    /// Set while text is kept verbatim (UserData, an unknown element, a Farseer-only
    /// joint, one inside another): the text from the first on stays at hand.
    pins: Vec<usize>,
    /// The comments read since the reader last took them, as spans of the text (which
    /// stay at hand until then).
    comments: Vec<(usize, usize)>,
    /// The open elements, outermost first, with the offsets of their start tags: the text
    /// of the third (an item of a world container, an object) stays at hand while it is
    /// open, so that its offsets can be placed until it ends.
    open: Vec<(Name, usize)>,
    elements: u64,
    /// Lines and columns, counted over the text as it is passed.
    lines: Lines,
    /// Where the reading may end before an item (see [`Tokenizer::end_before`]): the
    /// items' offsets in order, with the names of the containers they are assumed to be
    /// in; those from `next_end` on lie ahead, the first at `end_at` (`usize::MAX` for
    /// none), where the text at hand ends.
    ends: Vec<(usize, Name)>,
    next_end: usize,
    end_at: usize,
}

/// Where a tokenizer stopped, for another to go on from there (see [`Tokenizer::resume`]).
pub(super) struct Stop {
    pos: usize,
    started: usize,
    last: usize,
    open: Vec<(Name, usize)>,
    elements: u64,
    /// The position of `pos`, counted from where the tokenizer started, when it placed
    /// what it found as it read; None for a text that stays in memory, whose findings are
    /// placed once the whole is read.
    end: Option<Position>,
}

impl Stop {
    /// The elements the tokenizer read.
    pub fn elements(&self) -> u64 {
        self.elements
    }

    /// The position where it stopped, counted from where it started, when it placed what
    /// it found as it read.
    pub fn end(&self) -> Option<Position> {
        self.end
    }
}

impl<'a> Tokenizer<'a> {
    pub fn new(source: Source<'a>, options: &'a LoadOptions) -> Tokenizer<'a> {
        let lines = Lines::new(source.encoding(), Cursor::start(source.base()));
        Tokenizer {
            source,
            options,
            pos: 0,
            started: 0,
            last: 0,
            pins: Vec::new(),
            comments: Vec::new(),
            open: Vec::new(),
            elements: 0,
            lines,
            ends: Vec::new(),
            next_end: 0,
            end_at: usize::MAX,
        }
    }

    pub fn options(&self) -> &LoadOptions {
        self.options
    }

    // ---- the tokenizer

    /// The text at hand from offset `from` on (empty when `from` is past it).
    #[inline(always)]
    fn rest(&self, from: usize) -> &[u8] {
        let text = self.source.text().as_bytes();
        text.get(from - self.source.base()..).unwrap_or_default()
    }

    /// Reads more text, keeping what the current node and the last one need. Ok(false)
    /// at the end of the file; the problem that ends the text early, when that is why;
    /// [`end_of_piece`] where the reading ends before an item (see
    /// [`Tokenizer::end_before`]).
    fn more(&mut self) -> Parsed<bool> {
        let keep = [self.pins.first(), self.comments.first().map(|(at, _)| at)]
            .into_iter()
            .flatten()
            .fold(self.last, |keep, &at| keep.min(at));
        let keep = self.open.get(2).map_or(keep, |&(_, object)| keep.min(object));
        // A text in memory stays at hand: nothing is let go, so nothing is counted yet.
        if !self.source.is_whole() {
            self.lines.release(self.source.text(), self.source.base(), keep);
        }
        let end = self.source.end();
        while !self.source.more(keep) {
            if self.source.end() != self.end_at {
                return match self.source.stop() {
                    Some(stop) => Err(Box::new(stop.clone())),
                    None => Ok(false),
                };
            }
            if self.pos == self.end_at && self.may_end() {
                return Err(end_of_piece());
            }
            self.pass_end();
            // A text in memory is at hand past the end at once.
            if self.source.end() > end {
                break;
            }
        }
        Ok(true)
    }

    /// Whether the reading, at the next end, may end there: directly in the container
    /// assumed, in the root, with nothing read waiting for the reader (text kept
    /// verbatim, comments, which would go before the item).
    fn may_end(&self) -> bool {
        let container = &self.ends[self.next_end].1;
        matches!(&self.open[..], [_, (open, _)] if open.as_bytes() == container.as_bytes())
            && self.pins.is_empty()
            && self.comments.is_empty()
    }

    /// The offset at which `find` first succeeds on the text from `from` on, reading more
    /// as needed; None at the end of the file. `find` is given the text from where it
    /// stopped last, less `overlap` bytes (a delimiter of `overlap + 1` bytes may be cut by
    /// the end of the text at hand), and returns an offset into it. A node longer than
    /// `max_text_bytes` is refused before it is all read.
    fn scan(
        &mut self,
        start: usize,
        mut from: usize,
        overlap: usize,
        mut find: impl FnMut(&[u8]) -> Option<usize>,
    ) -> Parsed<Option<usize>> {
        loop {
            let rest = self.rest(from);
            if let Some(i) = find(rest) {
                return self.within_text_limit(start, from + i).map(Some);
            }
            from = (from + rest.len()).saturating_sub(overlap).max(from);
            if (from - start) as u64 > self.options.max_text_bytes {
                return Err(self.limit(start, "max_text_bytes", self.options.max_text_bytes));
            }
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
        let rest = self.rest(self.pos);
        let (space, all) = (space_len(rest), rest.len());
        self.pos += space;
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
        while self.more()? {
            let rest = self.rest(self.pos);
            let (space, all) = (space_len(rest), rest.len());
            self.pos += space;
            if space < all {
                break;
            }
        }
        Ok(())
    }

    /// A node begins at `at`: the one before it stays at hand (see [`Tokenizer::started`]).
    #[inline(always)]
    fn begin_node(&mut self, at: usize) {
        (self.last, self.started) = (self.started, at);
    }

    pub fn next_node(&mut self) -> Parsed<Node> {
        self.begin_node(self.pos);
        loop {
            let at = self.pos;
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
        let mut plain = true;
        let end = self.scan(at, at, 0, |rest| {
            let mut from = 0;
            while let Some(i) = find3(&rest[from..], b'<', b'&', b'\r') {
                if rest[from + i] == b'<' {
                    return Some(from + i);
                }
                plain = false;
                from += i + 1;
            }
            None
        })?;
        let end = end.unwrap_or(self.source.end());
        if (end - at) as u64 > self.options.max_text_bytes {
            return Err(self.limit(at, "max_text_bytes", self.options.max_text_bytes));
        }
        self.pos = end;
        // `]]>` ends CDATA only: in text, XML wants its `>` escaped.
        if let Some(i) = memchr::memmem::find(self.source.slice(at, end).as_bytes(), b"]]>") {
            return Err(problem(
                Code::MalformedXml,
                at + i,
                "malformed XML: `]]>` in text outside CDATA (write `]]&gt;`)",
            ));
        }
        let resolved = match plain {
            true => None,
            false => Some(resolve_text(self.source.slice(at, end), at)?),
        };
        Ok(Node::Text(Text { at, end, resolved }))
    }

    /// The end of a tag that starts at `at`: the offset of its `>`.
    fn tag_end(&mut self, at: usize) -> Parsed<usize> {
        // The tag at hand, its quoted values skipped; the element parser takes the rest.
        let rest = self.rest(at + 1);
        let mut from = 0;
        while let Some(i) = find3(&rest[from..], b'>', b'"', b'\'').map(|i| from + i) {
            if rest[i] == b'>' {
                return self.within_text_limit(at, at + 1 + i);
            }
            // Values are short: the same byte three times is found eight bytes at a time.
            let quote = rest[i];
            match find3(&rest[i + 1..], quote, quote, quote) {
                Some(len) => from = i + 2 + len,
                None => break,
            }
        }
        let mut parser = ElementParser::Outside;
        match self.scan(at, at + 1, 0, |rest| parser.feed(rest))? {
            Some(end) => Ok(end),
            None => Err(malformed(at, parser.eof_error(&[]))),
        }
    }

    fn start_tag(&mut self, at: usize) -> Parsed<Node> {
        let tag = match self.short_tag(at) {
            Some(tag) => tag,
            None => {
                let end = self.tag_end(at)?;
                self.pos = end + 1;
                let content = self.source.slice(at + 1, end);
                let (content, empty) = match content.strip_suffix('/') {
                    Some(content) => (content, true),
                    None => (content, false),
                };
                let name_len =
                    content.bytes().position(text::is_xml_space_byte).unwrap_or(content.len());
                let name = &content[..name_len];
                let content = (content.len() > name_len).then(|| content.into());
                Tag { name: Name::new(name), content, at, empty }
            }
        };
        self.opened(&tag)?;
        Ok(Node::Open(tag))
    }

    /// Reads the usual end tag of the innermost open element, if it is next; whether it
    /// was.
    #[inline(always)]
    fn closes_parent(&mut self) -> bool {
        let at = self.pos;
        let closed = self.usual_end_tag(at);
        if closed {
            self.begin_node(at);
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
        self.pos = at + len;
        self.open.pop();
        true
    }

    /// How long the usual end tag of the innermost open element is, when `text` starts
    /// with it.
    #[inline(always)]
    fn usual_end_tag_len(&self, text: &[u8]) -> Option<usize> {
        let (expected, _) = self.open.last()?;
        let len = expected.end_tag_len(text)?;
        // Longer than the limit (measured up to its `>`): the ordinary reading refuses it.
        ((len - 1) as u64 <= self.options.max_text_bytes).then_some(len)
    }

    /// Counts a start tag just read against the limits and opens its element.
    #[inline(always)]
    fn opened(&mut self, tag: &Tag) -> Parsed<()> {
        let at = tag.at;
        self.elements += 1;
        if self.elements > self.options.max_elements {
            return Err(self.limit(at, "max_elements", self.options.max_elements));
        }
        if !tag.empty {
            if self.open.len() as u64 >= u64::from(self.options.max_depth) {
                return Err(self.limit(at, "max_depth", self.options.max_depth.into()));
            }
            self.open.push((tag.name.clone(), at));
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
        let len = head.iter().position(|&b| ENDS_NAME[usize::from(b)]).filter(|&n| n <= SHORT)?;
        let empty = match head[len..] {
            [b'>', ..] => false,
            [b'/', b'>', ..] => true,
            _ => return None,
        };
        if (1 + len + usize::from(empty)) as u64 > self.options.max_text_bytes {
            return None;
        }
        let name = Name::from_head(head.first_chunk()?, len);
        self.pos = at + 2 + len + usize::from(empty);
        Some(Tag { name, content: None, at, empty })
    }

    fn end_tag(&mut self, at: usize) -> Parsed<Node> {
        if self.usual_end_tag(at) {
            return Ok(Node::Close(at));
        }
        let end = self.tag_end(at)?;
        self.pos = end + 1;
        let found = self.source.slice(at + 2, end).trim_end_matches(text::XML_SPACE);
        let Some((expected, _)) = self.open.pop() else {
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
        let end = self.scan(at, at + 2, 1, |rest| memchr::memmem::find(rest, b"?>"))?;
        let Some(end) = end else {
            let unclosed = quick_xml::parser::PiParser(false).eof_error(self.rest(at));
            return Err(malformed(at, unclosed));
        };
        self.pos = end + 2;
        let content = self.source.slice(at + 2, end);
        let is_declaration = content.starts_with("xml")
            && content.as_bytes().get(3).is_none_or(|&b| text::is_xml_space_byte(b));
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
            // XML allows `--` in a comment only as the start of its `-->`.
            let mut dashes = false;
            let end = self.scan(at, at + 4, 2, |rest| {
                let i = memchr::memmem::find(rest, b"--")?;
                dashes = *rest.get(i + 2)? != b'>';
                Some(i)
            })?;
            let end = end.ok_or_else(|| malformed(at, SyntaxError::UnclosedComment))?;
            if dashes {
                return Err(problem(
                    Code::MalformedXml,
                    end,
                    "malformed XML: `--` inside a comment (a comment ends at the first `--`, \
                     which must be followed by `>`)",
                ));
            }
            self.pos = end + 3;
            if self.pins.is_empty() {
                self.comments.push((at, self.pos));
            }
            return Ok(None);
        }
        if head.starts_with(b"<![CDATA[") {
            let end = self.scan(at, at + 9, 2, |rest| memchr::memmem::find(rest, b"]]>"))?;
            let end = end.ok_or_else(|| malformed(at, SyntaxError::UnclosedCData))?;
            self.pos = end + 3;
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

    /// The text of `t`, valid until the next node is read.
    pub fn text_of<'t>(&'t self, t: &'t Text) -> &'t str {
        t.read(&self.source)
    }

    pub fn is_blank(&self, t: &Text) -> bool {
        trim_xml(self.text_of(t)).is_empty()
    }

    #[cold]
    pub fn limit(&self, at: usize, name: &str, value: u64) -> Problem {
        problem(
            Code::LimitExceeded,
            at,
            format!(
                "the file exceeds a load limit here ({name} = {value}); raise it in the load options if the file is trusted"
            ),
        )
    }

    fn check_declared_encoding(&self, decl: &BytesDecl, at: usize) -> Parsed<()> {
        let Some(Ok(declared)) = decl.encoding() else {
            return Ok(());
        };
        let declared = declared.to_ascii_lowercase();
        let fits = match self.source.encoding() {
            Encoding::Utf8 { .. } => matches!(declared.as_str(), "utf-8" | "utf8"),
            Encoding::Utf16 { .. } => declared.starts_with("utf-16") || declared == "unicode",
        };
        if fits {
            return Ok(());
        }
        Err(problem(
            Code::UnsupportedEncoding,
            at,
            format!(
                "the declaration names encoding '{declared}', but box2scene reads UTF-8 and \
                 UTF-16 (with a byte-order mark) only; convert the file"
            ),
        ))
    }

    /// Reads the next child element of `parent` into `child`, which the reader keeps over
    /// its loop, so that the tag is made where the reader holds it rather than moved out of
    /// a result: whether there was one (false at the end of `parent`). Blank text and
    /// comments are skipped; other text is an error. Inlined into the readers' loops, so
    /// that the usual child costs no more than it needs.
    #[inline(always)]
    pub fn child(&mut self, parent: &Tag, child: &mut Tag) -> Parsed<bool> {
        if parent.empty {
            return Ok(false);
        }
        self.skip_space()?;
        if let Some(tag) = self.short_tag(self.pos) {
            self.begin_node(tag.at);
            self.opened(&tag)?;
            *child = tag;
            return Ok(true);
        }
        if self.closes_parent() {
            return Ok(false);
        }
        match self.other_child(parent)? {
            Some(tag) => {
                *child = tag;
                Ok(true)
            }
            None => Ok(false),
        }
    }

    /// [`Tokenizer::child`] when the next node is not the usual start or end tag, and the
    /// general reading of a child: apart, so that the usual child costs no more than it
    /// needs.
    #[inline(never)]
    fn other_child(&mut self, parent: &Tag) -> Parsed<Option<Tag>> {
        loop {
            self.skip_space()?;
            match self.next_node()? {
                Node::Open(tag) => return Ok(Some(tag)),
                Node::Close(_) => return Ok(None),
                Node::Text(t) => {
                    let (lead, text) = trim_xml_at(self.text_of(&t));
                    if !text.is_empty() {
                        return Err(problem(
                            Code::UnexpectedText,
                            t.written_at(lead),
                            format!(
                                "text '{}' inside <{}>, which holds only elements",
                                shorten(text),
                                parent.name()
                            ),
                        ));
                    }
                }
                Node::Eof => return Err(self.unclosed(parent)),
            }
        }
    }

    /// The text of a value element (`<Density>5</Density>`), trimmed.
    pub fn value(&mut self, tag: &Tag) -> Parsed<Value> {
        match self.plain_value(tag) {
            Some(value) => Ok(value),
            None => self.value_of_nodes(tag),
        }
    }

    /// [`Tokenizer::value`] when it is not the usual one: read node by node.
    fn value_of_nodes(&mut self, tag: &Tag) -> Parsed<Value> {
        let mut value: Option<Text> = None;
        if !tag.empty {
            loop {
                match self.next_node()? {
                    Node::Text(t) => match &mut value {
                        None => value = Some(t),
                        Some(first) => {
                            let joined = self.joined(first, &t);
                            if joined.text.len() as u64 > self.options.max_text_bytes {
                                return Err(self.limit(
                                    t.at,
                                    "max_text_bytes",
                                    self.options.max_text_bytes,
                                ));
                            }
                            first.resolved = Some(joined);
                        }
                    },
                    Node::Open(child) => {
                        return Err(problem(
                            Code::UnexpectedElement,
                            child.at,
                            format!(
                                "<{}> holds a value, not elements such as <{}>",
                                tag.name(),
                                child.name()
                            ),
                        ));
                    }
                    Node::Close(_) => break,
                    Node::Eof => return Err(self.unclosed(tag)),
                }
            }
        }
        let Some(mut text) = value else {
            return Ok(Value {
                text: Text { at: tag.at, end: tag.at, resolved: None },
                at: tag.at,
            });
        };
        let (lead, trimmed) = trim_xml_at(self.text_of(&text));
        let (at, trimmed) = (text.written_at(lead), trimmed.len());
        match &mut text.resolved {
            Some(resolved) => {
                resolved.keep(lead, lead + trimmed);
                text.at = at;
            }
            None => (text.at, text.end) = (at, at + trimmed),
        }
        Ok(Value { text, at })
    }

    /// The text of `first` followed by that of `second`, which were written apart.
    fn joined(&self, first: &mut Text, second: &Text) -> Resolved {
        let mut joined = first.resolved.take().unwrap_or_else(|| {
            let mut whole = Resolved::default();
            whole.push(self.source.slice(first.at, first.end), first.at);
            whole
        });
        match &second.resolved {
            Some(resolved) => joined.append(resolved, second.at),
            None => joined.push(self.source.slice(second.at, second.end), second.at),
        }
        joined
    }

    /// The usual value, read without nodes: text at hand with no markup, references or
    /// carriage returns, then the end tag of `tag`. None for anything else.
    #[inline(always)]
    fn plain_value(&mut self, tag: &Tag) -> Option<Value> {
        let (at, end) = self.plain_span(tag)?;
        Some(Value { text: Text { at, end, resolved: None }, at })
    }

    /// Where the text of [`Tokenizer::plain_value`] starts and ends.
    #[inline(always)]
    fn plain_span(&mut self, tag: &Tag) -> Option<(usize, usize)> {
        // Text kept as written (a Farseer-only joint) must be XML as it stands, which the
        // nodes' path checks.
        if tag.empty || !self.pins.is_empty() {
            return None;
        }
        let at = self.pos;
        let rest = self.rest(at);
        let len = find3(rest, b'<', b'&', b'\r').filter(|&i| rest[i] == b'<')?;
        if len as u64 > self.options.max_text_bytes {
            return None;
        }
        let end_tag = self.usual_end_tag_len(&rest[len..])?;
        let (start, end) = trimmed_span(&rest[..len]);
        self.pos = at + len + end_tag;
        self.open.pop();
        // `<X></X>` has its value at its tag.
        Some(if len == 0 { (tag.at, tag.at) } else { (at + start, at + end) })
    }

    /// Reads a value element and converts its text with `convert`: the value and its offset,
    /// or (inside) the error for a text that does not convert, which leaves the reading
    /// where a value that converts would. Generic, not a `fn` pointer, so that the usual
    /// conversions are inlined into their readers.
    #[inline]
    pub fn parsed<T>(
        &mut self,
        tag: &Tag,
        convert: impl FnOnce(&str) -> Result<T, Finding>,
    ) -> Parsed<Result<(T, usize), Problem>> {
        // The usual value converted where it is written, without a Value to carry it.
        if let Some((at, end)) = self.plain_span(tag) {
            return Ok(match convert(self.source.slice(at, end)) {
                Ok(v) => Ok((v, at)),
                Err(e) => {
                    let value = Value { text: Text { at, end, resolved: None }, at };
                    Err(self.bad_value(tag, &value, e))
                }
            });
        }
        let value = self.value_of_nodes(tag)?;
        Ok(match convert(self.text_of(&value.text)) {
            Ok(v) => Ok((v, value.at)),
            Err(e) => Err(self.bad_value(tag, &value, e)),
        })
    }

    /// The error for the value of `tag`, which `convert` refused with `e`.
    #[cold]
    fn bad_value(&self, tag: &Tag, value: &Value, e: Finding) -> Problem {
        let at = value.text.written_at(e.at);
        problem(e.code, at, format!("<{}>: {}", tag.name(), e.message))
    }

    /// Converts an attribute's value with `convert`; errors point into the value.
    pub fn attribute<T>(
        &self,
        tag: &Tag,
        attr: &Attr,
        convert: fn(&str) -> Result<T, Finding>,
    ) -> Parsed<(T, usize)> {
        let (lead, value) = trim_xml_at(&attr.value);
        match convert(value) {
            Ok(v) => Ok((v, written_at(tag, attr, lead))),
            Err(e) => Err(problem(
                e.code,
                written_at(tag, attr, lead + e.at),
                format!("<{} {}>: {}", tag.name(), attr.key, e.message),
            )),
        }
    }

    /// The attributes of `tag`, unescaped, each with the offset of its value.
    pub fn attributes<'t>(&self, tag: &'t Tag) -> Parsed<Vec<Attr<'t>>> {
        let Some(content) = tag.content.as_deref() else {
            return Ok(Vec::new());
        };
        let attrs = match plain_attributes(content, tag.name.len(), tag.at) {
            Some(attrs) => attrs,
            None => self.xml_attributes(tag, content)?,
        };
        // Names compare as the loader reads them, ignoring case: `Type` and `type` are one
        // attribute, given twice.
        for (i, attr) in attrs.iter().enumerate() {
            if attrs[..i].iter().any(|a| a.is(attr.key)) {
                let offset = attr.key.as_ptr().addr().saturating_sub(content.as_ptr().addr());
                return Err(problem(
                    Code::DuplicateAttribute,
                    tag.at + 1 + offset,
                    format!(
                        "<{}> has the attribute {} twice (names ignore case)",
                        tag.name(),
                        attr.key
                    ),
                ));
            }
        }
        Ok(attrs)
    }

    /// Checks that the attributes of `tag`, which is kept as written rather than read
    /// (inside UserData or an ignored element), are well-formed: the writer writes them
    /// back. Names differing in case are distinct there, as in any XML.
    pub fn check_attributes(&self, tag: &Tag) -> Parsed<()> {
        let Some(content) = tag.content.as_deref() else {
            return Ok(());
        };
        if plain_attributes(content, tag.name.len(), tag.at).is_none() {
            self.xml_attributes(tag, content)?;
        }
        Ok(())
    }

    /// The attributes of `tag`, whose `content` is not as plain as most, read by quick-xml.
    fn xml_attributes<'t>(&self, tag: &'t Tag, content: &'t str) -> Parsed<Vec<Attr<'t>>> {
        // quick-xml's attributes borrow its BytesStart; the same text, borrowed from the
        // tag, is found by its offset in `content` (which counts from after `<`).
        let within = |piece: &str| {
            let from = piece.as_ptr().addr().checked_sub(content.as_ptr().addr())?;
            Some((from, content.get(from..from + piece.len())?))
        };
        let start = BytesStart::from_content(content, tag.name.len());
        let mut attrs = Vec::new();
        for attr in start.attributes() {
            let attr = attr.map_err(|e| self.attr_error(tag, e))?;
            let raw = within(&attr.value);
            let at = raw.map_or(tag.at, |(from, _)| tag.at + 1 + from);
            if let Some(lt) = raw.and_then(|(_, raw)| raw.find('<')) {
                return Err(problem(
                    Code::MalformedXml,
                    at + lt,
                    "malformed XML: `<` in an attribute value (write `&lt;`)",
                ));
            }
            if let Some((_, raw)) = raw.filter(|(_, raw)| raw.contains('&')) {
                // quick-xml resolves a reference to any character; ours to those XML allows,
                // with the position of the first that names another.
                resolve_text(raw, at)?;
            }
            let value = match (attr.normalized_value(quick_xml::XmlVersion::Implicit1_0), raw) {
                // Unchanged by normalisation: the text as written.
                (Ok(Cow::Borrowed(_)), Some((_, raw))) => Cow::Borrowed(raw),
                (Ok(value), _) => Cow::Owned(value.into_owned()),
                (Err(e), _) => {
                    return Err(problem(Code::MalformedXml, at, format!("malformed XML: {e}")));
                }
            };
            let key = within(attr.key.as_ref()).map_or("", |(_, key)| key);
            attrs.push(Attr { key, value, at });
        }
        Ok(attrs)
    }

    #[cold]
    fn attr_error(&self, tag: &Tag, e: AttrError) -> Problem {
        // Attribute error positions count from the first byte after `<`.
        let at = |pos: usize| tag.at + 1 + pos;
        match e {
            AttrError::Duplicated(pos, _) => problem(
                Code::DuplicateAttribute,
                at(pos),
                format!("<{}> has the same attribute twice", tag.name()),
            ),
            e => problem(Code::MalformedXml, tag.at, format!("malformed XML: {e}")),
        }
    }

    /// Skips `tag` and everything inside it.
    pub fn skip(&mut self, tag: &Tag) -> Parsed<()> {
        if tag.empty {
            return Ok(());
        }
        let mut depth = 1;
        while depth > 0 {
            match self.next_node()? {
                Node::Open(t) => {
                    self.check_attributes(&t)?;
                    depth += usize::from(!t.empty);
                }
                Node::Text(..) => {}
                Node::Close(_) => depth -= 1,
                Node::Eof => return Err(self.unclosed(tag)),
            }
        }
        Ok(())
    }

    /// The error for a repeated container.
    #[cold]
    pub fn duplicate_container(&self, parent: &Tag, child: &Tag) -> Problem {
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
    pub fn missing(&self, tag: &Tag, what: &str) -> Problem {
        problem(Code::MissingElement, tag.at, format!("<{}> has no {what}", tag.name()))
    }

    #[cold]
    pub fn unclosed(&self, tag: &Tag) -> Problem {
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

    /// Keeps the text from `from` on at hand (UserData keeps its inner XML verbatim),
    /// until [`Tokenizer::unpin`].
    pub fn pin(&mut self, from: usize) {
        self.pins.push(from);
    }

    /// The text from the last pinned offset to `to`, and lets it go.
    pub fn unpin(&mut self, to: usize) -> String {
        let from = self.pins.pop().unwrap_or(to);
        self.source.slice(from, to).to_owned()
    }

    /// Starts reading at `at`, the start tag of an item in the open elements `open` (the
    /// root and a container), as a reader of one piece of the text does. Positions are
    /// counted from there (see [`Cursor::start`]).
    pub fn start_item(&mut self, at: usize, open: Vec<(Name, usize)>) {
        (self.pos, self.started, self.last, self.open) = (at, at, at, open);
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
    /// with nothing read waiting, it stops there with [`end_of_piece`] before the item.
    /// Where it cannot, the reading goes on past it.
    pub fn end_before(&mut self, ends: Vec<(usize, Name)>) {
        (self.ends, self.next_end) = (ends, 0);
        self.aim();
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

    /// Lets go of the last pinned offset, keeping nothing.
    pub fn drop_pin(&mut self) {
        self.pins.pop();
    }

    /// Whether text is being kept verbatim (see [`Tokenizer::pin`]).
    pub fn pinned(&self) -> bool {
        !self.pins.is_empty()
    }

    /// Whether comments were read since [`Tokenizer::take_comments`] was last called.
    #[inline(always)]
    pub fn has_comments(&self) -> bool {
        !self.comments.is_empty()
    }

    /// The comments read since the last call, as spans of the text at hand; None when
    /// there are none, as between most elements.
    pub fn take_comments(&mut self) -> Option<Vec<(usize, usize)>> {
        (!self.comments.is_empty()).then(|| std::mem::take(&mut self.comments))
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

/// The attributes of the usual tag, whose `content` (what follows its `<`) has its name
/// of `name_len` bytes and then `name="value"` pairs (or single quotes) after white space,
/// with plain names, values with no reference, `<` or line break, and no name twice.
/// None for anything else: quick-xml reads that, and tells what is malformed.
fn plain_attributes(content: &str, name_len: usize, at: usize) -> Option<Vec<Attr<'_>>> {
    let bytes = content.as_bytes();
    // A tag with more than its name has an attribute or two: one allocation, no growing.
    let mut attrs: Vec<Attr> = Vec::with_capacity(2);
    let mut i = name_len;
    loop {
        // The tag's text is the source's, so white space is every byte up to 0x20.
        let space = space_len(&bytes[i..]);
        i += space;
        if i == bytes.len() {
            return Some(attrs);
        }
        let key_len = bytes[i..].iter().position(|&b| !is_plain_name_byte(b))?;
        let (key, after) = (&content[i..i + key_len], &bytes[i + key_len..]);
        let [b'=', quote @ (b'"' | b'\''), value @ ..] = after else {
            return None;
        };
        let len = value
            .iter()
            .position(|b| matches!(b, b'&' | b'<' | b'\t' | b'\n' | b'\r') || b == quote)?;
        if space == 0 || key_len == 0 || value[len] != *quote || attrs.iter().any(|a| a.is(key)) {
            return None;
        }
        let start = i + key_len + 2;
        let value = Cow::Borrowed(&content[start..start + len]);
        attrs.push(Attr { key, value, at: at + 1 + start });
        i = start + len + 1;
    }
}

/// An attribute of `tag` as written (` key="value"`, its value's references unresolved).
pub(super) fn verbatim(tag: &Tag, attr: &Attr) -> String {
    let (quote, value) = written_value(tag, attr);
    format!(" {}={quote}{value}{quote}", attr.key)
}

/// The quote around the value of an attribute of `tag`, and the value as written.
fn written_value<'t>(tag: &'t Tag, attr: &Attr) -> (char, &'t str) {
    let content = tag.content.as_deref().unwrap_or_default();
    let value = (attr.at - tag.at - 1).min(content.len());
    let quote = content[..value].chars().next_back().unwrap_or('"');
    let len = content[value..].find(quote).unwrap_or(content.len() - value);
    (quote, &content[value..value + len])
}

/// Where the character at `offset` of an attribute's value is written. A value unlike what
/// is written (references resolved, white space normalised) is resolved again to tell, as
/// only a message needs it: its bytes line up with the resolved text's.
fn written_at(tag: &Tag, attr: &Attr, offset: usize) -> usize {
    if let Cow::Borrowed(_) = attr.value {
        return attr.at + offset;
    }
    match resolve_text(written_value(tag, attr).1, attr.at) {
        Ok(resolved) => resolved.written_at(attr.at, offset),
        Err(_) => attr.at + offset,
    }
}

/// ASCII letters, digits, `_`, `:`, `-` and `.`: the names of attributes read without
/// quick-xml.
fn is_plain_name_byte(b: u8) -> bool {
    b.is_ascii_alphanumeric() || matches!(b, b'_' | b':' | b'-' | b'.')
}

/// The bytes that end a name in the usual tags: white space (and the control characters,
/// which no name has), `/`, `>` and quotes.
const ENDS_NAME: [bool; 256] = {
    let mut ends = [false; 256];
    let mut b = 0;
    while b <= b' ' {
        ends[b as usize] = true;
        b += 1;
    }
    ends[b'/' as usize] = true;
    ends[b'>' as usize] = true;
    ends[b'"' as usize] = true;
    ends[b'\'' as usize] = true;
    ends
};

/// How many bytes of white space the text at hand `text` starts with. Every byte of it up to
/// 0x20 is white space, as the source stops before any other control character: so the
/// test is one comparison a byte, made eight at a time.
#[inline(always)]
fn space_len(text: &[u8]) -> usize {
    if text.first().is_none_or(|&b| b > b' ') {
        return 0;
    }
    const HIGH: u64 = u64::from_le_bytes([0x80; 8]);
    const OVER_SPACE: u64 = u64::from_le_bytes([0x80 - 0x21; 8]);
    let mut i = 0;
    while let Some(eight) = text[i..].first_chunk::<8>() {
        let word = u64::from_le_bytes(*eight);
        // The high bit of each byte above 0x20: the low seven bits plus 0x5F reach 0x80
        // from 0x21 on and never carry out of their byte (0x7F + 0x5F < 0x100); a byte of
        // 0x80 or more has it already.
        let other = (((word & !HIGH) + OVER_SPACE) | word) & HIGH;
        if other != 0 {
            return i + (other.trailing_zeros() / 8) as usize;
        }
        i += 8;
    }
    i + text[i..].iter().position(|&b| b > b' ').unwrap_or(text.len() - i)
}

/// Where the text at hand `text` without leading and trailing white space starts and ends
/// (see [`space_len`]).
#[inline(always)]
fn trimmed_span(text: &[u8]) -> (usize, usize) {
    let start = space_len(text);
    let end = text.iter().rposition(|&b| b > b' ').map_or(start, |i| i + 1);
    (start, end)
}

/// The offset of the first of three bytes in `hay`. Nodes are short: their first 32 bytes
/// are looked at eight at a time, which is cheaper than setting up memchr, which takes the
/// rest.
#[inline]
fn find3(hay: &[u8], a: u8, b: u8, c: u8) -> Option<usize> {
    let mut i = 0;
    while let Some(eight) = hay[i..].first_chunk::<8>().filter(|_| i < 32) {
        let word = u64::from_le_bytes(*eight);
        let found = first_equal(word, a) | first_equal(word, b) | first_equal(word, c);
        if found != 0 {
            return Some(i + (found.trailing_zeros() / 8) as usize);
        }
        i += 8;
    }
    memchr::memchr3(a, b, c, &hay[i..]).map(|found| i + found)
}

/// A mask whose lowest set bit is the high bit of the first byte (the lowest, read little
/// endian) of `word` that is `b`; 0 when no byte is. Bits above that one may be set too.
///
/// With `x = word ^ [b; 8]`, the bytes equal to `b` are the zero bytes of `x`, and
/// `(x - 0x01..01) & !x & 0x80..80` flags the lowest of them exactly. Going up from the
/// lowest byte, as long as no borrow comes in: a byte `x_i` that is not zero borrows
/// nothing from the next, and `x_i - 1` has its high bit set only when `x_i` is 0x81 or
/// more, when `!x_i` has not, so it is not flagged; the first zero byte becomes 0xFF, high
/// bit set, with `!x_i` high bit set: flagged. Only past it can a borrow flag a byte that is
/// not zero (0x01 becomes 0xFF). So OR-ing the masks of several bytes keeps the first byte
/// equal to any of them as the lowest set bit, which is all [`find3`] looks at; the exact
/// test ([`text::bytes_equal`]) takes more instructions for every byte.
#[inline(always)]
fn first_equal(word: u64, b: u8) -> u64 {
    const ONES: u64 = u64::from_le_bytes([0x01; 8]);
    const HIGH: u64 = u64::from_le_bytes([0x80; 8]);
    let x = word ^ u64::from_le_bytes([b; 8]);
    x.wrapping_sub(ONES) & !x & HIGH
}

/// Text with references or carriage returns, written from `at` on: references resolved
/// (only the five predefined entities and character references exist), line ends
/// normalised to `\n`.
fn resolve_text(raw: &str, at: usize) -> Parsed<Resolved> {
    let mut out = Resolved { text: String::with_capacity(raw.len()), written: Vec::new() };
    let (mut rest, mut offset) = (raw, at);
    while let Some(amp) = memchr::memchr(b'&', rest.as_bytes()) {
        push_normalised(&mut out, &rest[..amp], offset);
        let after = &rest[amp + 1..];
        let name = match memchr::memchr2(b';', b'&', after.as_bytes()) {
            Some(semi) if after.as_bytes()[semi] == b';' => &after[..semi],
            _ => return Err(malformed(offset + amp, IllFormedError::UnclosedReference)),
        };
        match name.starts_with('#') {
            true => out.text.push(char_reference(name, offset + amp)?),
            false => match quick_xml::escape::resolve_predefined_entity(name) {
                Some(resolved) => out.text.push_str(resolved),
                None => return Err(unknown_entity(name, offset + amp)),
            },
        }
        let used = amp + 1 + name.len() + 1;
        rest = &rest[used..];
        offset += used;
        out.written.push((out.text.len(), offset));
    }
    push_normalised(&mut out, rest, offset);
    Ok(out)
}

/// Appends `text`, written from `at` on, with `\r\n` and lone `\r` made `\n` (XML 1.0
/// section 2.11).
fn push_normalised(out: &mut Resolved, text: &str, at: usize) {
    let mut pieces = text.split('\r');
    let first = pieces.next().unwrap_or_default();
    out.text.push_str(first);
    let mut offset = at + first.len();
    for piece in pieces {
        out.text.push('\n');
        offset += 1;
        if let Some(line) = piece.strip_prefix('\n') {
            offset += 1;
            out.written.push((out.text.len(), offset));
            out.text.push_str(line);
            offset += line.len();
        } else {
            out.text.push_str(piece);
            offset += piece.len();
        }
    }
}

/// The character that the reference `&{name};` at `at` names (`name` begins with `#`):
/// one of those XML allows, as a reference may not name any other (XML 1.0, section 4.1).
fn char_reference(name: &str, at: usize) -> Parsed<char> {
    use quick_xml::escape::{EscapeError::InvalidCharRef, ParseCharRefError as Number};
    let bad =
        |why: String| problem(Code::MalformedXml, at, format!("malformed XML: &{name}; {why}"));
    let code = match BytesRef::new(name).resolve_char_ref() {
        Ok(Some(c)) => u32::from(c),
        Err(quick_xml::Error::Escape(InvalidCharRef(
            Number::InvalidCodepoint(code) | Number::IllegalCharacter(code),
        ))) => code,
        _ => return Err(bad("is not a character reference (&#DIGITS; or &#xHEX;)".into())),
    };
    let allowed = |c: &char| first_non_char(c.encode_utf8(&mut [0; 4]).as_bytes()).is_none();
    char::from_u32(code)
        .filter(allowed)
        .ok_or_else(|| bad(format!("names the character U+{code:04X}, which XML does not allow")))
}

#[cold]
fn unknown_entity(name: &str, at: usize) -> Problem {
    problem(
        Code::MalformedXml,
        at,
        format!(
            "malformed XML: unknown entity &{name}; (only &amp; &lt; &gt; &quot; &apos; and character references are allowed)"
        ),
    )
}

#[cfg(test)]
mod tests;
