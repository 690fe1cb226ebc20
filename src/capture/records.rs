//! The records of a capture, as C fills them: what an engine holds of each body, shape and
//! joint, read through its getters into the plan's own terms (`crate::plan`'s records, so
//! that the way back is the plan read in reverse), with what a definition has not but a
//! live object may (a v3 filter's high bits, a 2.4 restitution threshold, a v3.2 motor's
//! driven velocities) beside it. An adapter reads; it converts and checks nothing: the
//! library turns the records into a scene and reports what the format cannot hold.

use crate::plan::{PlanBody, PlanJoint, PlanShape};
use crate::scene::{Str, UserData, Vec2};

/// The Name and UserData a host gives an object, or the engine keeps (v3's body name).
/// All NULL: the object is unlabelled, and a capture of a built world takes the level's.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldLabel {
    /// The name, or NULL.
    pub name: Str,
    /// The UserData: raw XML, or a type name and value for the editor's form; all NULL for
    /// none.
    pub user_data: UserData,
}

/// One body as the engine holds it. `body` is read as the plan's, but:
/// - `body.body`: the scene body it was built from, `B2S_NONE` for one of the host's;
/// - `body.angle` the engine's angle (2.x `GetAngle`), `body.rotation` its transform's
///   rotation (2.x `GetTransform().q`, v3 `b2Body_GetRotation`);
/// - `body.linear_velocity`: as the engine gives it (its centre of mass's);
/// - `body.mass`: as the engine holds it (2.x `GetMass`, `GetLocalCenter`, `GetInertia`
///   about the origin; v3 `b2Body_GetMassData`, its inertia about the centre);
/// - `body.shapes`: its held shapes, in the order they were created;
/// - `body.name` is not read (the label is), nor `velocity_after_mass` and the three flags
///   of what an executor does.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldBody {
    /// The body in the plan's terms.
    pub body: PlanBody,
    /// Its Name and UserData.
    pub label: HeldLabel,
}

/// One shape as the engine holds it. `shape` is read as the plan's, but:
/// - `shape.slot`: the scene's fixture ID pool entry it was built for, `B2S_NONE` for one of
///   the host's; `fixture` and `shape` are not read;
/// - `shape.kind` and `shape.points` as the plan gives them (a 2.x chain whole, its ghosts
///   around it; a loop is the engine's own points, as it holds them), and a v3 chain as its
///   segments: each a `SEGMENT` of four points `[ghost, ends, ghost]` with `chain` set;
/// - `shape.center`: a circle's centre, a 2.x polygon's centroid;
/// - `shape.radius`: a circle's radius, any other shape's skin (2.x `m_radius`, a v3
///   polygon's rounding);
/// - `shape.filter`: not read (`category_bits`, `mask_bits`, `group_index` are).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldShape {
    /// The shape and its fixture's material, in the plan's terms.
    pub shape: PlanShape,
    /// The filter's category bits, in the engine's width.
    pub category_bits: u64,
    /// The filter's mask bits.
    pub mask_bits: u64,
    /// The filter's group.
    pub group_index: i32,
    /// m/s: 2.4's restitution threshold; NaN for an engine that has none.
    pub restitution_threshold: f32,
    /// The v3 chain a segment belongs to (any number the chain's segments share, they stand
    /// one after another), `B2S_NONE` for a shape of no chain.
    pub chain: u32,
    /// NULL for a shape of the plan's kinds; else what the engine's shape is, for the report
    /// that it has no form ("a capsule"), and `shape` is not read.
    pub other: Str,
    /// The fixture's Name and UserData.
    pub label: HeldLabel,
    /// The shape's Name, or NULL.
    pub shape_name: Str,
}

/// One joint as the engine holds it. `joint` is read as the plan's, but:
/// - `joint.joint`: the scene joint it was built from, `B2S_NONE` for one of the host's;
/// - `joint.body_a`, `joint.body_b`: held bodies (indices of the capture's bodies),
///   `B2S_NONE` for a body not held;
/// - `joint.joint_a`, `joint.joint_b`: a gear's held joints;
/// - every field as its getter gives it, the limits and spring flags of every kind too
///   (v3: `enable_spring` of a revolute, prismatic, distance and wheel joint; a distance
///   joint's `min_length` and `max_length`, `enable_limit` and `enable_motor`), v3.2 motor
///   joints' spring maxima in `max_force` and `max_torque`, their hertz and damping ratios
///   as `hertz`/`damping_ratio` (angular) and the linear pair here.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeldJoint {
    /// The joint in the plan's terms.
    pub joint: PlanJoint,
    /// Hz: a v3 weld's or v3.2 motor's linear spring.
    pub linear_hertz: f32,
    /// Its damping ratio.
    pub linear_damping_ratio: f32,
    /// m/s: a v3.2 motor joint's driven linear velocity.
    pub linear_velocity: Vec2,
    /// rad/s: its driven angular velocity.
    pub angular_velocity: f32,
    /// N: its velocity drive's maximum force (a v3.2 motor joint).
    pub max_velocity_force: f32,
    /// N m: its velocity drive's maximum torque.
    pub max_velocity_torque: f32,
    /// NULL for a joint of the plan's kinds; else what the engine's joint is, for the
    /// report that it has no form ("a mouse joint"), and `joint` is not read.
    pub other: Str,
    /// Its Name and UserData.
    pub label: HeldLabel,
}

/// What an engine holds of a world, read for a capture: every array in the engine's
/// creation order (a host's subset of bodies, in its order, where the adapter takes one).
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct HeldWorld {
    /// The engine version, a `b2s_engine` number.
    pub engine: u32,
    /// m/s^2: the world's gravity.
    pub gravity: Vec2,
    /// The `body_count` bodies.
    pub bodies: *const HeldBody,
    /// The `shape_count` shapes, each body's a range.
    pub shapes: *const HeldShape,
    /// The point pool the shapes' `points` ranges index.
    pub points: *const Vec2,
    /// The `joint_count` joints.
    pub joints: *const HeldJoint,
    /// The scene joints the build skipped (the engine could not hold them), in the scene's
    /// order: a capture of a built world writes them back where the file had them.
    pub skipped_joints: *const u32,
    /// Number of items in `bodies`.
    pub body_count: u32,
    /// Number of items in `shapes`.
    pub shape_count: u32,
    /// Number of items in `points`.
    pub point_count: u32,
    /// Number of items in `joints`.
    pub joint_count: u32,
    /// Number of items in `skipped_joints`.
    pub skipped_count: u32,
}
