//! The records of a plan, as C reads them: every body, shape and joint as one Box2D
//! version's definitions want them, in world terms after the placement, and the reports of
//! what that version cannot hold. An executor creates exactly these, in this order, through
//! its engine's own calls; it converts and checks nothing of its own.

use crate::scene::{Filter, Range, Str, Vec2, u32_enum_conversions};

/// A rotation, as its cosine and sine (Box2D v3's `b2Rot`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Rot {
    /// The cosine of the angle.
    pub c: f32,
    /// The sine of the angle.
    pub s: f32,
}

/// A rigid transform: a rotation about the origin, then a translation (`b2Transform`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Transform {
    /// m: the translation.
    pub p: Vec2,
    /// The rotation.
    pub q: Rot,
}

/// What a plan is made for: the engine version, where the scene is placed, and the world
/// it is built into (its settings, as the host made them).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanOptions {
    /// The engine version, a `b2s_engine` number.
    pub engine: u32,
    /// Where the scene goes: every body's position, rotation and linear velocity is moved
    /// by it. Its rotation must be normalised. `{{0, 0}, {1, 0}}` places nothing.
    pub placement: Transform,
    /// m/s^2: the gravity of the world the plan is built into (the file's, or the host's
    /// fallback); the checks of a body's gravity scale use it.
    pub gravity: Vec2,
    /// m/s: the world's maximum linear speed (v3's `b2World_GetMaximumLinearSpeed`); a
    /// body's faster velocity is reported. `FLT_MAX` where the engine has none.
    pub max_linear_speed: f32,
    /// Bytes: the longest body name the engine build keeps (v3.2's `B2_NAME_LENGTH`, which a
    /// host's build may redefine); 0 takes the working range's `name_bytes`.
    pub name_bytes: u32,
}

/// What a plan shape is, as the engine creates it.
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PlanShapeKind {
    /// `center` and `radius`.
    Circle = 0,
    /// `points`: the vertices the engine's polygon call takes (2.x `b2PolygonShape::Set`);
    /// for v3 the hull itself, `b2ComputeHull`'s counter-clockwise points, which
    /// `b2MakePolygon` takes as a `b2Hull` with radius 0.
    Polygon = 1,
    /// `points`: its two ends; in 2.x also four, `[ghost, ends, ghost]`, for a one-sided
    /// edge (2.4 `SetOneSided`; 2.3 keeps each ghost on its own, NaN for one it has not).
    Segment = 2,
    /// `points`: an open chain, `[ghost, vertices..., ghost]` (2.x `CreateChain` with the
    /// ghosts as previous and next vertices, in 2.3 a ghost NaN where it has none; v3 a
    /// chain whose first and last points only guide).
    Chain = 3,
    /// `points`: a loop, its vertices once each.
    Loop = 4,
}

u32_enum_conversions!(PlanShapeKind { Circle, Polygon, Segment, Chain, Loop });

/// Mass data to give a body after its shapes, in the engine's terms: `inertia` about the
/// body origin in 2.x (`b2MassData::I`), about the centre of mass in v3
/// (`rotationalInertia`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanMass {
    /// kg.
    pub mass: f32,
    /// m, in the body's frame.
    pub center: Vec2,
    /// kg m^2.
    pub inertia: f32,
}

/// One body to create, with its shapes and the mass to give it after them.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanBody {
    /// The scene body it is made from.
    pub body: u32,
    /// A `b2s_body_kind`, equal to the engine's body type.
    pub kind: u32,
    /// m: its origin, placed.
    pub position: Vec2,
    /// rad: its angle, placed (what 2.x takes).
    pub angle: f32,
    /// Its rotation, placed (what v3 takes: the cosine and sine of the file's angle, turned
    /// by the placement's).
    pub rotation: Rot,
    /// m/s: its origin's velocity, placed.
    pub linear_velocity: Vec2,
    /// rad/s.
    pub angular_velocity: f32,
    /// 1/s.
    pub linear_damping: f32,
    /// 1/s.
    pub angular_damping: f32,
    /// A multiple of the world's gravity.
    pub gravity_scale: f32,
    /// The name the engine keeps, or NULL where it keeps none (2.x, or a name longer
    /// than it keeps). Owned by the plan.
    pub name: Str,
    /// Its shapes, in the order to create them: a range of the plan's shapes.
    pub shapes: Range,
    /// The mass to give it after its shapes, where `set_mass`. In 2.x, where not, the mass
    /// the engine computes from its shapes (what `b2Body::GetMassData` gives). For v3, a
    /// dynamic body's mass as the engine holds it once made, given or not (what it
    /// computes from the shapes where `set_mass` is false), predicted bit for bit.
    pub mass: PlanMass,
    /// m/s: the linear velocity to give it after its mass, where `set_velocity` (v3's
    /// `b2Body_SetMassData` does not keep the origin's velocity, as 2.x's does).
    pub velocity_after_mass: Vec2,
    /// Whether it may sleep.
    pub allow_sleep: bool,
    /// Whether it starts awake.
    pub awake: bool,
    /// Whether its rotation is fixed (2.x and v3.1 `fixedRotation`, v3.2's angular lock).
    pub fixed_rotation: bool,
    /// Whether it is a bullet.
    pub bullet: bool,
    /// Whether it is enabled (the file's `Active`).
    pub enabled: bool,
    /// Whether the executor computes its mass from its shapes once they are made (v3's
    /// `b2Body_ApplyMassFromShapes`), before `set_mass`.
    pub apply_mass_from_shapes: bool,
    /// Whether the executor gives it `mass` after its shapes.
    pub set_mass: bool,
    /// Whether the executor gives it `velocity_after_mass` after its mass.
    pub set_velocity: bool,
}

/// One shape to create on a body: a fixture of the scene on that body.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanShape {
    /// The entry of the scene's fixture ID pool it is made for (a fixture may serve many
    /// bodies): what the executor's result is indexed by.
    pub slot: u32,
    /// The scene fixture.
    pub fixture: u32,
    /// The scene shape.
    pub shape: u32,
    /// A `b2s_plan_shape_kind`.
    pub kind: u32,
    /// Its points, a range of the plan's point pool (see `b2s_plan_shape_kind`).
    pub points: Range,
    /// m: a circle's centre, in the body's frame; in 2.x a polygon's centroid to keep (the
    /// file's `Centroid`), NaN where the engine keeps its own.
    pub center: Vec2,
    /// m: a circle's radius.
    pub radius: f32,
    /// kg/m^2.
    pub density: f32,
    /// The friction coefficient.
    pub friction: f32,
    /// The restitution.
    pub restitution: f32,
    /// The collision filter.
    pub filter: Filter,
    /// Whether it is a sensor.
    pub is_sensor: bool,
}

/// What a plan joint is, as the engine creates it (its def).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PlanJointKind {
    /// `b2RevoluteJointDef`.
    Revolute = 0,
    /// `b2PrismaticJointDef`.
    Prismatic = 1,
    /// `b2DistanceJointDef` (v3 also a rope: a spring of 0 Hz with its upper limit on).
    Distance = 2,
    /// `b2PulleyJointDef` (2.x).
    Pulley = 3,
    /// `b2GearJointDef` (2.x): `joint_a` and `joint_b` are plan joints made before it.
    Gear = 4,
    /// `b2WheelJointDef` (also a line joint).
    Wheel = 5,
    /// `b2WeldJointDef`.
    Weld = 6,
    /// `b2FrictionJointDef` (2.x); in v3 a `b2MotorJointDef` that drives no velocity, with
    /// `max_force` and `max_torque` (v3.2: its velocity limits, at its frames).
    Friction = 7,
    /// `b2MotorJointDef` (v3.2: springs of `hertz` and `damping_ratio` limited to
    /// `max_force` and `max_torque`, frame A at the offsets).
    Motor = 8,
    /// `b2RopeJointDef` (Box2D 2.3).
    Rope = 9,
}

u32_enum_conversions!(PlanJointKind {
    Revolute,
    Prismatic,
    Distance,
    Pulley,
    Gear,
    Wheel,
    Weld,
    Friction,
    Motor,
    Rope
});

/// One joint to create, every field its kind's def has in the engine version, in its units.
/// Fields a kind has not are 0.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PlanJoint {
    /// The scene joint it is made from; `B2S_NONE` for one the plan adds to the one before
    /// it (2.x: a rope holding a pulley's side, from a static body).
    pub joint: u32,
    /// A `b2s_plan_joint_kind`.
    pub kind: u32,
    /// The scene body A: the plan's body of that scene index.
    pub body_a: u32,
    /// The scene body B.
    pub body_b: u32,
    /// Gear: the plan joints (indices into the plan's joints) it couples.
    pub joint_a: u32,
    /// Gear: the second.
    pub joint_b: u32,
    /// m: the anchor on body A, in its frame (2.x and v3.1 `localAnchorA`).
    pub anchor_a: Vec2,
    /// m: the anchor on body B (`localAnchorB`).
    pub anchor_b: Vec2,
    /// The unit axis in body A's frame (`localAxisA`).
    pub axis: Vec2,
    /// rad (`referenceAngle`).
    pub reference_angle: f32,
    /// Body A's local frame (v3.2 `localFrameA`).
    pub frame_a: Transform,
    /// Body B's local frame (v3.2 `localFrameB`).
    pub frame_b: Transform,
    /// m: a pulley's ground anchors, in world terms, placed.
    pub ground_anchor_a: Vec2,
    /// m.
    pub ground_anchor_b: Vec2,
    /// m: a pulley's lengths.
    pub length_a: f32,
    /// m.
    pub length_b: f32,
    /// A pulley's or gear's ratio.
    pub ratio: f32,
    /// m or rad: the limits (`lowerAngle`/`lowerTranslation`, ...).
    pub lower: f32,
    /// m or rad.
    pub upper: f32,
    /// m: a distance joint's length (a 2.3 rope's `maxLength`).
    pub length: f32,
    /// m: a distance joint's shortest and longest lengths.
    pub min_length: f32,
    /// m.
    pub max_length: f32,
    /// m/s or rad/s.
    pub motor_speed: f32,
    /// N or N m: the motor's force or torque.
    pub max_motor: f32,
    /// 2.x spring: N/m or N m/rad.
    pub stiffness: f32,
    /// 2.x spring: N s/m or N m s/rad.
    pub damping: f32,
    /// v3 spring: Hz (weld: angular; motor: linear and angular).
    pub hertz: f32,
    /// v3 spring: the damping ratio.
    pub damping_ratio: f32,
    /// m: a motor joint's linear offset (2.x and v3.1).
    pub linear_offset: Vec2,
    /// rad: its angular offset.
    pub angular_offset: f32,
    /// N: a friction or motor joint's force maximum.
    pub max_force: f32,
    /// N m: its torque maximum.
    pub max_torque: f32,
    /// A motor joint's correction factor.
    pub correction_factor: f32,
    /// Whether the bodies collide.
    pub collide_connected: bool,
    /// Whether the limit is on.
    pub enable_limit: bool,
    /// Whether the motor is on.
    pub enable_motor: bool,
    /// Whether the spring is on (v3).
    pub enable_spring: bool,
}

/// Something of the scene the engine version cannot hold, or holds only approximately.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanReport {
    /// A `b2s_code`: `B2S_CODE_BEYOND_BOX2D_RANGE`, `B2S_CODE_SKIPPED_JOINT`, ...
    pub code: u32,
    /// "shape", "fixture", "body", "joint" or "world" (static storage).
    pub object: Str,
    /// The object's index in the scene's array of its kind.
    pub index: u32,
    /// The object's Name, or NULL. Owned by the plan.
    pub name: Str,
    /// What happened, for a level designer. Owned by the plan.
    pub message: Str,
}

/// A read-only view of a plan: a pointer and a count per array. Valid until the plan is
/// freed; the plan needs nothing of the scene it was made from.
#[repr(C)]
#[derive(Clone, Copy, Debug)]
pub struct PlanView {
    /// The `body_count` bodies, in the order to create them.
    pub bodies: *const PlanBody,
    /// The `shape_count` shapes, each body's a range.
    pub shapes: *const PlanShape,
    /// The point pool the shapes' `points` ranges index.
    pub points: *const Vec2,
    /// The `joint_count` joints, in the order to create them, after every body.
    pub joints: *const PlanJoint,
    /// The reports, in the order the plan met them.
    pub reports: *const PlanReport,
    /// Number of items in `bodies`.
    pub body_count: u32,
    /// Number of items in `shapes`.
    pub shape_count: u32,
    /// Number of items in `points`.
    pub point_count: u32,
    /// Number of items in `joints`.
    pub joint_count: u32,
    /// Number of items in `reports`.
    pub report_count: u32,
    /// Whether the placement was usable; when false the plan holds nothing but its report.
    pub placed: bool,
}
