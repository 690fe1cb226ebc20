//! Bodies: the checks, the body def placed, its fixtures, and the mass the executor gives
//! it once its shapes are made.

use super::geometry::Mass;
use super::mass::{self, ShapeMass};
use super::math::{add, cross_sv, length, mul_rot, mul_sv, rotate, rotation, sub, transform_point};
use super::{Created, Mapper};
use crate::error::Code;
use crate::plan::check::Check;
use crate::plan::container::Object;
use crate::plan::printf::{G, G9};
use crate::plan::range::PI;
use crate::plan::records::{PlanBody, PlanMass, Transform};
use crate::scene::{Body, BodyKind, Range, Str, Vec2};

impl Mapper<'_> {
    pub(super) fn make_body(&mut self, index: u32) {
        let body = &self.scene.bodies()[index as usize];
        if body.kind > BodyKind::Dynamic as u32 {
            self.report(
                Code::UnknownType,
                Object::Body,
                index,
                body.name,
                format_args!("unknown body kind {}; body skipped", body.kind),
            );
            self.skip_fixtures_of(index, body);
            return;
        }
        let end = u64::from(body.fixtures.first) + u64::from(body.fixtures.count);
        if end > self.scene.fixture_id_pool().len() as u64 {
            self.report(
                Code::IdOutOfRange,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "its fixture list lies outside the scene's fixture ID pool; body skipped"
                ),
            );
            return;
        }
        let dynamic = body.kind == BodyKind::Dynamic as u32;
        let mut check = self.body_check(body);
        let (mut computed, mut final_mass) = (Mass::default(), Mass::default());
        if dynamic && check.passed() {
            let (c, kept) =
                mass::from_shapes(self.v3, &self.shape_masses(body), body.fixed_rotation);
            (computed, final_mass) = (c, mass::final_mass(c, body));
            mass::check(self.v3, self.range, computed, kept, final_mass, &mut check);
        }
        if !check.passed() {
            self.beyond(check.problem(), Object::Body, index, body.name, "");
            self.skip_fixtures_of(index, body);
            return;
        }
        self.report_losses(index, body);
        let mut planned = self.body_def(index, body);
        let first = self.plan.shape_count();
        for slot in body.fixtures.indices() {
            self.make_fixture(index, slot as u32);
        }
        planned.shapes = Range::between(first, self.plan.shape_count());
        let awake = body.active && (body.awake || !body.allow_sleep);
        if dynamic {
            self.give_mass(&mut planned, body, computed, final_mass, awake);
        }
        self.created[index as usize] = Some(Created {
            kind: body.kind,
            transform: Transform { p: planned.position, q: planned.rotation },
            mass: final_mass,
            angular_velocity: if awake { planned.angular_velocity } else { 0.0 },
            fixed_rotation: body.fixed_rotation,
        });
        self.plan.push_body(planned);
    }

    fn body_check(&self, body: &Body) -> Check {
        let (v3, r) = (self.v3, self.range);
        let mut check = Check::new(v3.name());
        check.vector("Position", body.position, r.max_length, "m");
        check.magnitude("Angle", body.angle, r.max_angle, "rad");
        if body.kind != BodyKind::Static as u32 {
            check.vector("LinearVelocity", body.linear_velocity, r.max_speed, "m/s");
            check.magnitude("AngularVelocity", body.angular_velocity, r.max_speed, "rad/s");
            let limit = self.options.max_linear_speed;
            let v = body.linear_velocity;
            if check.passed() && !(length(v) <= limit) {
                check.fail(format_args!(
                    "LinearVelocity ({}, {}) is faster than the world's maximum linear speed {} \
                     m/s, to which {} would clamp it",
                    G9(v.x),
                    G9(v.y),
                    G(limit),
                    v3.name()
                ));
            }
        }
        check.magnitude("LinearDamping", body.linear_damping, r.max_damping, "1/s");
        check.magnitude("AngularDamping", body.angular_damping, r.max_damping, "1/s");
        check.magnitude("GravityScale", body.gravity_scale, r.max_gravity_scale, "");
        if body.kind == BodyKind::Dynamic as u32 && check.passed() {
            let gravity = mul_sv(body.gravity_scale, self.options.gravity);
            let field = "GravityScale times the world's gravity";
            check.vector(field, gravity, r.max_acceleration, "m/s^2");
        }
        if body.mass_data.center_given {
            check.vector("MassData Center", body.mass_data.center, r.max_length, "m");
        }
        if check.passed() {
            let placed = self.placed(body.position);
            check.vector("its placed Position", placed, r.max_length, "m");
        }
        check
    }

    /// The masses of the shapes a body's fixtures will make, in creation order.
    fn shape_masses(&self, body: &Body) -> Vec<ShapeMass> {
        let ids = self.scene.body_fixtures(body);
        ids.iter()
            .filter_map(|&index| self.creatable(index))
            .map(|(fixture, g)| ShapeMass {
                mass: self.geometry_mass(&g, fixture.density),
                density: fixture.density,
            })
            .collect()
    }

    /// The fixtures of a body that was not created: they depend on it.
    fn skip_fixtures_of(&mut self, index: u32, body: &Body) {
        let pool = self.scene.fixture_id_pool();
        for slot in body.fixtures.indices().take_while(|&slot| slot < pool.len()) {
            let fixture = pool[slot];
            let name = self.scene.fixtures().get(fixture as usize).map_or(Str::NULL, |f| f.name);
            self.report(
                Code::SkippedDependent,
                Object::Fixture,
                fixture,
                name,
                format_args!(
                    "fixture {fixture} of body {index}: the body was not created; fixture \
                     skipped"
                ),
            );
        }
    }

    /// The longest name the engine keeps, in bytes.
    fn name_bytes(&self) -> usize {
        match self.options.name_bytes {
            0 => self.range.name_bytes as usize,
            n => n as usize,
        }
    }

    /// What a body's def cannot say of the file, reported.
    fn report_losses(&mut self, index: u32, body: &Body) {
        let name = self.v3.name();
        if body.angle.abs() > PI {
            self.report(
                Code::LossyCapture,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "{name} keeps a rotation, not an angle: the whole turns of Angle {} are \
                     lost, and a capture writes it within +-pi",
                    G9(body.angle)
                ),
            );
        }
        if self.scene.text(body.name).is_some_and(|n| n.len() > self.name_bytes()) {
            let bytes = self.name_bytes();
            self.report(
                Code::LossyBody,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "its Name is longer than the {bytes} bytes {name} keeps of a name; the body \
                     has none, and a capture writes none"
                ),
            );
        }
        let moves = body.kind != BodyKind::Static as u32;
        if self.v3.lock_stops_spin() && body.fixed_rotation && moves && body.angular_velocity != 0.0
        {
            self.report(
                Code::LossyBody,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "FixedRotation with AngularVelocity {} rad/s: {name}'s motion lock stops the \
                     spin at the first step, where Box2D 2.x and v3.1 keep the body turning at \
                     that rate",
                    G9(body.angular_velocity)
                ),
            );
        }
        if !body.awake && !body.allow_sleep && moves {
            self.report(
                Code::LossyBody,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "Awake false with AllowSleep false: {name} creates such a body awake (Box2D \
                     2.x keeps it asleep until it is touched)"
                ),
            );
        }
    }

    /// v3 asserts against a negative damping, which the format does not forbid.
    fn damping(&mut self, index: u32, body: &Body, value: f32, field: &str) -> f32 {
        if value >= 0.0 {
            return value;
        }
        let name = self.v3.name();
        self.report(
            Code::NegativeValue,
            Object::Body,
            index,
            body.name,
            format_args!(
                "{field} {} is negative, which {name} does not allow; 0 was used",
                G9(value)
            ),
        );
        0.0
    }

    fn body_def(&mut self, index: u32, body: &Body) -> PlanBody {
        let placement = self.options.placement;
        let moves = body.kind != BodyKind::Static as u32;
        let dynamic = body.kind == BodyKind::Dynamic as u32;
        let name = self.scene.text(body.name).filter(|n| n.len() <= self.name_bytes());
        let linear_damping = self.damping(index, body, body.linear_damping, "LinearDamping");
        let angular_damping = self.damping(index, body, body.angular_damping, "AngularDamping");
        PlanBody {
            body: index,
            kind: body.kind,
            position: self.placed(body.position),
            angle: body.angle + placement.q.s.atan2(placement.q.c),
            // b2MakeRot approximates; the rotation of the file's angle is its cosine and sine.
            rotation: mul_rot(placement.q, rotation(body.angle)),
            linear_velocity: if moves {
                rotate(placement.q, body.linear_velocity)
            } else {
                Default::default()
            },
            angular_velocity: if moves { body.angular_velocity } else { 0.0 },
            linear_damping,
            angular_damping,
            gravity_scale: body.gravity_scale,
            name: self.plan.keep(name),
            shapes: Range::default(),
            mass: PlanMass::default(),
            velocity_after_mass: Default::default(),
            allow_sleep: body.allow_sleep,
            awake: body.awake,
            fixed_rotation: body.fixed_rotation,
            bullet: body.bullet,
            enabled: body.active,
            apply_mass_from_shapes: dynamic
                || (body.kind == BodyKind::Kinematic as u32 && self.v3.kinematic_mass_update()),
            set_mass: false,
            set_velocity: false,
        }
    }

    /// The mass the body gets (its prediction, whether given or not), given after v3 has
    /// computed its own (which clears the mark v3
    /// asserts against at the step) where it differs: MassData, a fixed rotation, no mass.
    /// 2.x's SetMassData keeps the origin's velocity when the centre moves; v3's does not, so
    /// a body that starts awake is given it again, as v3 computes it from the origin's.
    fn give_mass(&self, planned: &mut PlanBody, body: &Body, computed: Mass, m: Mass, awake: bool) {
        planned.mass = PlanMass { mass: m.mass, center: m.center, inertia: m.inertia };
        if !mass::given(body) && !body.fixed_rotation && computed.mass > 0.0 {
            return;
        }
        planned.set_mass = true;
        if !awake {
            return;
        }
        let transform = Transform { p: planned.position, q: planned.rotation };
        planned.set_velocity = true;
        planned.velocity_after_mass =
            center_velocity(transform, m.center, planned.angular_velocity, planned.linear_velocity);
    }
}

/// The velocity of a body's centre of mass (`center`, in its frame) as v3 computes it from
/// its origin's: `v + w x (R center)`.
pub(crate) fn center_velocity(transform: Transform, center: Vec2, w: f32, v: Vec2) -> Vec2 {
    let center = transform_point(transform, center);
    add(v, cross_sv(w, sub(center, transform.p)))
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{BALL, messages, plan_of};
    use crate::error::Code;
    use crate::plan::Engine;
    use crate::scene::Vec2;

    #[test]
    fn mass_data_moves_the_centre_and_the_velocity_is_given_again() {
        let (shape, fixture) = BALL;
        let body = "<Body Type=\"Dynamic\"><AngularVelocity>2</AngularVelocity>\
            <LinearVelocity>1 0</LinearVelocity><MassData><Center>0.1 0</Center></MassData>\
            <Fixtures><ID>0</ID></Fixtures></Body>";
        let plan = plan_of(Engine::Box2d31, shape, fixture, body, "");
        let b = plan.bodies()[0];
        assert!(b.set_mass && b.set_velocity);
        assert_eq!(b.mass.center, Vec2 { x: 0.1, y: 0.0 });
        // v = v_origin + w x (centre - origin) = (1, 0) + 2 x (0.1, 0).
        assert_eq!(b.velocity_after_mass, Vec2 { x: 1.0, y: 0.2 });
    }

    #[test]
    fn a_body_asleep_gets_its_mass_but_no_velocity() {
        let (shape, fixture) = BALL;
        let body = "<Body Type=\"Dynamic\"><Awake>false</Awake><FixedRotation>true</FixedRotation>\
            <Fixtures><ID>0</ID></Fixtures></Body>";
        let plan = plan_of(Engine::Box2d32, shape, fixture, body, "");
        let b = plan.bodies()[0];
        assert!(b.set_mass && !b.set_velocity);
        assert_eq!(b.mass.inertia, 0.0);
    }

    #[test]
    fn a_fixed_rotation_spin_is_lost_in_v32_only_and_long_names_by_each_length() {
        let (shape, fixture) = BALL;
        let body = "<Body Type=\"Dynamic\"><Name>twelve bytes</Name><FixedRotation>true\
            </FixedRotation><AngularVelocity>1</AngularVelocity><Fixtures><ID>0</ID></Fixtures>\
            </Body>";
        let plan = plan_of(Engine::Box2d31, shape, fixture, body, "");
        assert!(plan.reports().is_empty());
        assert_eq!(plan.text(plan.bodies()[0].name), Some("twelve bytes"));
        let plan = plan_of(Engine::Box2d32, shape, fixture, body, "");
        assert!(plan.bodies()[0].name.is_null());
        let reports = messages(&plan);
        assert_eq!(reports.len(), 2);
        assert_eq!(
            reports[0].3,
            "its Name is longer than the 10 bytes Box2D v3.2 keeps of a name; the body has \
             none, and a capture writes none"
        );
        assert_eq!(reports[1].0, Code::LossyBody as u32);
        assert!(reports[1].3.starts_with("FixedRotation with AngularVelocity 1 rad/s"));
    }

    #[test]
    fn a_body_beyond_the_range_skips_its_fixtures() {
        let (shape, fixture) = BALL;
        let body = "<Body Type=\"Dynamic\"><Position>20000 0</Position><Fixtures><ID>0</ID>\
            </Fixtures></Body>";
        let plan = plan_of(Engine::Box2d31, shape, fixture, body, "");
        assert!(plan.bodies().is_empty());
        assert_eq!(
            messages(&plan),
            [
                (
                    Code::BeyondBox2dRange as u32,
                    "body",
                    0,
                    "Position (20000, 0) lies beyond Box2D v3's working range (each component \
                     within +-10000 m); body not created"
                ),
                (
                    Code::SkippedDependent as u32,
                    "fixture",
                    0,
                    "fixture 0 of body 0: the body was not created; fixture skipped"
                ),
            ]
        );
    }
}
