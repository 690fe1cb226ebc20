//! Pictures: a scene drawn as SVG, with a title, a key and the names of its named bodies.
//!
//! A picture shows every body where the scene puts it, or where a host's simulation says
//! (a start), and optionally a second time where the simulation ended (an end: the start is
//! then drawn faint), with the path each body's origin took between. Shapes are coloured by
//! their body's type; joints are drawn as Box2D's debug draw draws them (body origin to
//! anchor to anchor to body origin; a distance joint anchor to anchor; a pulley through its
//! ground anchors), their anchors marked by dots sized to the smaller body they join.
//! `box2scene render` and the examples draw with this one module.
//!
//! The world is drawn in metres, y up, inside one transform that turns it over; the title,
//! the key and the labels are sized in pixels of the picture's own width and height, so that
//! they read the same for a 2 m scene and a 2 km one. Geometry is computed in double
//! precision; a picture that reaches near the edges of single precision (finite values a
//! file may hold) is written scaled down by a power of two, and a tiny one (less than half
//! a metre across) scaled up, to one or two pixels a unit, so that every number written,
//! and every number a viewer computes from them in single precision, stays finite.

mod geometry;
mod labels;
mod svg;

use crate::error::{Code, Error, Position};
use crate::scene::{Scene, Vec2};
use geometry::Drawing;

/// Where a body is: its origin in the world and its angle in radians, as Box2D's
/// `GetPosition` and `GetAngle` (v3: `b2Body_GetPosition`, `b2Rot_GetAngle`) give them.
/// A pose with a coordinate or an angle that is not finite is not drawn: a body the host
/// did not create, or one its engine lost.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pose {
    /// The body's origin, in metres.
    pub position: Vec2,
    /// The body's angle, in radians.
    pub angle: f32,
}

/// What a picture shows beside the scene's shapes and joints.
#[derive(Clone, Copy, Debug, Default)]
pub struct Picture<'a> {
    /// The line on top of the picture; none when empty.
    pub title: &'a str,
    /// Where each body starts, one pose per body of the scene in its order; `None`: where
    /// the scene puts it.
    pub start: Option<&'a [Pose]>,
    /// Where each body ended, one pose per body; `None` draws the start alone, solid.
    pub end: Option<&'a [Pose]>,
    /// Which joints the host created, one flag per joint of the scene; `None`: every one.
    /// A joint not created is not drawn.
    pub joints: Option<&'a [bool]>,
    /// The points each body's origin passed through: sample after sample, each sample one
    /// point per body in the scene's order (so a multiple of the body count). A point that
    /// is not finite breaks the body's path there. Empty: no paths.
    pub trajectories: &'a [Vec2],
}

/// `scene` drawn as an SVG document, as `picture` says.
///
/// # Errors
/// `invalid-argument` when `start` or `end` does not hold one pose per body, `joints` one
/// flag per joint, or `trajectories` a whole number of samples.
pub fn svg(scene: &Scene, picture: &Picture<'_>) -> Result<String, Error> {
    let bodies = scene.bodies().len();
    for (what, poses) in [("start", picture.start), ("end", picture.end)] {
        if let Some(poses) = poses.filter(|poses| poses.len() != bodies) {
            let message = format!("{what} holds {} poses for {bodies} bodies", poses.len());
            return Err(invalid(message));
        }
    }
    if let Some(joints) = picture.joints.filter(|j| j.len() != scene.joints().len()) {
        let message =
            format!("joints holds {} flags for {} joints", joints.len(), scene.joints().len());
        return Err(invalid(message));
    }
    let samples = picture.trajectories.len();
    if (bodies == 0 && samples > 0) || (bodies > 0 && samples % bodies != 0) {
        let message = format!("trajectories hold {samples} points, not a multiple of {bodies}");
        return Err(invalid(message));
    }
    Ok(Drawing::new(scene, picture).document(picture.title))
}

fn invalid(message: String) -> Error {
    Error { code: Code::InvalidArgument, position: Position::default(), message }
}
