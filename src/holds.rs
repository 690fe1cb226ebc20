//! What the format can hold, where the builder and the writer meet: the joints and texts a
//! file can carry, the kept text and attributes a reader would take back, the constructs
//! that need Version 2, and markup escaped. It checks what a reader would take back by
//! reading it (the UserData fragment, the kept text).
#![forbid(unsafe_code)]

use crate::bytes::first_non_char;
use crate::error::{Code, Error, Finding, Parsed, Position, Problem, problem};
use crate::markup::{USER_DATA_DEPTH, user_data_fragment};
use crate::options::LoadOptions;
use crate::scene::Object;
use crate::scene::joints::{VERSION_2_KINDS, has_version_2_value};
use crate::scene::{Body, Joint, JointKind, NONE};
use crate::scene::{KeptAt, Scene, Shape, ShapeKind};

/// The error for the first joint of the unsupported kind that has no text of its own.
pub(crate) fn unwritable_joint(scene: &Scene) -> Result<(), Error> {
    let has_text = |i: usize| {
        scene.beyond.of(Object::Joint(i as u32)).iter().any(|k| k.place == KeptAt::Whole)
    };
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
pub(crate) fn unwritable_texts(scene: &Scene) -> Result<(), Error> {
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
pub(crate) fn unreadable_kept_text(scene: &Scene) -> Result<(), Error> {
    for kept in &scene.beyond.pieces {
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
        let text = scene.beyond.text(kept);
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
pub(crate) fn clashing_attributes(scene: &Scene) -> Result<(), Error> {
    let mut names: Vec<(Object, String)> = Vec::new();
    for kept in &scene.beyond.pieces {
        if kept.place != KeptAt::Attribute {
            continue;
        }
        let text = scene.beyond.text(kept).trim_start();
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

pub(crate) fn needs_version_2(scene: &Scene) -> bool {
    let shape = |s: &Shape| matches!(s.kind(), Some(ShapeKind::Edge | ShapeKind::Chain));
    let body = |b: &Body| b.gravity_scale.to_bits() != 1f32.to_bits();
    let joint = |j: &Joint| match j.kind() {
        // A Farseer-only joint is written back as Farseer wrote it, in a Version 2 file.
        Some(JointKind::Unsupported) => true,
        Some(kind) => VERSION_2_KINDS.contains(kind) || has_version_2_value(j, kind),
        None => false,
    };
    scene.shapes().iter().any(shape)
        || scene.bodies().iter().any(body)
        || scene.joints().iter().any(joint)
}

/// Text content and attribute values: markup characters as entities, characters XML
/// would change on reading (carriage returns) as character references.
pub(crate) fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    escaped(text, |piece| out.push_str(piece));
    out
}

/// [`escape`] of `text`, as the pieces to append in turn.
pub(crate) fn escaped(mut text: &str, mut push: impl FnMut(&str)) {
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
