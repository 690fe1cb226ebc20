//! The quick-xml event loop: a thin pull parser over the decoded text that enforces the
//! limits and hands whole elements, values and attributes to one handler per object kind
//! (`world`, `shape`, `fixture`, `body`, `joint`, `user_data`).
#![forbid(unsafe_code)]

mod body;
mod fixture;
mod joint;
mod shape;
mod user_data;
mod world;

pub(crate) use joint::canonical_joint;
pub(crate) use user_data::user_data_fragment;

use std::borrow::Cow;

use quick_xml::Reader;
use quick_xml::events::attributes::AttrError;
use quick_xml::events::{BytesStart, Event};

use crate::error::{Code, Diagnostic, Error, MAX_WARNINGS, Severity};
use crate::input::{self, Decoded, Encoding, Locator};
use crate::scene::{Scene, SceneBuilder, Vec2};
use crate::text::{self, BadValue, trim_xml};
use crate::{LoadOptions, resolve, validate};

/// Loads a scene: decode, parse into the arena, check cross references, freeze.
pub fn load(bytes: &[u8], options: &LoadOptions) -> Result<Scene, Error> {
    let decoded = input::decode(bytes, options)?;
    let mut parser = Parser::new(&decoded, options);
    let outcome = parser
        .document()
        .and_then(|()| resolve::resolve(&mut parser))
        .and_then(|()| validate::dynamic_bodies_without_mass(&mut parser));
    let mut locator = Locator::new(&decoded);
    if let Err(problem) = outcome {
        return Err(Error {
            code: problem.code,
            position: locator.locate(problem.at),
            message: problem.message,
        });
    }
    let Parser { mut scene, mut warnings, dropped_warnings: (dropped, first_dropped), .. } = parser;
    warnings.sort_by_key(|w| w.at);
    if dropped > 0 {
        let message = format!(
            "{dropped} more warnings from here on were not kept (a scene keeps {MAX_WARNINGS})"
        );
        warnings.push(problem(Code::WarningsTruncated, first_dropped, message));
    }
    for w in warnings {
        let position = locator.locate(w.at);
        let message = scene.add_str(&w.message);
        scene.diagnostics.push(Diagnostic {
            message,
            byte_offset: position.byte_offset,
            code: w.code as u32,
            severity: Severity::Warning as u32,
            line: position.line,
            column: position.column,
        });
    }
    Ok(scene.freeze())
}

/// An error or warning found while parsing, at a byte offset of the decoded text.
#[derive(Debug)]
pub struct Problem {
    pub code: Code,
    pub at: usize,
    pub message: String,
}

pub type Parsed<T> = Result<T, Problem>;

pub fn problem(code: Code, at: usize, message: impl Into<String>) -> Problem {
    Problem { code, at, message: message.into() }
}

/// A start tag (`<Name ...>` or `<Name .../>`) and where it begins.
pub(crate) struct Tag<'a> {
    start: BytesStart<'a>,
    /// Offset of its `<`.
    pub at: usize,
    /// `<Name/>`: it has no children and no text.
    pub empty: bool,
}

impl Tag<'_> {
    pub fn name(&self) -> &str {
        self.start.name().into_inner()
    }

    /// Names compare case-insensitively (spec section 2).
    pub fn is(&self, name: &str) -> bool {
        self.name().eq_ignore_ascii_case(name)
    }
}

/// The trimmed text of a value element and the offset of its first character.
pub(crate) struct Value<'a> {
    pub text: Cow<'a, str>,
    pub at: usize,
}

/// An attribute: lowercase comparisons go through [`Attr::is`].
pub(crate) struct Attr<'t> {
    key: &'t str,
    pub value: Cow<'t, str>,
    pub at: usize,
}

impl Attr<'_> {
    pub fn is(&self, lowercase_name: &str) -> bool {
        self.key.eq_ignore_ascii_case(lowercase_name)
    }
}

enum Node<'a> {
    Open(Tag<'a>),
    Text(Cow<'a, str>, usize),
    /// An end tag, at the offset of its `<`.
    Close(usize),
    Eof,
}

/// Which of an object's known elements were already read (for `duplicate-element`).
#[derive(Default)]
pub(crate) struct Seen(u64);

impl Seen {
    /// Whether the element `name` (any case) of the list `names` was read.
    pub fn contains(&self, names: &[&str], name: &str) -> bool {
        let index = names.iter().position(|n| n.eq_ignore_ascii_case(name));
        index.is_some_and(|i| self.0 & (1 << i) != 0)
    }
}

/// The offsets the cross-reference checks need after the whole file is read.
#[derive(Default)]
pub(crate) struct Origins {
    /// Per fixture: its `Shape` value.
    pub fixture_shapes: Vec<usize>,
    /// Per body: its tag.
    pub bodies: Vec<usize>,
    /// Per entry of the fixture ID pool: its `ID` value.
    pub fixture_ids: Vec<usize>,
    pub joints: Vec<JointOrigin>,
    /// Version 3 (Farseer): per shape, its `Density` attribute (0 when absent).
    pub shape_densities: Vec<f32>,
    /// Version 3: per fixture template, its `Id` attribute and where that is.
    pub fixture_template_ids: Vec<(u32, usize)>,
    /// Version 3: every body's `Bindings`, in body order.
    pub pairs: Vec<Pair>,
}

/// A Version 3 `<Pair FixtureId="k" ShapeId="s"/>`: one fixture of a body.
pub(crate) struct Pair {
    pub body: u32,
    pub fixture_id: (u32, usize),
    pub shape: (u32, usize),
}

/// Where a joint's references are.
#[derive(Clone, Copy)]
pub(crate) struct JointOrigin {
    pub body_a: usize,
    pub body_b: usize,
    pub joint_a: usize,
    pub joint_b: usize,
}

pub struct Parser<'a> {
    reader: Reader<&'a [u8]>,
    text: &'a str,
    encoding: Encoding,
    options: &'a LoadOptions,
    depth: u32,
    elements: u64,
    /// The file's Version; 0 for an unversioned legacy file.
    pub version: u32,
    pub scene: SceneBuilder,
    pub origins: Origins,
    warnings: Vec<Problem>,
    /// Warnings past [`MAX_WARNINGS`]: how many, and where the first was.
    dropped_warnings: (u64, usize),
}

impl<'a> Parser<'a> {
    fn new(decoded: &'a Decoded<'a>, options: &'a LoadOptions) -> Parser<'a> {
        let text: &'a str = &decoded.text;
        let mut reader = Reader::from_str(text);
        let config = reader.config_mut();
        config.check_end_names = true;
        config.trim_text(false);
        Parser {
            reader,
            text,
            encoding: decoded.encoding,
            options,
            depth: 0,
            elements: 0,
            version: 0,
            scene: SceneBuilder::default(),
            origins: Origins::default(),
            warnings: Vec::new(),
            dropped_warnings: (0, 0),
        }
    }

    pub fn options(&self) -> &LoadOptions {
        self.options
    }

    /// Records a warning; in strict mode it is the load's error instead.
    pub fn warn(&mut self, code: Code, at: usize, message: impl Into<String>) -> Parsed<()> {
        let w = problem(code, at, message);
        if self.options.strict {
            return Err(Problem { message: format!("{} (strict mode)", w.message), ..w });
        }
        if self.warnings.len() < MAX_WARNINGS {
            self.warnings.push(w);
        } else {
            let (count, first) = &mut self.dropped_warnings;
            if *count == 0 {
                *first = w.at;
            }
            *count += 1;
        }
        Ok(())
    }

    /// Whether the file uses Farseer's Version 3 layout (spec section 8.2).
    pub fn farseer_layout(&self) -> bool {
        self.version >= 3
    }

    /// Warns that `what` needs Version 2 when the file says less.
    pub fn newer_construct(&mut self, at: usize, what: &str) -> Parsed<()> {
        if self.version >= 2 {
            return Ok(());
        }
        let said = match self.version {
            0 => "has no Version (legacy)".to_string(),
            v => format!("says Version {v}"),
        };
        self.warn(
            Code::ConstructNewerThanVersion,
            at,
            format!("{what} is a Version 2 construct, but the file {said}"),
        )
    }

    fn next_node(&mut self) -> Parsed<Node<'a>> {
        loop {
            let at = self.reader.buffer_position() as usize;
            let event = self.reader.read_event().map_err(|e| self.xml_error(e))?;
            return Ok(match event {
                Event::Start(start) => {
                    self.depth += 1;
                    if self.depth > self.options.max_depth {
                        return Err(self.limit(at, "max_depth", self.options.max_depth.into()));
                    }
                    self.open(start, at, false)?
                }
                Event::Empty(start) => self.open(start, at, true)?,
                Event::End(_) => {
                    self.depth -= 1;
                    Node::Close(at)
                }
                Event::Text(t) => self.text_node(t.xml10_content(), at)?,
                Event::CData(c) => self.text_node(c.into_inner(), at + "<![CDATA[".len())?,
                Event::GeneralRef(r) => {
                    let resolved = match r.resolve_char_ref() {
                        Ok(Some(c)) => c.to_string(),
                        _ => quick_xml::escape::resolve_predefined_entity(&r)
                            .ok_or_else(|| unknown_entity(&r, at))?
                            .to_string(),
                    };
                    Node::Text(Cow::Owned(resolved), at)
                }
                Event::Decl(decl) => {
                    self.check_declared_encoding(&decl, at)?;
                    continue;
                }
                Event::DocType(_) => {
                    return Err(problem(
                        Code::DoctypeForbidden,
                        at,
                        "a <!DOCTYPE> is not allowed in a scene file: box2scene never expands \
                         entities or fetches DTDs",
                    ));
                }
                Event::Comment(_) | Event::PI(_) => continue,
                Event::Eof => Node::Eof,
            });
        }
    }

    fn open(&mut self, start: BytesStart<'a>, at: usize, empty: bool) -> Parsed<Node<'a>> {
        self.elements += 1;
        if self.elements > self.options.max_elements {
            return Err(self.limit(at, "max_elements", self.options.max_elements));
        }
        if start.name().as_ref().len() as u64 > self.options.max_text_bytes {
            return Err(self.limit(at, "max_text_bytes", self.options.max_text_bytes));
        }
        Ok(Node::Open(Tag { start, at, empty }))
    }

    fn text_node(&self, text: Cow<'a, str>, at: usize) -> Parsed<Node<'a>> {
        if text.len() as u64 > self.options.max_text_bytes {
            return Err(self.limit(at, "max_text_bytes", self.options.max_text_bytes));
        }
        Ok(Node::Text(text, at))
    }

    pub fn limit(&self, at: usize, name: &str, value: u64) -> Problem {
        problem(
            Code::LimitExceeded,
            at,
            format!(
                "the file exceeds a load limit here ({name} = {value}); raise it in the load options if the file is trusted"
            ),
        )
    }

    fn xml_error(&self, e: quick_xml::Error) -> Problem {
        let at = self.reader.error_position() as usize;
        match e {
            quick_xml::Error::InvalidAttr(AttrError::Duplicated(..)) => {
                problem(Code::DuplicateAttribute, at, format!("malformed XML: {e}"))
            }
            e => problem(Code::MalformedXml, at, format!("malformed XML: {e}")),
        }
    }

    fn check_declared_encoding(
        &self,
        decl: &quick_xml::events::BytesDecl,
        at: usize,
    ) -> Parsed<()> {
        let Some(Ok(declared)) = decl.encoding() else {
            return Ok(());
        };
        let declared = declared.to_ascii_lowercase();
        let fits = match self.encoding {
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

    /// The next child element of `parent`, or None at its end. Blank text and comments are
    /// skipped; other text is an error.
    pub fn child(&mut self, parent: &Tag) -> Parsed<Option<Tag<'a>>> {
        if parent.empty {
            return Ok(None);
        }
        loop {
            match self.next_node()? {
                Node::Open(tag) => return Ok(Some(tag)),
                Node::Close(_) => return Ok(None),
                Node::Text(t, at) => {
                    let text = trim_xml(&t);
                    if !text.is_empty() {
                        let lead = t.len() - t.trim_start_matches(text::is_xml_space).len();
                        return Err(problem(
                            Code::UnexpectedText,
                            at + lead,
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
    pub fn value(&mut self, tag: &Tag) -> Parsed<Value<'a>> {
        let mut value: Option<(Cow<'a, str>, usize)> = None;
        if !tag.empty {
            loop {
                match self.next_node()? {
                    Node::Text(t, at) => match &mut value {
                        None => value = Some((t, at)),
                        Some((text, _)) => {
                            text.to_mut().push_str(&t);
                            if text.len() as u64 > self.options.max_text_bytes {
                                return Err(self.limit(
                                    at,
                                    "max_text_bytes",
                                    self.options.max_text_bytes,
                                ));
                            }
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
        let Some((text, at)) = value else {
            return Ok(Value { text: Cow::Borrowed(""), at: tag.at });
        };
        let lead = text.len() - text.trim_start_matches(text::is_xml_space).len();
        let text = match text {
            Cow::Borrowed(t) => Cow::Borrowed(trim_xml(t)),
            Cow::Owned(t) => Cow::Owned(trim_xml(&t).to_owned()),
        };
        Ok(Value { text, at: at + lead })
    }

    /// Reads a value element and converts its text with `convert`.
    pub fn parsed<T>(
        &mut self,
        tag: &Tag,
        convert: fn(&str) -> Result<T, BadValue>,
    ) -> Parsed<(T, usize)> {
        let value = self.value(tag)?;
        match convert(&value.text) {
            Ok(v) => Ok((v, value.at)),
            Err(e) => {
                Err(problem(e.code, value.at + e.at, format!("<{}>: {}", tag.name(), e.message)))
            }
        }
    }

    pub fn float(&mut self, tag: &Tag) -> Parsed<f32> {
        Ok(self.parsed(tag, text::float)?.0)
    }

    /// A float that must not be negative (error `negative-value`).
    pub fn non_negative(&mut self, tag: &Tag) -> Parsed<f32> {
        let (v, at) = self.parsed(tag, text::float)?;
        not_negative(&format!("<{}>", tag.name()), v, at)
    }

    pub fn vector(&mut self, tag: &Tag) -> Parsed<Vec2> {
        Ok(self.parsed(tag, text::vector2)?.0)
    }

    pub fn boolean(&mut self, tag: &Tag) -> Parsed<bool> {
        Ok(self.parsed(tag, text::boolean)?.0)
    }

    /// An ID value and its offset.
    pub fn id(&mut self, tag: &Tag) -> Parsed<(u32, usize)> {
        self.parsed(tag, text::id)
    }

    /// Converts an attribute's value with `convert`; errors point into the value.
    pub fn attribute<T>(
        &self,
        tag: &Tag,
        attr: &Attr,
        convert: fn(&str) -> Result<T, BadValue>,
    ) -> Parsed<(T, usize)> {
        let value = trim_xml(&attr.value);
        let lead = attr.value.len() - attr.value.trim_start_matches(text::is_xml_space).len();
        convert(value).map(|v| (v, attr.at + lead)).map_err(|e| {
            problem(
                e.code,
                attr.at + lead + e.at,
                format!("<{} {}>: {}", tag.name(), attr.key, e.message),
            )
        })
    }

    /// A string value, stored in the scene's string pool.
    pub fn string(&mut self, tag: &Tag) -> Parsed<crate::scene::Str> {
        let value = self.value(tag)?;
        Ok(self.scene.add_str(&value.text))
    }

    /// The attributes of `tag`, unescaped, each with the offset of its value.
    pub fn attributes<'t>(&self, tag: &'t Tag<'a>) -> Parsed<Vec<Attr<'t>>> {
        let mut attrs = Vec::new();
        for attr in tag.start.attributes() {
            let attr = attr.map_err(|e| self.attr_error(tag, e))?;
            let at = self.offset_of(&attr.value).unwrap_or(tag.at);
            let value = attr
                .normalized_value(quick_xml::XmlVersion::Implicit1_0)
                .map_err(|e| problem(Code::MalformedXml, at, format!("malformed XML: {e}")))?;
            let key = attr.key.into_inner();
            attrs.push(Attr { key, value: Cow::Owned(value.into_owned()), at });
        }
        Ok(attrs)
    }

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

    /// Where a slice of the input starts, when it is one.
    fn offset_of(&self, s: &str) -> Option<usize> {
        let offset = s.as_ptr().addr().checked_sub(self.text.as_ptr().addr())?;
        (offset <= self.text.len()).then_some(offset)
    }

    /// Warns about every attribute of `tag` except the lowercase names in `known`.
    pub fn unknown_attributes(
        &mut self,
        tag: &Tag<'a>,
        attrs: &[Attr],
        known: &[&str],
    ) -> Parsed<()> {
        for attr in attrs.iter().filter(|a| !known.iter().any(|k| a.is(k))) {
            let message = format!("unknown attribute {} on <{}> ignored", attr.key, tag.name());
            self.warn(Code::UnknownElement, attr.at, message)?;
        }
        Ok(())
    }

    /// Skips `tag` and everything inside it.
    pub fn skip(&mut self, tag: &Tag) -> Parsed<()> {
        if tag.empty {
            return Ok(());
        }
        let mut depth = 1;
        while depth > 0 {
            match self.next_node()? {
                Node::Open(t) if !t.empty => depth += 1,
                Node::Open(_) | Node::Text(..) => {}
                Node::Close(_) => depth -= 1,
                Node::Eof => return Err(self.unclosed(tag)),
            }
        }
        Ok(())
    }

    /// Warns that `child` is not part of `parent` and skips it.
    pub fn unknown(&mut self, parent: &Tag, child: &Tag) -> Parsed<()> {
        let message = format!("unknown element <{}> in <{}> ignored", child.name(), parent.name());
        self.warn(Code::UnknownElement, child.at, message)?;
        self.skip(child)
    }

    /// Looks `child` up among an object's known elements (lowercase). Returns its canonical
    /// name and whether the object already had it; None (after a warning and a skip) when
    /// it is not one of them.
    pub fn known(
        &mut self,
        parent: &Tag,
        child: &Tag,
        names: &[&'static str],
        seen: &mut Seen,
    ) -> Parsed<Option<(&'static str, bool)>> {
        let Some(index) = names.iter().position(|n| child.is(n)) else {
            self.unknown(parent, child)?;
            return Ok(None);
        };
        let bit = 1u64 << index;
        let repeated = seen.0 & bit != 0;
        seen.0 |= bit;
        Ok(Some((names[index], repeated)))
    }

    /// Warns that a scalar element was repeated (the last one wins).
    pub fn duplicate(&mut self, parent: &Tag, child: &Tag) -> Parsed<()> {
        let message =
            format!("<{}> appears twice in <{}>; the last one wins", child.name(), parent.name());
        self.warn(Code::DuplicateElement, child.at, message)
    }

    /// The error for a repeated container.
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

    /// Reads every child of a container, each of which must be an `item` element (any
    /// letter case).
    pub fn items(
        &mut self,
        container: &Tag,
        item: &str,
        mut each: impl FnMut(&mut Self, Tag<'a>) -> Parsed<()>,
    ) -> Parsed<()> {
        while let Some(child) = self.child(container)? {
            if !child.is(item) {
                return Err(problem(
                    Code::UnexpectedElement,
                    child.at,
                    format!(
                        "<{}> holds <{item}> elements, not <{}>",
                        container.name(),
                        child.name()
                    ),
                ));
            }
            each(self, child)?;
        }
        Ok(())
    }

    pub fn missing(&self, tag: &Tag, what: &str) -> Problem {
        problem(Code::MissingElement, tag.at, format!("<{}> has no {what}", tag.name()))
    }

    fn unclosed(&self, tag: &Tag) -> Problem {
        problem(
            Code::MalformedXml,
            self.text.len(),
            format!(
                "malformed XML: the file ends before </{}> (opened at byte {})",
                tag.name(),
                tag.at
            ),
        )
    }

    /// The offset the reader has reached: just past the last event read.
    pub fn position(&self) -> usize {
        self.reader.buffer_position() as usize
    }

    /// The decoded text between two offsets (UserData keeps its inner XML verbatim).
    pub fn slice(&self, from: usize, to: usize) -> &'a str {
        self.text.get(from..to).unwrap_or_default()
    }
}

fn unknown_entity(r: &quick_xml::events::BytesRef, at: usize) -> Problem {
    let name: &str = r;
    problem(
        Code::MalformedXml,
        at,
        format!(
            "malformed XML: unknown entity &{name}; (only &amp; &lt; &gt; &quot; &apos; and character references are allowed)"
        ),
    )
}

/// `value`, unless it is negative (error `negative-value` naming `what`).
pub(crate) fn not_negative(what: &str, value: f32, at: usize) -> Parsed<f32> {
    if value < 0.0 {
        return Err(problem(
            Code::NegativeValue,
            at,
            format!("{what} is {value}, but it cannot be negative"),
        ));
    }
    Ok(value)
}

/// At most 40 characters of `text`, for messages.
pub(crate) fn shorten(text: &str) -> Cow<'_, str> {
    match text.char_indices().nth(40) {
        Some((cut, _)) => Cow::Owned(format!("{}...", &text[..cut])),
        None => Cow::Borrowed(text),
    }
}
