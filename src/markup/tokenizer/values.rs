//! Values and attributes: an element's text joined, trimmed and converted, a tag's
//! attributes read (the usual ones here, the rest by quick-xml), elements skipped.

use std::borrow::Cow;
use std::collections::HashSet;
use std::hash::{Hash, Hasher};

use quick_xml::errors::IllFormedError;
use quick_xml::events::attributes::AttrError;
use quick_xml::events::{BytesDecl, BytesRef, BytesStart};

use super::super::shorten;
use super::{Attr, Attrs, Node, Resolved, Tag, Text, Tokenizer, Value, malformed};
use crate::bytes::{
    ENDS_NAME, ENDS_PLAIN_VALUE, first_lt, first_non_char, plain_name_len, plain_trimmed, space_len,
};
use crate::error::{Code, Finding, Parsed, Problem, problem};
use crate::input::Encoding;
use crate::text::{trim_xml, trim_xml_at};

impl<'a> Tokenizer<'a> {
    /// The text of `t`, valid until the next node is read.
    pub fn text_of<'t>(&'t self, t: &'t Text) -> &'t str {
        t.read(&self.window)
    }

    pub fn is_blank(&self, t: &Text) -> bool {
        trim_xml(self.text_of(t)).is_empty()
    }

    pub(super) fn check_declared_encoding(&self, decl: &BytesDecl, at: usize) -> Parsed<()> {
        let Some(Ok(declared)) = decl.encoding() else {
            return Ok(());
        };
        let declared = declared.to_ascii_lowercase();
        let fits = match self.window.encoding() {
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
        if let Some(tag) = self.short_tag(self.lex.pos) {
            self.lex.begin_node(tag.at);
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
    pub(super) fn other_child(&mut self, parent: &Tag) -> Parsed<Option<Tag>> {
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
                Node::Eof if self.at_piece_end() => return Ok(None),
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
            whole.push(self.window.slice(first.at, first.end), first.at);
            whole
        });
        match &second.resolved {
            Some(resolved) => joined.append(resolved, second.at),
            None => joined.push(self.window.slice(second.at, second.end), second.at),
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
        if tag.empty || self.kept.pinned() {
            return None;
        }
        let at = self.lex.pos;
        let rest = self.rest(at);
        // The value ends at the next markup, as the scan would mark it.
        let len = first_lt(rest)?;
        if len as u64 > self.options.max_text_bytes {
            return None;
        }
        let (start, end) = plain_trimmed(rest, len)?;
        let end_tag = self.usual_end_tag_len(&rest[len..])?;
        self.lex.pos = at + len + end_tag;
        self.lex.open.pop();
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
            return Ok(match convert(self.window.slice(at, end)) {
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
        let at = e.at.map_offset(|at| value.text.written_at(at));
        Box::new(Finding::at(e.code, at, format!("<{}>: {}", tag.name(), e.message)))
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
            Ok(v) => Ok((v, self.written_at(tag, attr, lead))),
            Err(e) => Err(Box::new(Finding::at(
                e.code,
                e.at.map_offset(|at| self.written_at(tag, attr, lead + at)),
                format!("<{} {}>: {}", tag.name(), attr.key, e.message),
            ))),
        }
    }

    /// An attribute of `tag` as written (` key="value"`, its value's references unresolved).
    pub fn verbatim(&self, tag: &Tag, attr: &Attr) -> String {
        let (quote, value) = self.written_value(tag, attr);
        format!(" {}={quote}{value}{quote}", attr.key)
    }

    /// The quote around the value of an attribute of `tag`, and the value as written.
    fn written_value(&self, tag: &Tag, attr: &Attr) -> (char, &str) {
        let content = self.content(tag).unwrap_or_default();
        let value = (attr.at - tag.at - 1).min(content.len());
        let quote = content[..value].chars().next_back().unwrap_or('"');
        let len = content[value..].find(quote).unwrap_or(content.len() - value);
        (quote, &content[value..value + len])
    }

    /// Where the character at `offset` of an attribute's value is written. A value unlike
    /// what is written (references resolved, white space normalised) is resolved again to
    /// tell, as only a message needs it: its bytes line up with the resolved text's.
    fn written_at(&self, tag: &Tag, attr: &Attr, offset: usize) -> usize {
        if let Cow::Borrowed(_) = attr.value {
            return attr.at + offset;
        }
        match resolve_text(self.written_value(tag, attr).1, attr.at) {
            Ok(resolved) => resolved.written_at(attr.at, offset),
            Err(_) => attr.at + offset,
        }
    }

    /// What lies between the `<` and `>` of `tag` when it has more than its name, where it
    /// is written: read right after the tag, while the text at hand holds it.
    fn content(&self, tag: &Tag) -> Option<&str> {
        let (from, to) = tag.content()?;
        Some(self.window.slice(from, to))
    }

    /// The attributes of `tag`, unescaped, each with the offset of its value, read where
    /// they are written: the usual one or two allocate nothing.
    pub fn attributes(&self, tag: &Tag) -> Parsed<Attrs<'_>> {
        let Some(content) = self.content(tag) else {
            return Ok(Attrs::default());
        };
        let attrs = match plain_attributes(content, tag.name.len(), tag.at) {
            Some(attrs) => return Ok(attrs),
            None => self.xml_attributes(tag, content)?,
        };
        // Names compare as the loader reads them, ignoring case: `Type` and `type` are one
        // attribute, given twice.
        let Some(i) = first_repeated(&attrs) else {
            return Ok(attrs);
        };
        let key = attrs[i].key;
        let offset = key.as_ptr().addr().saturating_sub(content.as_ptr().addr());
        Err(problem(
            Code::DuplicateAttribute,
            tag.at + 1 + offset,
            format!("<{}> has the attribute {key} twice (names ignore case)", tag.name()),
        ))
    }

    /// Checks that the attributes of `tag`, which is kept as written rather than read
    /// (inside UserData or an ignored element), are well-formed: the writer writes them
    /// back. Names differing in case are distinct there, as in any XML.
    pub fn check_attributes(&self, tag: &Tag) -> Parsed<()> {
        let Some(content) = self.content(tag) else {
            return Ok(());
        };
        if plain_attributes(content, tag.name.len(), tag.at).is_none() {
            self.xml_attributes(tag, content)?;
        }
        Ok(())
    }

    /// The attributes of `tag`, whose `content` is not as plain as most, read by quick-xml.
    pub(super) fn xml_attributes<'t>(&self, tag: &Tag, content: &'t str) -> Parsed<Attrs<'t>> {
        // quick-xml's attributes borrow its BytesStart; the same text, borrowed from the
        // text at hand, is found by its offset in `content` (which counts from after `<`).
        let within = |piece: &str| {
            let from = piece.as_ptr().addr().checked_sub(content.as_ptr().addr())?;
            Some((from, content.get(from..from + piece.len())?))
        };
        let start = BytesStart::from_content(content, tag.name.len());
        let mut attrs = Attrs::default();
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
}

/// The attributes of the usual tag, whose `content` (what follows its `<`) has its name
/// of `name_len` bytes and then `name="value"` pairs (or single quotes) after white space,
/// with plain names, values with no reference, `<`, line break or other quote, and no
/// name twice (in any case, found by [`first_repeated`]). None for anything else:
/// quick-xml reads that, and tells what is malformed.
pub(super) fn plain_attributes(content: &str, name_len: usize, at: usize) -> Option<Attrs<'_>> {
    let bytes = content.as_bytes();
    let mut attrs = Attrs::default();
    let mut i = name_len;
    loop {
        // The tag's text is the source's, so white space is every byte up to 0x20.
        let space = space_len(&bytes[i..]);
        i += space;
        if i == bytes.len() {
            return first_repeated(&attrs).is_none().then_some(attrs);
        }
        let (key_len, start, len) = plain_pair(bytes, i).filter(|_| space > 0)?;
        let key = &content[i..i + key_len];
        let value = Cow::Borrowed(&content[start..start + len]);
        attrs.push(Attr { key, value, at: at + 1 + start });
        i = start + len + 1;
    }
}

/// The plain `name="value"` (or single quotes) at `i` of a tag's `bytes` (see
/// [`plain_attributes`]): the length of its name, and where its value starts and how long
/// it is (its closing quote just after). None for anything else.
#[inline(always)]
fn plain_pair(bytes: &[u8], i: usize) -> Option<(usize, usize, usize)> {
    let key_len = plain_name_len(&bytes[i..]);
    let [b'=', quote @ (b'"' | b'\''), value @ ..] = &bytes[i + key_len..] else {
        return None;
    };
    // The other quote ends it too: quick-xml reads a value that holds one.
    let len = value.iter().position(|&b| ENDS_PLAIN_VALUE[usize::from(b)])?;
    (key_len > 0 && value[len] == *quote).then_some((key_len, i + key_len + 2, len))
}

/// Where the start tag at the start of `text` ends, the offset of its `>`, when its
/// attributes are plain (see [`plain_attributes`]): its name holds no quote, and each
/// value is quoted as the scan stage sees it, so this `>` is the first outside quoted
/// values, the one the scan would mark. None for any other tag, or when the text at hand
/// ends first.
#[inline]
pub(super) fn plain_tag_end(text: &[u8]) -> Option<usize> {
    let mut i = 1 + text.get(1..)?.iter().position(|&b| ENDS_NAME[usize::from(b)])?;
    loop {
        let space = space_len(&text[i..]);
        i += space;
        match text[i..] {
            [b'>', ..] => return Some(i),
            [b'/', b'>', ..] => return Some(i + 1),
            _ if space == 0 => return None,
            _ => {}
        }
        let (_, start, len) = plain_pair(text, i)?;
        i = start + len + 1;
    }
}

/// Tags have an attribute or two; past this many, names are compared through a hash set.
const FEW_ATTRIBUTES: usize = 8;

/// The index of the first of `attrs` whose name one before it has, in any case. Linear in
/// the attributes however many a tag has: a file may give one tag thousands.
fn first_repeated(attrs: &[Attr]) -> Option<usize> {
    if attrs.len() <= FEW_ATTRIBUTES {
        return (1..attrs.len()).find(|&i| attrs[..i].iter().any(|a| a.is(attrs[i].key)));
    }
    let mut seen = HashSet::with_capacity(attrs.len());
    attrs.iter().position(|attr| !seen.insert(Caseless(attr.key)))
}

/// A name that hashes and compares ignoring ASCII case, as names are read.
struct Caseless<'k>(&'k str);

impl PartialEq for Caseless<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.0.eq_ignore_ascii_case(other.0)
    }
}

impl Eq for Caseless<'_> {}

impl Hash for Caseless<'_> {
    fn hash<H: Hasher>(&self, state: &mut H) {
        for b in self.0.bytes() {
            state.write_u8(b.to_ascii_lowercase());
        }
        state.write_usize(self.0.len());
    }
}

/// Text with references or carriage returns, written from `at` on: references resolved
/// (only the five predefined entities and character references exist), line ends
/// normalised to `\n`.
pub(super) fn resolve_text(raw: &str, at: usize) -> Parsed<Resolved> {
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
