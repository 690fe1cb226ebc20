//! The plan for Box2D v3.1 and v3.2: every shape, body and joint of a scene as the
//! version's definitions take them, placed, with the working range checked and the mass of
//! every dynamic body predicted bit for bit, and the reports of what the version cannot
//! hold, in the order the executor always made them: the world, the shapes, the bodies with
//! their fixtures, then the joints (whose checks need every body's final mass).

pub(crate) mod bodies;
pub(crate) mod geometry;
mod hull;
mod joint_checks;
pub(crate) mod joints;
pub(crate) mod mass;
pub(crate) mod math;
mod shapes;
#[cfg(test)]
mod test_support;
mod version;

use std::fmt;

use self::geometry::Mass;
use self::math::transform_point;
use self::shapes::Geometry;
pub(crate) use self::version::V3;
use super::container::{Object, Plan};
use super::gravity::gravity_fits;
use super::printf::{G, G9};
use super::range::WorkingRange;
use super::records::{PlanOptions, Rot, Transform};
use crate::error::Code;
use crate::scene::{Scene, Str, Vec2};

/// A body the plan creates, as the joints' checks and defs see it once made.
#[derive(Clone, Copy, Debug)]
struct Created {
    kind: u32,
    transform: Transform,
    /// Its final mass: a dynamic body's, else none.
    mass: Mass,
    /// rad/s: its angular velocity as created (0 unless it starts awake).
    angular_velocity: f32,
    fixed_rotation: bool,
}

struct Mapper<'a> {
    scene: &'a Scene,
    options: &'a PlanOptions,
    v3: V3,
    range: &'static WorkingRange,
    plan: Plan,
    /// Per scene shape: what it was made into, or `None` (reported).
    geometries: Vec<Option<Geometry>>,
    /// Per scene body: what was created of it.
    created: Vec<Option<Created>>,
    /// Per scene body: 1 + the joint that starts it pulled far from satisfied, or 0.
    pulled: Vec<u32>,
    /// Per scene body: the first line or wheel joint planned from it (as body A) to a body
    /// that does not turn, and how far (m) its anchors start apart across its axis.
    railed: Vec<Option<(u32, f32)>>,
    /// Per scene body: whether it is a dynamic body that a revolute or weld joint of the
    /// scene holds to a body that does not move.
    pinned: Vec<bool>,
}

/// The plan of `scene` for a v3 version.
pub(super) fn plan(scene: &Scene, options: &PlanOptions, v3: V3) -> Plan {
    let mut m = Mapper {
        scene,
        options,
        v3,
        range: v3.range(),
        plan: Plan::with_capacity(
            scene.bodies().len(),
            scene.fixture_id_pool().len(),
            scene.joints().len(),
        ),
        geometries: vec![None; scene.shapes().len()],
        created: vec![None; scene.bodies().len()],
        pulled: vec![0; scene.bodies().len()],
        railed: vec![None; scene.bodies().len()],
        pinned: vec![false; scene.bodies().len()],
    };
    if !m.placement_valid() {
        let t = options.placement;
        m.report(
            Code::InvalidArgument,
            Object::World,
            0,
            Str::NULL,
            format_args!(
                "the placement ({}, {}) turned by ({}, {}) is not finite, not within +-{} m or \
                 not a normalised rotation; nothing was built",
                G9(t.p.x),
                G9(t.p.y),
                G9(t.q.c),
                G9(t.q.s),
                G(m.range.max_length)
            ),
        );
        m.plan.set_unplaced();
        return m.plan;
    }
    m.check_gravity();
    for index in 0..scene.shapes().len() {
        m.make_shape(index as u32);
    }
    for index in 0..scene.bodies().len() {
        m.make_body(index as u32);
    }
    m.find_pinned();
    for index in 0..scene.joints().len() {
        m.make_joint(index as u32);
    }
    m.plan
}

impl Mapper<'_> {
    /// A report about a scene object named by the scene's `name`.
    fn report(
        &mut self,
        code: Code,
        object: Object,
        index: u32,
        name: Str,
        message: fmt::Arguments<'_>,
    ) {
        let name = self.scene.text(name);
        self.plan.report(code, object, index, name, message);
    }

    /// An object left out for a value beyond the working range.
    fn beyond(&mut self, problem: &str, object: Object, index: u32, name: Str, owner: &str) {
        let what = object.name().to_str().expect("object names are ASCII");
        self.report(
            Code::BeyondBox2dRange,
            object,
            index,
            name,
            format_args!("{owner}{problem}; {what} not created"),
        );
    }

    /// A placement v3 can take: finite, within the working range, its rotation normalised
    /// as `b2CreateBody` asserts.
    fn placement_valid(&self) -> bool {
        let Transform { p, q: Rot { c, s } } = self.options.placement;
        let qq = c * c + s * s;
        let bound = self.range.max_length;
        p.x.is_finite()
            && p.y.is_finite()
            && c.is_finite()
            && s.is_finite()
            && (qq - 1.0).abs() < 1e-4
            && p.x.abs() <= bound
            && p.y.abs() <= bound
    }

    fn check_gravity(&mut self) {
        let Some(g) = self.scene.gravity() else { return };
        if !gravity_fits(self.range, g) {
            let (name, bound) = (self.v3.name(), self.range.max_acceleration);
            self.report(
                Code::BeyondBox2dRange,
                Object::World,
                0,
                Str::NULL,
                format_args!(
                    "Gravity ({}, {}) lies beyond {name}'s working range (each component within \
                     +-{} m/s^2); the world def gives the host's fallback instead",
                    G9(g.x),
                    G9(g.y),
                    G(bound)
                ),
            );
        }
    }

    /// A body's origin placed.
    fn placed(&self, position: Vec2) -> Vec2 {
        transform_point(self.options.placement, position)
    }
}

#[cfg(test)]
mod tests {
    use super::test_support::{IDENTITY, messages, options};
    use super::*;
    use crate::plan::{Engine, PlanShapeKind, make};

    const SCENE: &[u8] = br#"<World Version="2"><Gravity>0 -10</Gravity><Shapes>
<Shape Type="Polygon"><Vertices><Vertex>-1 -1</Vertex><Vertex>1 -1</Vertex><Vertex>1 1</Vertex><Vertex>-1 1</Vertex></Vertices></Shape>
<Shape Type="Chain"><Vertices><Vertex>0 0</Vertex><Vertex>1 0</Vertex><Vertex>2 0</Vertex></Vertices></Shape>
</Shapes><Fixtures><Fixture><Shape>0</Shape><Density>2</Density></Fixture><Fixture><Shape>1</Shape><IsSensor>true</IsSensor></Fixture></Fixtures>
<Bodies><Body Type="Dynamic"><Name>box</Name><Position>1 2</Position><LinearDamping>-1</LinearDamping><Fixtures><ID>0</ID><ID>1</ID></Fixtures></Body><Body Type="Static"/></Bodies>
<Joints><Joint Type="Pulley"><BodyA>0</BodyA><BodyB>1</BodyB><Ratio>1</Ratio></Joint></Joints></World>"#;

    #[test]
    fn a_scene_planned_for_each_v3_version() {
        let scene = crate::load(SCENE, &Default::default()).unwrap();
        let plan = make(&scene, &options(Engine::Box2d31, IDENTITY)).unwrap();
        assert_eq!(plan.bodies().len(), 2);
        let body = plan.bodies()[0];
        assert_eq!((body.position, body.linear_damping), (Vec2 { x: 1.0, y: 2.0 }, 0.0));
        assert_eq!(plan.text(body.name), Some("box"));
        assert_eq!(body.mass.mass, 8.0);
        assert!(body.apply_mass_from_shapes && !body.set_mass);
        let shapes = plan.shapes();
        assert_eq!(shapes.len(), 2);
        assert_eq!(shapes[0].kind, PlanShapeKind::Polygon as u32);
        assert_eq!(plan.points(&shapes[0]).len(), 4);
        // v3.1's chains cannot be sensors: [ghost, 3 vertices, ghost], made solid.
        assert_eq!(shapes[1].kind, PlanShapeKind::Chain as u32);
        assert_eq!(plan.points(&shapes[1]).len(), 5);
        assert!(!shapes[1].is_sensor);
        assert_eq!(
            messages(&plan),
            [
                (
                    Code::LossyShape as u32,
                    "shape",
                    1,
                    "Box2D v3's chain segments need a ghost vertex at each end: both ghost \
                     vertices extrapolated along the end segment"
                ),
                (
                    Code::NegativeValue as u32,
                    "body",
                    0,
                    "LinearDamping -1 is negative, which Box2D v3 does not allow; 0 was used"
                ),
                (
                    Code::LossyShape as u32,
                    "fixture",
                    1,
                    "fixture 1 of body 0 is a sensor, but Box2D v3's chains have no sensor \
                     form; it was made a solid chain"
                ),
                (
                    Code::SkippedJoint as u32,
                    "joint",
                    0,
                    "Box2D v3 has no form for a pulley joint; joint skipped"
                ),
            ]
        );
        let plan = make(&scene, &options(Engine::Box2d32, IDENTITY)).unwrap();
        assert!(plan.shapes()[1].is_sensor, "v3.2's loose segments take the flag");
        assert_eq!(plan.reports().len(), 3);
        assert!(plan.text(plan.reports()[2].message).unwrap().starts_with("Box2D v3.2 has"));
    }

    #[test]
    fn a_placement_v3_cannot_take_plans_only_its_report() {
        let scene = crate::load(SCENE, &Default::default()).unwrap();
        let bad = Transform { p: Vec2 { x: 1.0, y: f32::NAN }, q: Rot { c: 1.0, s: 0.0 } };
        let plan = make(&scene, &options(Engine::Box2d31, bad)).unwrap();
        assert!(!plan.placed());
        assert!(plan.bodies().is_empty() && plan.shapes().is_empty());
        assert_eq!(
            messages(&plan),
            [(
                Code::InvalidArgument as u32,
                "world",
                0,
                "the placement (1, nan) turned by (1, 0) is not finite, not within +-10000 m or \
                 not a normalised rotation; nothing was built"
            )]
        );
    }

    #[test]
    fn a_plan_outlives_its_scene() {
        let scene = crate::load(SCENE, &Default::default()).unwrap();
        let plan = make(&scene, &options(Engine::Box2d32, IDENTITY)).unwrap();
        drop(scene);
        assert_eq!(plan.text(plan.bodies()[0].name), Some("box"));
        assert_eq!(plan.text(plan.reports()[0].name), None);
    }
}
