//! What differs between Box2D v3.1 and v3.2 in what a plan gives them, in one place (the
//! executor's `v31.h` and `v32.h` hold what differs in how it creates it).

use crate::plan::{Engine, WorkingRange};

/// A Box2D v3 version.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum V3 {
    V31,
    V32,
}

impl V3 {
    pub(crate) fn of(engine: Engine) -> Option<V3> {
        match engine {
            Engine::Box2d31 => Some(V3::V31),
            Engine::Box2d32 => Some(V3::V32),
            Engine::Box2d23 | Engine::Box2d24 => None,
        }
    }

    pub(super) fn range(self) -> &'static WorkingRange {
        match self {
            V3::V31 => Engine::Box2d31.working_range(),
            V3::V32 => Engine::Box2d32.working_range(),
        }
    }

    /// The engine as reports name it.
    pub(crate) fn name(self) -> &'static str {
        match self {
            V3::V31 => "Box2D v3",
            V3::V32 => "Box2D v3.2",
        }
    }

    /// Whether a shape's inertia is about the body origin (v3.1), not its centroid (v3.2).
    pub(super) fn inertia_about_origin(self) -> bool {
        self == V3::V31
    }

    /// The fewest points a loop takes: v3.1 asserts 4 in `b2CreateChain`; v3.2's loose
    /// segments make one of 3.
    pub(super) fn min_loop_points(self) -> usize {
        match self {
            V3::V31 => 4,
            V3::V32 => 3,
        }
    }

    /// Whether a chain loses its fixture's sensor flag (v3.1's `b2ChainDef` has none).
    pub(super) fn chain_loses_sensor(self) -> bool {
        self == V3::V31
    }

    /// Whether a kinematic body's mass is computed from its shapes too: v3.2 asserts at the
    /// step unless every body that moves had it computed once.
    pub(super) fn kinematic_mass_update(self) -> bool {
        self == V3::V32
    }

    /// Whether a fixed rotation stops a body's spin (v3.2's motion lock), where 2.x and v3.1
    /// keep the body turning at the rate it starts with.
    pub(super) fn lock_stops_spin(self) -> bool {
        self == V3::V32
    }

    /// Whether joints take local frames (v3.2), not anchors, an axis and a reference angle.
    pub(crate) fn frames(self) -> bool {
        self == V3::V32
    }
}
