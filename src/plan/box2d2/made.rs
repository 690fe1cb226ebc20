//! A scene shape as the engine makes it, made once and kept for every fixture naming it:
//! what the shapes make and the world holds.

use super::shape_mass::MassShape;
use crate::plan::records::PlanShapeKind;
use crate::scene::{Range, Vec2};

/// A scene shape as the engine makes it: the plan's form, and the engine's for its mass.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Made {
    pub kind: PlanShapeKind,
    /// Its points in the plan's pool, which every fixture of the shape shares.
    pub points: Range,
    /// A circle's centre, or a polygon's Centroid as the file gives it (NaN where it
    /// gives none: the engine keeps its own).
    pub center: Vec2,
    pub radius: f32,
    pub mass: MassShape,
}
