//! The capture stage, the plan's way back: what an engine holds of a live world, read by an
//! adapter into the plan's records (`records.rs`), turned into a scene whose build gives
//! the same bits back, and the reports of what the format cannot hold. Every conversion of
//! the way back lives here, once per engine family, beside the plan it inverts:
//!
//! - `mod.rs` (this file): the input, the result, and the family a capture is made by;
//! - `level.rs`: a capture of a built world labelled from the level it was built from (its
//!   Names and UserData where the host gives none, the joints the build skipped written
//!   back where the file had them, gears that name them);
//! - `world.rs`: the pass over the held records into a builder, equal shapes and fixtures
//!   written once, the order of the joints, what is not written and why;
//! - `box2d2/` (Box2D 2.3 and 2.4) and `box2d3/` (v3.1 and v3.2): one engine family's
//!   inverses, each computing forward with the plan's own arithmetic and searching the
//!   floats that give back what the engine holds.
//!
//! - `search.rs`: the floats near a guess for which a forward computation gives the wanted
//!   bits, which every family's inverses search.
//!
//! A family turns one held record into the scene's record and says what it loses; the
//! labels, indices, order and de-duplication are `world.rs`'s, the same for every engine.

#![forbid(unsafe_code)]
// The checks are negated comparisons, `!(value > 0)`, so that a NaN fails them as it fails
// the engine's.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod box2d2;
mod box2d3;
mod level;
mod records;
mod search;
mod world;

pub use records::*;

use crate::error::Error;
use crate::plan::box2d2::Version;
use crate::plan::box2d3::V3;
use crate::plan::{Engine, Plan, PlanReport};
use crate::scene::{Scene, Str, Vec2};
use world::Family;

/// A Name and UserData as text (what a [`HeldLabel`] points at, read).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Label<'a> {
    /// The name, if any.
    pub name: Option<&'a str>,
    /// The UserData's raw XML, if any.
    pub user_data_raw: Option<&'a str>,
    /// Its type name (the editor's form), if any.
    pub user_data_type: Option<&'a str>,
    /// Its value (the editor's form), if any.
    pub user_data_value: Option<&'a str>,
}

/// What an engine holds of a world, read: the records and, beside them, the texts their
/// `Str` fields point at (one entry per record, in the same order), so that nothing here
/// reads a pointer.
#[derive(Clone, Copy, Debug)]
pub struct Held<'a> {
    /// The engine version the records are read from.
    pub engine: Engine,
    /// m/s^2.
    pub gravity: Vec2,
    /// The bodies.
    pub bodies: &'a [HeldBody],
    /// The shapes.
    pub shapes: &'a [HeldShape],
    /// The shapes' points.
    pub points: &'a [Vec2],
    /// The joints.
    pub joints: &'a [HeldJoint],
    /// The scene joints the build skipped.
    pub skipped_joints: &'a [u32],
    /// Per body, its label.
    pub body_labels: &'a [Label<'a>],
    /// Per shape, its fixture's label.
    pub fixture_labels: &'a [Label<'a>],
    /// Per shape, the shape's name.
    pub shape_names: &'a [Option<&'a str>],
    /// Per shape, what it is where it has no form (`HeldShape::other`).
    pub shape_others: &'a [Option<&'a str>],
    /// Per joint, its label.
    pub joint_labels: &'a [Label<'a>],
    /// Per joint, what it is where it has no form (`HeldJoint::other`).
    pub joint_others: &'a [Option<&'a str>],
}

/// A capture's result: the scene, and the reports of what it could not hold exactly (the
/// plan's report records, their index counting the held objects of their kind, a joint
/// the build skipped counted in the level's joints).
#[derive(Debug)]
pub struct Captured {
    /// The scene.
    pub scene: Scene,
    /// What was lost or not written, in the order met: a plan that holds only reports,
    /// which owns their texts.
    pub reports: Plan,
}

impl Captured {
    /// The reports, in the order met.
    pub fn reports(&self) -> &[PlanReport] {
        self.reports.reports()
    }

    /// The text of a report's name or message.
    pub fn text(&self, s: Str) -> Option<&str> {
        self.reports.text(s)
    }
}

/// The scene holding what `held` says an engine holds, and the reports of what it cannot
/// hold exactly; `level`, the scene the world was built from, labels what the host does
/// not and gives the joints the build skipped back. Every engine's capture is made: the
/// result is an error only as the builder's checks are.
pub fn capture(held: &Held<'_>, level: Option<&Scene>) -> Result<Captured, Error> {
    let family = match Version::of(held.engine) {
        Some(version) => Family::Box2d2(version),
        None => Family::Box2d3(V3::of(held.engine).expect("every engine is 2.x or v3")),
    };
    Ok(world::capture(held, level, family))
}

#[cfg(test)]
mod tests;
