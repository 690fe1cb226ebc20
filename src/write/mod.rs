//! Scene -> Box2Scene XML (spec section 11): box2scene's own dialect (`own`) and those of
//! the engines' readers (`farseer`), after the checks of what the format can hold
//! ([`crate::holds`]), with the numbers spelt as `numbers` spells them. What it writes reads
//! back to the identical scene: every float bit for bit, every name, every UserData text.
#![forbid(unsafe_code)]

mod farseer;
mod numbers;
mod own;

use own::{Scope, Writer};

use crate::error::{Code, Error, Position};
use crate::holds::{clashing_attributes, needs_version_2, unreadable_kept_text};
use crate::holds::{unwritable_joint, unwritable_texts};
use crate::options::WriteOptions;
use crate::scene::{Dialect, Object, Scene};

/// Writes `scene` as a Box2Scene file, with no XML declaration (no reader of the format
/// wants one), in the dialect `options` names or else the one the scene remembers (never
/// another: a file of an engine's dialect given what its reader cannot take is refused,
/// not written in box2scene's). In
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
        // The one the scene was read in: what that dialect cannot hold is refused below,
        // never written in another dialect unasked.
        0 => scene.dialect(),
        n => Dialect::try_from(n).map_err(|n| Error {
            code: Code::InvalidArgument,
            position: Position::default(),
            message: format!("{n} names no dialect (1 to {})", Dialect::ALL.len()),
        })?,
    };
    if dialect != Dialect::Box2scene {
        return farseer::write(scene, dialect).map(String::into_bytes);
    }
    own::tags_respellable(scene)?;
    let size = estimated_size(scene);
    let mut writer = Writer {
        out: String::with_capacity(size + size / 8 + 4096),
        depth: 0,
        scene,
        all: options.all_fields,
        version: if needs_version_2(scene) { 2 } else { 1 },
        world: Scope::new(scene.beyond.of(Object::World), 1),
        item: None,
    };
    writer.document();
    Ok(writer.out.into_bytes())
}

/// About how many bytes a scene's text takes, from what is typical of the editor's files:
/// room enough that the text is rarely moved while it grows.
fn estimated_size(scene: &Scene) -> usize {
    let shapes: usize = scene.shapes().iter().map(|s| 100 + 40 * s.vertices.count as usize).sum();
    let bodies: usize = scene.bodies().iter().map(|b| 300 + 30 * b.fixtures.count as usize).sum();
    shapes + 200 * scene.fixtures().len() + bodies + 270 * scene.joints().len()
}

#[cfg(test)]
mod tests;
