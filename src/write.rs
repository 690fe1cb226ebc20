//! Scene -> Box2Scene XML (spec section 11), in box2scene's own dialect here and in those of
//! the engines' readers in [`farseer`]. What it writes reads back to the identical scene:
//! every float bit for bit, every name, every UserData text.
#![forbid(unsafe_code)]

mod farseer;

use std::fmt::Write as _;

use crate::containers::Container;
use crate::error::{Code, Error, Finding, Parsed, Position, Problem, problem};
use crate::input::first_non_char;
use crate::options::{LoadOptions, WriteOptions};
use crate::parse::{USER_DATA_DEPTH, user_data_fragment};
use crate::scene::Object;
use crate::scene::{Body, BodyKind, Dialect, Filter, Fixture, Joint, JointKind, Kept, NONE};
use crate::scene::{Place as KeptAt, Scene, Shape, ShapeKind, Str, Vec2};

/// Writes `scene` as a Box2Scene file, with no XML declaration (no reader of the format
/// wants one), in the dialect `options` names or else the one the scene remembers. In
/// box2scene's own: `Version="1"` when it uses only Version 1 constructs, else
/// `Version="2"`. In an engine's (spec section 11): every field, laid out as that engine's
/// reader needs; what it cannot hold is error `dialect-cannot-hold` naming the object. A loaded scene is written with everything its file
/// held beyond the records: comments, unknown elements and attributes, and Farseer-only
/// joints as they were written, in their places (spec section 11). A joint of the
/// unsupported kind with no text of its own (one a host built) has no form to write:
/// error `unsupported-joint-type` naming it; nor has an object given two unknown
/// attributes of one name from different places of its file: `duplicate-attribute`.
pub fn write(scene: &Scene, options: &WriteOptions) -> Result<String, Error> {
    let bytes = write_utf8(scene, options)?;
    Ok(String::from_utf8(bytes).expect("the text is written from str pieces"))
}

/// [`write`](fn@write)'s text, as the bytes it is made of (for the C text and files, which need
/// no `String`).
pub(crate) fn write_utf8(scene: &Scene, options: &WriteOptions) -> Result<Vec<u8>, Error> {
    unwritable_joint(scene)?;
    clashing_attributes(scene)?;
    unwritable_texts(scene)?;
    unreadable_kept_text(scene)?;
    let dialect = match options.dialect {
        0 => remembered_dialect(scene),
        n => Dialect::try_from(n).map_err(|n| Error {
            code: Code::InvalidArgument,
            position: Position::default(),
            message: format!("{n} names no dialect (1 to {})", Dialect::ALL.len()),
        })?,
    };
    if dialect != Dialect::Box2scene {
        return farseer::write(scene, dialect).map(String::into_bytes);
    }
    let size = estimated_size(scene);
    let mut writer = Writer {
        out: String::with_capacity(size + size / 8 + 4096),
        depth: 0,
        scene,
        all: options.all_fields,
        version: if needs_version_2(scene) { 2 } else { 1 },
        world: Scope::new(scene.kept(Object::World), 1),
        item: None,
    };
    writer.document();
    Ok(writer.out.into_bytes())
}

/// The dialect a write keeps when none is asked for: the one the scene was read in, when
/// it can hold the scene (a file of an engine's dialect that was given comments, or
/// anything else its reader would not take, is no longer that engine's), else box2scene's.
fn remembered_dialect(scene: &Scene) -> Dialect {
    match scene.dialect() {
        Dialect::Box2scene => Dialect::Box2scene,
        engine if farseer::cannot_hold(scene, engine).is_some() => Dialect::Box2scene,
        engine => engine,
    }
}

/// The error for the first joint of the unsupported kind that has no text of its own.
fn unwritable_joint(scene: &Scene) -> Result<(), Error> {
    let has_text =
        |i: usize| scene.kept(Object::Joint(i as u32)).iter().any(|k| k.place == KeptAt::Whole);
    let Some((i, joint)) = scene
        .joints()
        .iter()
        .enumerate()
        .find(|&(i, j)| j.kind() == Some(JointKind::Unsupported) && !has_text(i))
    else {
        return Ok(());
    };
    let name = scene.text(joint.name).map(|n| format!(" (\"{n}\")")).unwrap_or_default();
    Err(Error {
        code: Code::UnsupportedJointType,
        position: Position::default(),
        message: format!(
            "joint {i}{name} is of the unsupported kind and has no text of its own (only a loaded Farseer-only joint has): the format has no other form for it, so the scene cannot be written"
        ),
    })
}

/// The error for the first name or UserData that a written file could not hold, or that
/// could not be read back from it with the default load options (a scene loaded with
/// larger limits, or built with a host's records, may have one).
fn unwritable_texts(scene: &Scene) -> Result<(), Error> {
    let unwritable = |object: Object, why: Problem| Error {
        code: why.code,
        position: Position::default(),
        message: format!("{object}: {}, so the scene cannot be written", why.message),
    };
    let index = |i: usize| i as u32;
    let shapes = scene.shapes().iter().enumerate();
    let shapes = shapes.map(|(i, s)| (Object::Shape(index(i)), s.name, NONE));
    let fixtures = scene.fixtures().iter().enumerate();
    let fixtures = fixtures.map(|(i, f)| (Object::Fixture(index(i)), f.name, f.user_data));
    let bodies = scene.bodies().iter().enumerate();
    let bodies = bodies.map(|(i, b)| (Object::Body(index(i)), b.name, b.user_data));
    let joints = scene.joints().iter().enumerate();
    let joints = joints.map(|(i, j)| (Object::Joint(index(i)), j.name, j.user_data));
    for (object, name, user_data) in shapes.chain(fixtures).chain(bodies).chain(joints) {
        if let Some(name) = scene.text(name) {
            writable_text("its Name", name).map_err(|e| unwritable(object, e))?;
        }
        if let Some(raw) = scene.user_data_at(user_data).and_then(|u| scene.text(u.raw)) {
            writable_content(raw, USER_DATA_DEPTH).map_err(|why| {
                let message = format!("its UserData: {}", why.message);
                unwritable(object, Box::new(Finding { message, ..*why }))
            })?;
        }
    }
    Ok(())
}

/// Whether `text`, written escaped as the text of `field`, reads back: it holds only
/// characters XML allows, and no more bytes than the loader reads in one text by default.
pub(crate) fn writable_text(field: &str, text: &str) -> Parsed<()> {
    if let Some(at) = first_non_char(text.as_bytes()) {
        let c = text[at..].chars().next().unwrap_or_default();
        let c = u32::from(c);
        return Err(problem(
            Code::MalformedXml,
            0,
            format!("{field} holds the character U+{c:04X}, which XML does not allow"),
        ));
    }
    let most = LoadOptions::default().max_text_bytes;
    let mut len = 0;
    escaped(text, |piece| len += piece.len());
    if len as u64 > most {
        return Err(problem(
            Code::LimitExceeded,
            0,
            format!(
                "{field} is {len} bytes long written, more than a load reads in one text by \
                 default (max_text_bytes = {most})"
            ),
        ));
    }
    Ok(())
}

/// Whether `raw`, XML content written verbatim inside `depth` open elements, reads back
/// with the default load options. Most is plainly short and shallow; the rest is read as
/// the loader would read it there.
fn writable_content(raw: &str, depth: u32) -> Parsed<()> {
    let default = LoadOptions::default();
    // Each `<` opens one more element at most.
    let tags = memchr::memchr_iter(b'<', raw.as_bytes()).count() as u64;
    let plain = first_non_char(raw.as_bytes()).is_none()
        && raw.len() as u64 <= default.max_text_bytes
        && u64::from(depth) + tags <= u64::from(default.max_depth);
    match plain {
        true => Ok(()),
        false => user_data_fragment(raw, depth).map(|_| ()),
    }
}

/// The error for the first text kept from a loaded file that a load with the default
/// options would refuse from the written file (a scene loaded with larger limits may hold
/// a long comment, or an unknown element nested deep).
fn unreadable_kept_text(scene: &Scene) -> Result<(), Error> {
    for kept in &scene.kept {
        // How many elements are open where the text is written.
        let depth = match (kept.object, kept.place) {
            (_, KeptAt::Attribute) => continue,
            (Object::World, KeptAt::Before | KeptAt::After) => 0,
            (Object::World, KeptAt::Inside { within: "", .. }) => 1,
            (Object::World, _) => 2,
            (_, KeptAt::Before | KeptAt::After | KeptAt::Whole) => 2,
            (_, KeptAt::Inside { within: "", .. }) => 3,
            (_, KeptAt::Inside { .. }) => 4,
        };
        let text = scene.text(kept.text).unwrap_or_default();
        writable_content(text, depth).map_err(|why| Error {
            code: why.code,
            position: Position::default(),
            message: format!(
                "{}: what its file held beyond the records: {}, so the scene cannot be \
                 written",
                kept.object, why.message
            ),
        })?;
    }
    Ok(())
}

/// The error for the first object whose start tag would carry one attribute name twice
/// (names compare as the loader compares them, ignoring case): two unknown attributes it
/// was given from different places of the file (a Version 3 body gets those of its
/// `<Pair>`s), or one named as the writer's own `Type` or `Version`.
fn clashing_attributes(scene: &Scene) -> Result<(), Error> {
    let mut names: Vec<(Object, String)> = Vec::new();
    for kept in &scene.kept {
        if kept.place != KeptAt::Attribute {
            continue;
        }
        let text = scene.text(kept.text).unwrap_or_default().trim_start();
        let name = text.split(['=', ' ', '\t', '\n', '\r']).next().unwrap_or_default();
        let key = name.to_ascii_lowercase();
        let own = match kept.object {
            Object::World => "version",
            Object::Fixture(_) => "",
            _ => "type",
        };
        let clash = key == own || names.iter().any(|(o, k)| *o == kept.object && *k == key);
        if clash {
            return Err(Error {
                code: Code::DuplicateAttribute,
                position: Position::default(),
                message: format!(
                    "{} would carry the attribute {name} twice: the file gave it unknown attributes of that name from more than one place (or one the writer writes itself), so the scene cannot be written without losing one",
                    kept.object
                ),
            });
        }
        names.push((kept.object, key));
    }
    Ok(())
}

/// About how many bytes a scene's text takes, from what is typical of the editor's files:
/// room enough that the text is rarely moved while it grows.
fn estimated_size(scene: &Scene) -> usize {
    let shapes: usize = scene.shapes().iter().map(|s| 100 + 40 * s.vertices.count as usize).sum();
    let bodies: usize = scene.bodies().iter().map(|b| 300 + 30 * b.fixtures.count as usize).sum();
    shapes + 200 * scene.fixtures().len() + bodies + 270 * scene.joints().len()
}

/// How many items `container` holds.
fn count(scene: &Scene, container: Container) -> usize {
    match container {
        Container::Shapes => scene.shapes().len(),
        Container::Fixtures => scene.fixtures().len(),
        Container::Bodies => scene.bodies().len(),
        Container::Joints => scene.joints().len(),
    }
}

pub(crate) fn needs_version_2(scene: &Scene) -> bool {
    let shape = |s: &Shape| matches!(s.kind(), Some(ShapeKind::Edge | ShapeKind::Chain));
    let body = |b: &Body| b.gravity_scale.to_bits() != 1f32.to_bits();
    let joint = |j: &Joint| match j.kind() {
        // A Farseer-only joint is written back as Farseer wrote it, in a Version 2 file.
        Some(JointKind::Wheel | JointKind::Rope | JointKind::Motor | JointKind::Unsupported) => {
            true
        }
        Some(JointKind::Weld) => j.frequency_hz.to_bits() != 0 || j.damping_ratio.to_bits() != 0,
        _ => false,
    };
    scene.shapes().iter().any(shape)
        || scene.bodies().iter().any(body)
        || scene.joints().iter().any(joint)
}

/// Appends the shortest text that reads back to the same f32 as `value`: plain
/// decimals for ordinary magnitudes, an exponent for tiny and huge ones (as .NET wrote
/// `8.369571E-36`). That is the text `Display` gives for the first and `{:e}` for the
/// others, laid out from ryu's shortest digits, which cost a fraction of `core::fmt`'s.
fn push_float(out: &mut String, value: f32) {
    if !value.is_finite() {
        let _ = write!(out, "{value}");
        return;
    }
    if value.is_sign_negative() {
        out.push('-');
    }
    if value == 0.0 {
        out.push('0');
        return;
    }
    let mut buffer = ryu::Buffer::new();
    let text = buffer.format_finite(value.abs());
    let plain = (1e-5..1e16).contains(&value.abs());
    if plain && !text.contains('e') && !may_be_a_tie(value.abs()) {
        // Most values: ryu's own layout is the one wanted, but for its `.0` on whole
        // numbers.
        out.push_str(text.strip_suffix(".0").unwrap_or(text));
        return;
    }
    let mut shortest = Shortest::of(text);
    shortest.break_ties_upwards(value.abs());
    let digits = shortest.digits();
    let point = shortest.point;
    if plain {
        if point <= 0 {
            out.push_str("0.");
            push_zeros(out, -point);
            out.push_str(digits);
        } else if point as usize >= digits.len() {
            out.push_str(digits);
            push_zeros(out, point - digits.len() as i32);
        } else {
            let (whole, fraction) = digits.split_at(point as usize);
            for piece in [whole, ".", fraction] {
                out.push_str(piece);
            }
        }
    } else {
        let (first, rest) = digits.split_at(1);
        out.push_str(first);
        if !rest.is_empty() {
            out.push('.');
            out.push_str(rest);
        }
        out.push('e');
        out.push_str(integer_text(i64::from(point - 1), &mut [0; 20]));
    }
}

fn push_zeros(out: &mut String, count: i32) {
    for _ in 0..count {
        out.push('0');
    }
}

/// `value` in decimal, in `buffer`.
fn integer_text(value: i64, buffer: &mut [u8; 20]) -> &str {
    let mut at = buffer.len();
    let mut rest = value.unsigned_abs();
    loop {
        at -= 1;
        buffer[at] = b'0' + (rest % 10) as u8;
        rest /= 10;
        if rest == 0 {
            break;
        }
    }
    if value < 0 {
        at -= 1;
        buffer[at] = b'-';
    }
    std::str::from_utf8(&buffer[at..]).unwrap_or_default()
}

/// A positive float as m x 2^e.
fn binary(value: f32) -> (u128, i32) {
    let bits = value.to_bits();
    let (fraction, biased) = (u128::from(bits & 0x7f_ffff), (bits >> 23) & 0xff);
    match biased {
        0 => (fraction, -149),
        _ => (fraction | 1 << 23, biased as i32 - 150),
    }
}

/// Whether a positive float could lie half way between two texts of its shortest
/// length. A tie has at most 10 digits, so its exact value is a fraction over at most
/// 2^14 (5^k digits need 2^k below them).
fn may_be_a_tie(value: f32) -> bool {
    let (m, e) = binary(value);
    -e - m.trailing_zeros() as i32 <= 14
}

/// A positive float's shortest digits, without leading or trailing zeros, and where
/// its decimal point goes: the value is 0.`digits` x 10^`point`.
struct Shortest {
    digits: [u8; 32],
    len: usize,
    point: i32,
}

impl Shortest {
    /// Reads them from ryu's text, whichever of its layouts (`1e-7`, `1.5e20`,
    /// `0.001`, `12.5`, `100.0`) it chose.
    fn of(text: &str) -> Self {
        let text = text.as_bytes();
        let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
            Some(e) => (&text[..e], Self::exponent(&text[e + 1..])),
            None => (text, 0),
        };
        let dot = mantissa.iter().position(|&b| b == b'.').unwrap_or(mantissa.len());
        let mut shortest = Shortest { digits: [0; 32], len: 0, point: exponent };
        for (at, &b) in mantissa.iter().enumerate().filter(|&(_, &b)| b != b'.') {
            if b == b'0' && shortest.len == 0 {
                continue;
            }
            if shortest.len == 0 {
                shortest.point += dot as i32 - at as i32 + i32::from(at > dot);
            }
            shortest.digits[shortest.len] = b;
            shortest.len += 1;
        }
        while shortest.len > 1 && shortest.digits[shortest.len - 1] == b'0' {
            shortest.len -= 1;
        }
        shortest
    }

    /// `core::fmt` breaks a tie between two shortest texts upwards, ryu to the even
    /// last digit: moves ryu's digits of `value` up where the two differ.
    fn break_ties_upwards(&mut self, value: f32) {
        let last = self.digits[self.len - 1] - b'0';
        if last % 2 == 1 || !self.is_just_below_half_way(value) {
            return;
        }
        self.digits[self.len - 1] += 1;
    }

    /// Whether `value` lies exactly half way between these digits and the next ones
    /// up, compared as integers: m x 2^e against (10 x digits + 5) x 10^q. Where a side
    /// overflows u128 the two differ.
    fn is_just_below_half_way(&self, value: f32) -> bool {
        if !may_be_a_tie(value) {
            return false;
        }
        let (m, e) = binary(value);
        let digits = self.digits().bytes().fold(0u128, |n, d| n * 10 + u128::from(d - b'0'));
        let q = self.point - self.len as i32 - 1;
        let times = |n: u128, base: u128, power: i32| {
            base.checked_pow(power.max(0) as u32).and_then(|p| n.checked_mul(p))
        };
        let left = times(m, 2, e).and_then(|n| times(n, 10, -q));
        let right = times(digits * 10 + 5, 10, q).and_then(|n| times(n, 2, -e));
        matches!((left, right), (Some(l), Some(r)) if l == r)
    }

    fn exponent(text: &[u8]) -> i32 {
        let (negative, digits) = match text {
            [b'-', digits @ ..] => (true, digits),
            _ => (false, text),
        };
        let magnitude = digits.iter().fold(0, |n, &d| n * 10 + i32::from(d - b'0'));
        if negative { -magnitude } else { magnitude }
    }

    fn digits(&self) -> &str {
        std::str::from_utf8(&self.digits[..self.len]).unwrap_or_default()
    }
}

/// Text content and attribute values: markup characters as entities, characters XML
/// would change on reading (carriage returns) as character references.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    escaped(text, |piece| out.push_str(piece));
    out
}

/// [`escape`] of `text`, as the pieces to append in turn.
fn escaped(mut text: &str, mut push: impl FnMut(&str)) {
    while let Some(at) = text.find(['&', '<', '>', '"', '\r']) {
        push(&text[..at]);
        push(match text.as_bytes()[at] {
            b'&' => "&amp;",
            b'<' => "&lt;",
            b'>' => "&gt;",
            b'"' => "&quot;",
            _ => "&#13;",
        });
        text = &text[at + 1..];
    }
    push(text);
}

struct Writer<'s> {
    out: String,
    depth: usize,
    scene: &'s Scene,
    all: bool,
    version: u32,
    /// The kept text of the world, and of the item being written.
    world: Scope<'s>,
    item: Option<Scope<'s>>,
}

/// An object being written (the world or an item) and the text its file held beyond the
/// records, with which of it is written so far.
struct Scope<'s> {
    kept: &'s [Kept],
    written: Vec<bool>,
    /// The depth of the object's children.
    depth: usize,
    /// The child open now, whose children are being written ("" for none).
    within: &'static str,
}

impl<'s> Scope<'s> {
    fn new(kept: &'s [Kept], depth: usize) -> Scope<'s> {
        Scope { kept, written: vec![false; kept.len()], depth, within: "" }
    }

    /// Whether some of the text goes inside the child `name`, which is then written even
    /// when all its values are defaults.
    fn has_within(&self, name: &str) -> bool {
        self.kept.iter().any(|k| matches!(k.place, KeptAt::Inside { within, .. } if within == name))
    }
}

impl<'s> Writer<'s> {
    fn scope(&mut self) -> &mut Scope<'s> {
        self.item.as_mut().unwrap_or(&mut self.world)
    }

    /// Writes the kept text of the current object at the places `wanted` selects, unless
    /// it was written: attributes as they are, the rest on lines of their own.
    fn put(&mut self, wanted: impl Fn(KeptAt) -> bool) {
        let kept = self.scope().kept;
        for (i, k) in kept.iter().enumerate() {
            if self.scope().written[i] || !wanted(k.place) {
                continue;
            }
            self.scope().written[i] = true;
            let text = self.scene.text(k.text).unwrap_or_default();
            if k.place != KeptAt::Attribute {
                self.indent();
            }
            self.out.push_str(text);
            if k.place != KeptAt::Attribute {
                self.out.push('\n');
            }
        }
    }

    /// Before an element `name` of the current object, or of its child open now: the
    /// kept text that preceded it.
    fn before(&mut self, name: &str) {
        let depth = self.depth;
        let scope = self.scope();
        // Above the object (its own start tag, or the world's) nothing of it goes before.
        let within = match depth.checked_sub(scope.depth) {
            Some(0) => "",
            Some(1) => scope.within,
            _ => return,
        };
        self.put(|at| matches!(at, KeptAt::Inside { within: w, before } if w == within && before == name));
    }

    /// Writes `object` (an item of a container) with `write`, or as its kept whole text,
    /// with the kept text before it.
    fn item(&mut self, object: Object, write: impl FnOnce(&mut Self)) {
        let kept = self.scene.kept(object);
        self.item = Some(Scope::new(kept, self.depth + 1));
        self.put(|at| at == KeptAt::Before);
        if kept.iter().any(|k| k.place == KeptAt::Whole) {
            self.put(|at| at == KeptAt::Whole);
        } else {
            write(self);
        }
        self.item = None;
    }

    /// The whole text: the world's start tag, its gravity, its containers and their
    /// items, and its end tag, each with the kept text around it.
    fn document(&mut self) {
        self.put(|at| at == KeptAt::Before);
        self.open_typed("World", "Version", if self.version == 2 { "2" } else { "1" });
        if let Some(gravity) = self.scene.gravity() {
            self.vector("Gravity", gravity);
        }
        let scene = self.scene;
        for container in Container::ALL {
            let (name, count) = (container.name(), count(scene, container));
            if count == 0 && !self.world.has_within(name) {
                self.element(name, "");
                continue;
            }
            self.open(name);
            for i in 0..count {
                let index = i as u32;
                match container {
                    Container::Shapes => {
                        self.item(Object::Shape(index), |w| w.shape(&scene.shapes()[i]))
                    }
                    Container::Fixtures => {
                        self.item(Object::Fixture(index), |w| w.fixture(&scene.fixtures()[i]))
                    }
                    Container::Bodies => {
                        self.item(Object::Body(index), |w| w.body(&scene.bodies()[i]))
                    }
                    Container::Joints => {
                        self.item(Object::Joint(index), |w| w.joint(&scene.joints()[i]))
                    }
                }
            }
            self.close(name);
        }
        self.close("World");
        self.put(|at| at == KeptAt::After);
    }

    fn indent(&mut self) {
        const SPACES: &str = "                ";
        let mut width = 2 * self.depth;
        while width > 0 {
            let piece = &SPACES[..width.min(SPACES.len())];
            self.out.push_str(piece);
            width -= piece.len();
        }
    }

    /// `<name>` on its own line.
    fn open(&mut self, name: &'static str) {
        self.open_with(name, |_| {});
    }

    /// `<name Type="value">` on its own line.
    fn open_typed(&mut self, name: &'static str, attribute: &str, value: &str) {
        self.open_with(name, |out| {
            for piece in [" ", attribute, "=\"", value, "\""] {
                out.push_str(piece);
            }
        });
    }

    /// `<name ...>` on its own line; the object's own start tag gets its kept attributes,
    /// and a child of the object is the one open now.
    fn open_with(&mut self, name: &'static str, attributes: impl FnOnce(&mut String)) {
        self.before(name);
        self.indent();
        self.out.push('<');
        self.out.push_str(name);
        attributes(&mut self.out);
        if self.depth + 1 == self.scope().depth {
            self.put(|at| at == KeptAt::Attribute);
        }
        self.out.push_str(">\n");
        self.depth += 1;
        let depth = self.depth;
        let scope = self.scope();
        if depth == scope.depth + 1 {
            scope.within = name;
        }
    }

    /// `</name>` on its own line, after the kept text that ended the element: for a child
    /// of the object, all of it that goes inside; for an item, whatever of it was not
    /// written yet (what preceded an element that was not written goes at the end).
    fn close(&mut self, name: &'static str) {
        let depth = self.scope().depth;
        if self.depth == depth + 1 {
            self.put(|at| matches!(at, KeptAt::Inside { within, .. } if within == name));
            self.scope().within = "";
        } else if self.depth == depth && self.item.is_some() {
            self.put(|at| matches!(at, KeptAt::Inside { .. }));
        } else if self.depth == depth {
            self.put(|at| at == KeptAt::Inside { within: "", before: "" });
        }
        self.depth -= 1;
        self.indent();
        for piece in ["</", name, ">\n"] {
            self.out.push_str(piece);
        }
    }

    fn element(&mut self, name: &str, text: &str) {
        if text.is_empty() {
            self.before(name);
            self.indent();
            for piece in ["<", name, " />\n"] {
                self.out.push_str(piece);
            }
        } else {
            self.element_with(name, |out| out.push_str(text));
        }
    }

    /// `<name>text</name>` on its own line, `text` written straight into the output.
    fn element_with(&mut self, name: &str, text: impl FnOnce(&mut String)) {
        self.before(name);
        self.indent();
        for piece in ["<", name, ">"] {
            self.out.push_str(piece);
        }
        text(&mut self.out);
        for piece in ["</", name, ">\n"] {
            self.out.push_str(piece);
        }
    }

    fn vector(&mut self, name: &str, v: Vec2) {
        self.element_with(name, |out| {
            push_float(out, v.x);
            out.push(' ');
            push_float(out, v.y);
        });
    }

    fn name(&mut self, name: Str) {
        match self.scene.text(name) {
            Some("") => self.element("Name", ""),
            Some(text) => {
                self.element_with("Name", |out| escaped(text, |piece| out.push_str(piece)))
            }
            None => {}
        }
    }

    fn number(&mut self, name: &str, value: f32) {
        self.element_with(name, |out| push_float(out, value));
    }

    fn integer(&mut self, name: &str, value: impl Into<i64>) {
        let value = value.into();
        self.element_with(name, |out| out.push_str(integer_text(value, &mut [0; 20])));
    }

    /// The optional elements: written when asked for every field or when the value's bits
    /// differ from the default's (so -0.0 and 0.0 stay apart).
    fn float(&mut self, name: &str, value: f32, default: f32) {
        if self.all || value.to_bits() != default.to_bits() {
            self.number(name, value);
        }
    }

    fn vector_or_default(&mut self, name: &str, value: Vec2, default: Vec2) {
        if self.all
            || value.x.to_bits() != default.x.to_bits()
            || value.y.to_bits() != default.y.to_bits()
        {
            self.vector(name, value);
        }
    }

    fn flag(&mut self, name: &str, value: bool, default: bool) {
        if self.all || value != default {
            self.element(name, if value { "true" } else { "false" });
        }
    }

    fn user_data(&mut self, index: u32) {
        let Some(user_data) = self.scene.user_data_at(index) else { return };
        let raw = self.scene.text(user_data.raw).unwrap_or_default();
        self.before("UserData");
        self.indent();
        for piece in ["<UserData>", raw, "</UserData>\n"] {
            self.out.push_str(piece);
        }
    }

    fn shape(&mut self, shape: &Shape) {
        let kind = shape.kind().unwrap_or(ShapeKind::Circle);
        let ty = match (kind, shape.is_loop) {
            (ShapeKind::Circle, _) => "Circle",
            (ShapeKind::Polygon, _) => "Polygon",
            (ShapeKind::Edge, _) => "Edge",
            (ShapeKind::Chain, false) => "Chain",
            (ShapeKind::Chain, true) => "Loop",
        };
        self.open_typed("Shape", "Type", ty);
        self.name(shape.name);
        let vertices = self.scene.vertices(shape);
        let zero = Vec2::ZERO;
        match kind {
            ShapeKind::Circle => {
                self.number("Radius", shape.radius);
                self.vector("Position", shape.position);
            }
            ShapeKind::Polygon | ShapeKind::Chain => {
                self.open("Vertices");
                for &v in vertices {
                    self.vector("Vertex", v);
                }
                self.close("Vertices");
            }
            ShapeKind::Edge => {
                self.vector("Vertex1", vertices[0]);
                self.vector("Vertex2", vertices[1]);
            }
        }
        match kind {
            ShapeKind::Polygon if shape.centroid_given => self.vector("Centroid", shape.centroid),
            ShapeKind::Edge => {
                self.vector_or_default("Vertex0", shape.prev_vertex, zero);
                self.vector_or_default("Vertex3", shape.next_vertex, zero);
                self.flag("HasVertex0", shape.has_prev_vertex, false);
                self.flag("HasVertex3", shape.has_next_vertex, false);
            }
            ShapeKind::Chain => {
                self.vector_or_default("PrevVertex", shape.prev_vertex, zero);
                self.vector_or_default("NextVertex", shape.next_vertex, zero);
                self.flag("HasPrevVertex", shape.has_prev_vertex, false);
                self.flag("HasNextVertex", shape.has_next_vertex, false);
            }
            _ => {}
        }
        self.close("Shape");
    }

    fn fixture(&mut self, fixture: &Fixture) {
        let defaults = Fixture::default();
        self.open("Fixture");
        self.integer("Shape", fixture.shape);
        self.name(fixture.name);
        self.float("Density", fixture.density, defaults.density);
        self.float("Friction", fixture.friction, defaults.friction);
        self.float("Restitution", fixture.restitution, defaults.restitution);
        self.flag("IsSensor", fixture.is_sensor, defaults.is_sensor);
        self.filter(&fixture.filter);
        self.user_data(fixture.user_data);
        self.close("Fixture");
    }

    fn filter(&mut self, filter: &Filter) {
        let defaults = Filter::default();
        if !self.all && *filter == defaults && !self.scope().has_within("FilterData") {
            return;
        }
        self.open("FilterData");
        for (name, value, default) in [
            ("CategoryBits", filter.category_bits, defaults.category_bits),
            ("MaskBits", filter.mask_bits, defaults.mask_bits),
        ] {
            if self.all || value != default {
                self.integer(name, value);
            }
        }
        if self.all || filter.group_index != defaults.group_index {
            self.integer("GroupIndex", filter.group_index);
        }
        self.close("FilterData");
    }

    fn body(&mut self, body: &Body) {
        let kind = body.kind().unwrap_or(BodyKind::Static);
        let d = Body::new(kind);
        let ty = match kind {
            BodyKind::Static => "Static",
            BodyKind::Kinematic => "Kinematic",
            BodyKind::Dynamic => "Dynamic",
        };
        self.open_typed("Body", "Type", ty);
        self.name(body.name);
        self.flag("Active", body.active, d.active);
        self.flag("AllowSleep", body.allow_sleep, d.allow_sleep);
        self.float("Angle", body.angle, d.angle);
        self.float("AngularDamping", body.angular_damping, d.angular_damping);
        self.float("AngularVelocity", body.angular_velocity, d.angular_velocity);
        self.flag("Awake", body.awake, d.awake);
        self.flag("Bullet", body.bullet, d.bullet);
        self.flag("FixedRotation", body.fixed_rotation, d.fixed_rotation);
        if self.version >= 2 {
            self.float("GravityScale", body.gravity_scale, d.gravity_scale);
        }
        self.float("InertiaScale", body.inertia_scale, d.inertia_scale);
        self.float("LinearDamping", body.linear_damping, d.linear_damping);
        self.vector_or_default("LinearVelocity", body.linear_velocity, d.linear_velocity);
        self.vector_or_default("Position", body.position, d.position);
        let m = body.mass_data;
        if m.mass_given || m.center_given || m.inertia_given || self.scope().has_within("MassData")
        {
            self.open("MassData");
            if m.mass_given {
                self.number("Mass", m.mass);
            }
            if m.center_given {
                self.vector("Center", m.center);
            }
            if m.inertia_given {
                self.number("Inertia", m.inertia);
            }
            self.close("MassData");
        }
        let ids = self.scene.body_fixtures(body);
        if ids.is_empty() {
            self.element("Fixtures", "");
        } else {
            self.open("Fixtures");
            for &id in ids {
                self.integer("ID", id);
            }
            self.close("Fixtures");
        }
        self.user_data(body.user_data);
        self.close("Body");
    }

    fn joint(&mut self, joint: &Joint) {
        let kind = joint.kind().unwrap_or(JointKind::Revolute);
        let d = Joint::new(kind);
        self.open_with("Joint", |out| {
            let _ = write!(out, " Type=\"{kind:?}\"");
        });
        self.name(joint.name);
        self.integer("BodyA", joint.body_a);
        self.integer("BodyB", joint.body_b);
        self.flag("CollideConnected", joint.collide_connected, d.collide_connected);
        use JointKind::*;
        let is = |kinds: &[JointKind]| kinds.contains(&kind);
        if !is(&[Gear, Motor]) {
            self.vector_or_default("LocalAnchorA", joint.local_anchor_a, d.local_anchor_a);
            self.vector_or_default("LocalAnchorB", joint.local_anchor_b, d.local_anchor_b);
        }
        if is(&[Prismatic, Line, Wheel]) {
            self.vector_or_default("LocalAxisA", joint.local_axis_a, d.local_axis_a);
        }
        if is(&[Revolute, Prismatic, Weld]) {
            self.float("ReferenceAngle", joint.reference_angle, d.reference_angle);
        }
        if is(&[Revolute, Prismatic, Line]) {
            self.flag("EnableLimit", joint.enable_limit, d.enable_limit);
            let (lower, upper) = if kind == Revolute {
                ("LowerAngle", "UpperAngle")
            } else {
                ("LowerTranslation", "UpperTranslation")
            };
            self.float(lower, joint.lower_limit, d.lower_limit);
            self.float(upper, joint.upper_limit, d.upper_limit);
        }
        if is(&[Revolute, Prismatic, Line, Wheel]) {
            self.flag("EnableMotor", joint.enable_motor, d.enable_motor);
            self.float("MotorSpeed", joint.motor_speed, d.motor_speed);
        }
        if is(&[Revolute, Wheel]) {
            self.float("MaxMotorTorque", joint.max_motor_torque, d.max_motor_torque);
        }
        if is(&[Prismatic, Line]) {
            self.float("MaxMotorForce", joint.max_motor_force, d.max_motor_force);
        }
        if kind == Distance {
            self.float("Length", joint.length, d.length);
        }
        if is(&[Distance, Wheel]) || (kind == Weld && self.version >= 2) {
            self.float("FrequencyHz", joint.frequency_hz, d.frequency_hz);
            self.float("DampingRatio", joint.damping_ratio, d.damping_ratio);
        }
        if kind == Pulley {
            self.vector_or_default("GroundAnchorA", joint.ground_anchor_a, d.ground_anchor_a);
            self.vector_or_default("GroundAnchorB", joint.ground_anchor_b, d.ground_anchor_b);
            self.float("LengthA", joint.length_a, d.length_a);
            self.float("LengthB", joint.length_b, d.length_b);
            self.float("MaxLengthA", joint.max_length_a, d.max_length_a);
            self.float("MaxLengthB", joint.max_length_b, d.max_length_b);
        }
        if kind == Gear && joint.joint_a != NONE {
            self.integer("JointA", joint.joint_a);
            self.integer("JointB", joint.joint_b);
        }
        if is(&[Pulley, Gear]) {
            self.float("Ratio", joint.ratio, d.ratio);
        }
        if is(&[Friction, Motor]) {
            self.float("MaxForce", joint.max_force, d.max_force);
            self.float("MaxTorque", joint.max_torque, d.max_torque);
        }
        if kind == Rope {
            self.float("MaxLength", joint.max_length, d.max_length);
        }
        if kind == Motor {
            self.vector_or_default("LinearOffset", joint.linear_offset, d.linear_offset);
            self.float("AngularOffset", joint.angular_offset, d.angular_offset);
            self.float("CorrectionFactor", joint.correction_factor, d.correction_factor);
        }
        self.user_data(joint.user_data);
        self.close("Joint");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn float_text(value: f32) -> String {
        let mut out = String::new();
        push_float(&mut out, value);
        out
    }

    #[test]
    fn floats_are_shortest_and_read_back_to_the_same_bits() {
        for (value, text) in [
            (1.0f32, "1"),
            (0.2, "0.2"),
            (-1.2345679, "-1.2345679"),
            (-0.0, "-0"),
            (8.369571e-36, "8.369571e-36"),
            (f32::MAX, "3.4028235e38"),
            (f32::from_bits(1), "1e-45"),
            (1e-5, "0.00001"),
        ] {
            assert_eq!(float_text(value), text);
            assert_eq!(crate::text::float(text).unwrap().to_bits(), value.to_bits(), "{text}");
        }
    }

    /// The writer's floats before ryu: `core::fmt`'s text, which stays the contract.
    fn core_fmt_text(value: f32) -> String {
        let magnitude = value.abs();
        if magnitude == 0.0 || (1e-5..1e16).contains(&magnitude) {
            format!("{value}")
        } else {
            format!("{value:e}")
        }
    }

    #[test]
    fn floats_are_written_as_core_fmt_writes_them() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut random_bits = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state as u32
        };
        let edges = [0u32, 1, 0x007f_ffff, 0x0080_0000, 0x7f7f_ffff, 0x3f80_0000, 0x4b80_0000]
            .into_iter()
            .chain([1e-5f32, 9.99999e-6, 1e16, 9.999999e15, 0.1, 123_456_790.0].map(f32::to_bits))
            .chain((-45..=38).map(|e| format!("1e{e}").parse::<f32>().unwrap().to_bits()));
        for bits in edges.chain((0..2_000_000).map(|_| random_bits())) {
            for value in [f32::from_bits(bits), -f32::from_bits(bits)] {
                assert_eq!(float_text(value), core_fmt_text(value), "{bits:#x}");
            }
        }
    }

    /// Every f32, a few minutes in release:
    /// `cargo test --release --lib every_float -- --ignored`.
    #[test]
    #[ignore]
    fn every_float_is_written_as_core_fmt_writes_it() {
        std::thread::scope(|scope| {
            for half in [0u32, 1] {
                scope.spawn(move || {
                    for bits in (half << 31..=(half << 31 | 0x7fff_ffff)).step_by(1) {
                        let value = f32::from_bits(bits);
                        assert_eq!(float_text(value), core_fmt_text(value), "{bits:#x}");
                    }
                });
            }
        });
    }

    #[test]
    fn text_escapes_markup_and_carriage_returns() {
        assert_eq!(escape("a<b & \"c\">\r\né"), "a&lt;b &amp; &quot;c&quot;&gt;&#13;\né");
    }
}
