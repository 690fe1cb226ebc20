//! What Box2D 2.3 (as pybox2d holds it) and Box2D 2.4 do differently, in one place: the
//! rest of `box2d2/` is what both do.

use crate::plan::range::Engine;

/// Where `b2PolygonShape::ComputeMass` fans its triangles from: the arithmetic, and so
/// the predicted bits, depend on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum PolygonReference {
    /// 2.3: the mean of the vertices.
    Mean,
    /// 2.4: the first vertex.
    First,
}

/// One 2.x version's differences.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Version {
    pub engine: Engine,
    /// How the reports name it.
    pub name: &'static str,
    pub polygon_reference: PolygonReference,
    /// 2.3's `ResetMassData` gives a dynamic body without mass 1 kg; 2.4's leaves it 0.
    pub massless_weighs_one_kg: bool,
    /// 2.3's distance, wheel and weld defs take `frequencyHz` and `dampingRatio` (the plan's
    /// `hertz` and `damping_ratio`); 2.4's a stiffness and damping the plan computes.
    pub springs_in_hertz: bool,
    /// 2.3 has a rope joint; 2.4 a distance joint slack up to its length, whose upper
    /// length `FLT_MAX` a spring turns into 0 * infinity between bodies without mass.
    pub rope_joint: bool,
    /// 2.4's wheel joint has a translation limit (a line joint's); 2.3's has none.
    pub wheel_limit: bool,
    /// Hz: 2.3's wheel joint without a spring reads its lever arms before it computes them
    /// (`b2WheelJoint::InitVelocityConstraints` computes them only for a spring, and warm
    /// starting multiplies them by 0), so whatever the memory held, NaN included, goes into
    /// the bodies: a spring this soft, undamped, stands in for none. 0 where none is needed.
    pub springless_wheel_hertz: f32,
    /// 2.3 keeps an edge's and an open chain's ghost vertices each on its own (`hasVertex0`,
    /// `SetPrevVertex`); 2.4 needs both (`SetOneSided`, `CreateChain`), so a missing one is
    /// extrapolated, or an edge with one left two-sided.
    pub ghosts_on_their_own: bool,
    /// pybox2d's builder has always left out a body whose MassData leaves no positive
    /// inertia about its centre of mass (2.3 asserts against it); 2.4's keeps the mass of
    /// its fixtures instead, and reports it.
    pub refuses_inconsistent_mass: bool,
    /// 2.3's builder gives a dynamic body its origin's velocity again once the mass is
    /// final (each fixture's `ResetMassData` moves it by w x the centre's shift); 2.4's
    /// adapter keeps what the engine made of it.
    pub velocity_after_mass: bool,
    /// What asserts against a prismatic joint's disabled limit with its lower translation
    /// above its upper: 2.4's joint as it is created, 2.3's only `SetLimits` (a host that
    /// sets them later), so the plan passes them swapped in both.
    pub inverted_limit_asserted_by: &'static str,
}

pub(crate) const BOX2D_23: Version = Version {
    engine: Engine::Box2d23,
    name: "Box2D 2.3",
    polygon_reference: PolygonReference::Mean,
    massless_weighs_one_kg: true,
    springs_in_hertz: true,
    rope_joint: true,
    wheel_limit: false,
    springless_wheel_hertz: 1e-3,
    ghosts_on_their_own: true,
    refuses_inconsistent_mass: true,
    velocity_after_mass: true,
    inverted_limit_asserted_by: "Box2D 2.3's SetLimits",
};

pub(crate) const BOX2D_24: Version = Version {
    engine: Engine::Box2d24,
    name: "Box2D 2.4",
    polygon_reference: PolygonReference::First,
    massless_weighs_one_kg: false,
    springs_in_hertz: false,
    rope_joint: false,
    wheel_limit: true,
    springless_wheel_hertz: 0.0,
    ghosts_on_their_own: false,
    refuses_inconsistent_mass: false,
    velocity_after_mass: false,
    inverted_limit_asserted_by: "Box2D 2.4",
};

impl Version {
    /// The version of `engine`, where it is a 2.x one.
    pub(crate) fn of(engine: Engine) -> Option<&'static Version> {
        match engine {
            Engine::Box2d23 => Some(&BOX2D_23),
            Engine::Box2d24 => Some(&BOX2D_24),
            _ => None,
        }
    }
}
