//! The working range of each Box2D version: the bounds past which an executor leaves an
//! object out and reports it `beyond-box2d-range`. Every number here was set by a
//! measurement, which `docs/working-range.md` gives bound by bound.

use crate::scene::u32_enum_conversions;

/// A Box2D version a plan is made for.
#[repr(u32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Engine {
    /// Box2D 2.3, as pybox2d holds it.
    Box2d23 = 1,
    /// Box2D 2.4 (`<box2scene/box2d.hpp>`).
    Box2d24 = 2,
    /// Box2D v3.1 (`<box2scene/box2d3.h>`, and pyb2d3, built on v3.1.1).
    Box2d31 = 3,
    /// Box2D v3.2 (`<box2scene/box2d32.h>`).
    Box2d32 = 4,
}

impl Engine {
    /// Every engine version, in the order of their numbers. Rust only: C has the
    /// `B2S_ENGINE_*` constants.
    ///
    /// cbindgen:ignore
    pub const ALL: [Engine; 4] =
        [Engine::Box2d23, Engine::Box2d24, Engine::Box2d31, Engine::Box2d32];

    /// Its working range.
    pub fn working_range(self) -> &'static WorkingRange {
        match self {
            Engine::Box2d23 => &BOX2D_23,
            Engine::Box2d24 => &BOX2D_24,
            Engine::Box2d31 => &BOX2D_31,
            Engine::Box2d32 => &BOX2D_32,
        }
    }
}

u32_enum_conversions!(Engine { Box2d23, Box2d24, Box2d31, Box2d32 });

/// The bounds an executor checks before it hands a value to one Box2D version. A value
/// beyond its bound leaves its object out (`beyond-box2d-range`), and what depends on it
/// (`skipped-dependent`). `FLT_MAX` is no bound: the version needs none there. Static
/// storage, never freed.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorkingRange {
    /// m, each component: positions, vertices, radii, anchors, lengths, limits, offsets.
    pub max_length: f32,
    /// rad: angles, angle limits, reference angles and offsets.
    pub max_angle: f32,
    /// m/s and rad/s, each component: velocities and motor speeds.
    pub max_speed: f32,
    /// m/s^2, each component: the gravity, and a body's gravity scale times it.
    pub max_acceleration: f32,
    /// A body's multiple of the gravity.
    pub max_gravity_scale: f32,
    /// 1/s: linear and angular damping.
    pub max_damping: f32,
    /// kg/m^2.
    pub max_density: f32,
    /// Friction coefficients and restitution.
    pub max_friction: f32,
    /// Pulley and gear ratios.
    pub max_ratio: f32,
    /// Hz, and damping ratios, of springs (and a motor joint's CorrectionFactor).
    pub max_frequency: f32,
    /// N/m or N m/rad: the softest spring the executor makes, unless 0 (rigid); 0 where
    /// the version needs no such bound.
    pub min_stiffness: f32,
    /// N and N m: force and torque maxima.
    pub max_force: f32,
    /// m: the shortest joint axis the version normalises.
    pub min_axis: f32,
    /// kg: a dynamic body's mass, unless 0.
    pub min_mass: f32,
    /// kg.
    pub max_mass: f32,
    /// kg m^2: a dynamic body's inertia about its centre of mass, unless 0.
    pub min_inertia: f32,
    /// kg m^2.
    pub max_inertia: f32,
    /// 1/kg: 1/m + r^2/I of a body at a joint's anchor (r from its centre of mass).
    pub max_compliance: f32,
    /// Radii of gyration sqrt(I/m): how far from its body's centre of mass a revolute
    /// joint may act (in 2.x also a friction or motor joint, which solve the same 2x2
    /// matrix).
    pub max_lever_revolute: f32,
    /// Radii of gyration: how far every other joint with anchors may act (in 2.x only the
    /// prismatic and weld joints, which invert 3x3 matrices; their other kinds solve row by
    /// row and have no such bound).
    pub max_lever: f32,
    /// Radii of gyration: how far a line or wheel joint may act on a body when its other
    /// body does not turn (static, kinematic, or with fixed rotation).
    pub max_lever_fixed_wheel: f32,
    /// m: how far from satisfied a joint may start on a body that another joint starting
    /// that far already pulls (the first is built, the later ones are not).
    pub max_pulled_violation: f32,
    /// m: how far from satisfied any joint but a line or wheel joint may start, whatever
    /// else acts on its bodies.
    pub max_violation: f32,
    /// m: how far from satisfied a line or wheel joint may start that turns a body as it
    /// pulls it onto its axis: one whose body A is dynamic (the axis turns with it), or one
    /// that acts on a dynamic body B beyond `max_lever_violated_wheel`.
    pub max_wheel_violation: f32,
    /// Radii of gyration: how far apart across its axis the anchors of a line or wheel joint
    /// whose body A is dynamic may start (the axis turns with body A), counted in radii of
    /// the smaller dynamic body: of the smaller of the two where body B is dynamic too, of
    /// body A where body B does not move.
    pub max_wheel_violation_gyrations: f32,
    /// m/s^2: what a joint's motor or friction force may give either of its dynamic bodies.
    pub max_joint_acceleration: f32,
    /// m/s: the maximum linear speed the executor gives the world (above `max_speed`, with
    /// room for gravity); `FLT_MAX` where the version has no such setting.
    pub world_max_linear_speed: f32,
    /// m: the engine's linear slop (2.x `b2_linearSlop` in `b2_settings.h`, v3
    /// `B2_LINEAR_SLOP` in its private `constants.h`, at one length unit per metre): v3
    /// refuses a segment no longer than it, and every version raises a distance joint's
    /// length to it.
    pub linear_slop: f32,
    /// rad: the farthest a revolute joint's limit may reach either way (v3 asserts
    /// -0.99 pi <= lower and upper <= 0.99 pi, `b2CreateRevoluteJoint`; v3.2 even when the
    /// limit is off); the executor clamps a limit to it. `FLT_MAX` where the version has no
    /// such bound.
    pub max_revolute_limit: f32,
    /// m: how far a polygon's Centroid may lie from the one the engine computes before the
    /// executor reports it lost (a hundredth of v3's linear slop: float noise of
    /// `b2ComputeHull`, not a different centroid). `FLT_MAX` where the executor does not
    /// compare them.
    pub centroid_tolerance: f32,
    /// Bytes: the longest body name the engine keeps (v3.1 `name[32]` in `body.h` with its
    /// NUL; v3.2 `B2_NAME_LENGTH` in `constants.h`, which a host's build may redefine, so
    /// the v3.2 adapter reads that macro itself). 0 where the engine's bodies have no name
    /// (2.x).
    pub name_bytes: u32,
    /// Whether a friction joint acts at its anchors, whose levers then count (else at the
    /// body origins).
    pub friction_at_anchors: bool,
    /// Whether a prismatic joint's lever on body A is measured to body B's anchor too (the
    /// joint's axis reaches it).
    pub prismatic_lever_to_b: bool,
    /// Radii of gyration of the joint's smaller dynamic body: how far a distance joint (a rod
    /// or a rope) between two dynamic bodies may act on one that a revolute or weld joint
    /// holds to a body that does not move (static or kinematic).
    pub max_lever_pinned_distance: f32,
    /// Radii of gyration of body B: how far from its centre of mass a line or wheel joint on
    /// a body A that does not move (static or kinematic) may act on a dynamic body B and start
    /// further than `max_wheel_violation` from satisfied (nearer, such a joint is not bounded
    /// by it). `FLT_MAX` where the version needs no such bound.
    pub max_lever_violated_wheel: f32,
}

impl WorkingRange {
    /// Every numeric bound by its field's name, in the order of the fields (for the Python
    /// extension and the docs' table).
    pub fn bounds(&self) -> [(&'static str, f32); 32] {
        [
            ("max_length", self.max_length),
            ("max_angle", self.max_angle),
            ("max_speed", self.max_speed),
            ("max_acceleration", self.max_acceleration),
            ("max_gravity_scale", self.max_gravity_scale),
            ("max_damping", self.max_damping),
            ("max_density", self.max_density),
            ("max_friction", self.max_friction),
            ("max_ratio", self.max_ratio),
            ("max_frequency", self.max_frequency),
            ("min_stiffness", self.min_stiffness),
            ("max_force", self.max_force),
            ("min_axis", self.min_axis),
            ("min_mass", self.min_mass),
            ("max_mass", self.max_mass),
            ("min_inertia", self.min_inertia),
            ("max_inertia", self.max_inertia),
            ("max_compliance", self.max_compliance),
            ("max_lever_revolute", self.max_lever_revolute),
            ("max_lever", self.max_lever),
            ("max_lever_fixed_wheel", self.max_lever_fixed_wheel),
            ("max_pulled_violation", self.max_pulled_violation),
            ("max_violation", self.max_violation),
            ("max_wheel_violation", self.max_wheel_violation),
            ("max_wheel_violation_gyrations", self.max_wheel_violation_gyrations),
            ("max_joint_acceleration", self.max_joint_acceleration),
            ("world_max_linear_speed", self.world_max_linear_speed),
            ("linear_slop", self.linear_slop),
            ("max_revolute_limit", self.max_revolute_limit),
            ("centroid_tolerance", self.centroid_tolerance),
            ("max_lever_pinned_distance", self.max_lever_pinned_distance),
            ("max_lever_violated_wheel", self.max_lever_violated_wheel),
        ]
    }
}

/// The ABI is pinned: 30 floats, a count, two flags and two floats added since, also asserted
/// on the C++ side.
const _: () = {
    use std::mem::{offset_of, size_of};
    assert!(offset_of!(WorkingRange, max_violation) == 88);
    assert!(offset_of!(WorkingRange, world_max_linear_speed) == 104);
    assert!(offset_of!(WorkingRange, linear_slop) == 108);
    assert!(offset_of!(WorkingRange, max_revolute_limit) == 112);
    assert!(offset_of!(WorkingRange, centroid_tolerance) == 116);
    assert!(offset_of!(WorkingRange, name_bytes) == 120);
    assert!(offset_of!(WorkingRange, friction_at_anchors) == 124);
    assert!(offset_of!(WorkingRange, prismatic_lever_to_b) == 125);
    assert!(offset_of!(WorkingRange, max_lever_pinned_distance) == 128);
    assert!(offset_of!(WorkingRange, max_lever_violated_wheel) == 132);
    assert!(size_of::<WorkingRange>() == 136);
};

/// No bound.
const NONE: f32 = f32::MAX;

/// pi as Box2D writes it (`b2_pi`, v3 `B2_PI`), rounded to a float.
pub(in crate::plan) const PI: f32 = 3.14159265359;

/// The linear slop of every version: 2.x's `b2_linearSlop` and v3's `B2_LINEAR_SLOP`.
const LINEAR_SLOP: f32 = 0.005;

/// Box2D 2.4.1, as `c_tests/range_sweep_test.cpp` and `finite_worlds_test.cpp` measured it,
/// and the dialect fixtures' weld 8.4 m from satisfied, which goes NaN among other joints.
const BOX2D_24: WorkingRange = WorkingRange {
    max_length: 1e5,
    max_angle: 1e5,
    max_speed: 1e3,
    max_acceleration: 1e3,
    max_gravity_scale: 1e3,
    max_damping: 1e5,
    max_density: 1e5,
    max_friction: 1e5,
    max_ratio: 1e5,
    max_frequency: 1e3,
    min_stiffness: 1e-20,
    max_force: 1e20,
    min_axis: 1e-6,
    min_mass: 1e-20,
    max_mass: 1e10,
    min_inertia: 1e-12,
    max_inertia: 1e12,
    max_compliance: 1e12,
    max_lever_revolute: 1e3,
    max_lever: 75.0,
    max_lever_fixed_wheel: NONE,
    max_pulled_violation: 0.5,
    max_violation: 4.0,
    max_wheel_violation: NONE,
    max_wheel_violation_gyrations: NONE,
    max_joint_acceleration: NONE,
    world_max_linear_speed: NONE,
    linear_slop: LINEAR_SLOP,
    max_revolute_limit: NONE,
    centroid_tolerance: NONE,
    name_bytes: 0,
    friction_at_anchors: true,
    prismatic_lever_to_b: true,
    max_lever_pinned_distance: NONE,
    max_lever_violated_wheel: NONE,
};

/// Box2D 2.3 as pybox2d holds it: 2.4's solver, whose measurements it shares.
const BOX2D_23: WorkingRange = BOX2D_24;

/// Box2D v3.1.1, as `c_tests/v3_range_sweep_test.c` and the v3 stress test measured it, the
/// levels that asserted (the dialect fixtures and the bench's generated level: one joint
/// started far from satisfied is enough, once other joints or contacts act on its bodies),
/// and line and wheel joints built by hand (`docs/working-range.md`).
const BOX2D_31: WorkingRange = WorkingRange {
    max_length: 1e4,
    max_ratio: NONE,
    max_pulled_violation: NONE,
    max_violation: 0.5,
    min_stiffness: 0.0,
    max_lever_fixed_wheel: 3.0,
    max_lever_pinned_distance: 2.5,
    max_wheel_violation: 0.5,
    max_lever_violated_wheel: 2.0,
    max_wheel_violation_gyrations: 2.4,
    max_joint_acceleration: 1e5,
    world_max_linear_speed: 1.5e3,
    max_revolute_limit: 0.99 * PI,
    centroid_tolerance: 0.01 * LINEAR_SLOP,
    name_bytes: 31,
    friction_at_anchors: false,
    ..BOX2D_24
};

/// Box2D v3.2, as `c_tests/v3_range_sweep_test.c` and `c_tests/box2d32_working_range_test.c`
/// measured it: v3.1's levers and smallest inertia (v3.2 dies of the same levels), but for the
/// two bounds of line and wheel joints that v3.1 was measured lower by hand and v3.2 was not
/// (`max_lever_fixed_wheel`, `max_wheel_violation_gyrations`). It holds
/// joints started further from satisfied than v3.1 does: the bench's 10,000-body level holds
/// with every joint up to 8 m off, and asserts from 16 m; the dialect fixtures' weld 8.4 m off
/// asserts.
const BOX2D_32: WorkingRange = WorkingRange {
    max_violation: 4.0,
    max_lever_fixed_wheel: 5.0,
    max_wheel_violation: NONE,
    max_lever_violated_wheel: NONE,
    max_wheel_violation_gyrations: 4.0,
    max_lever_pinned_distance: 7.0,
    name_bytes: 10,
    friction_at_anchors: true,
    ..BOX2D_31
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_engine_number_names_its_engine() {
        for engine in Engine::ALL {
            assert_eq!(Engine::try_from(engine as u32), Ok(engine));
        }
        assert_eq!(Engine::try_from(0), Err(0));
        assert_eq!(Engine::try_from(5), Err(5));
    }

    #[test]
    fn v3_bounds_lengths_ten_times_tighter_than_2x() {
        assert_eq!(Engine::Box2d24.working_range().max_length, 1e5);
        assert_eq!(Engine::Box2d23.working_range().max_length, 1e5);
        assert_eq!(Engine::Box2d31.working_range().max_length, 1e4);
        assert_eq!(Engine::Box2d32.working_range().max_length, 1e4);
    }

    #[test]
    fn v3_engine_facts_are_the_float_products_the_adapters_had() {
        for engine in [Engine::Box2d31, Engine::Box2d32] {
            let r = engine.working_range();
            assert_eq!(r.linear_slop.to_bits(), 0.005f32.to_bits());
            assert_eq!(r.max_revolute_limit.to_bits(), 0x4047_0D23);
            assert_eq!(r.centroid_tolerance.to_bits(), 0x3851_B717);
        }
        assert_eq!(Engine::Box2d31.working_range().name_bytes, 31);
        assert_eq!(Engine::Box2d32.working_range().name_bytes, 10);
        assert_eq!(Engine::Box2d24.working_range().max_revolute_limit, f32::MAX);
    }
}
