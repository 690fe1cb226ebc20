//! The bodies of a Box2D 2.x plan: each checked, placed, given its fixtures and the mass
//! the engine will hold, predicted as the engine sums it.

use super::body::Body;
use super::body_mass::{
    FixtureMass, about_origin, central_inertia_positive, inertia_centred, reset_mass, set_mass,
};
use super::math::{add, cross_sv, mul_sv, rotate, rotation, sub, transform};
use super::world::Mapper;
use crate::error::Code;
use crate::plan::check::Check;
use crate::plan::container::Object;
use crate::plan::printf::F;
use crate::plan::records::{PlanBody, PlanMass};
use crate::scene::{Body as SceneBody, BodyKind, MassData, Range, Str, Vec2};

impl Mapper<'_> {
    pub(super) fn make_body(&mut self, index: u32) {
        let body = &self.scene.bodies()[index as usize];
        let Ok(kind) = BodyKind::try_from(body.kind) else {
            self.report(
                Code::UnknownType,
                Object::Body,
                index,
                body.name,
                format_args!("unknown body kind {}; body skipped", body.kind),
            );
            self.skip_fixtures_of(index, body);
            return;
        };
        let mut check = self.body_check(body, kind);
        if kind == BodyKind::Dynamic && check.passed() {
            self.masses[index as usize] = self.predicted_mass(body, &mut check);
        }
        if !self.within_range(&check, Object::Body, index, body.name, "") {
            self.skip_fixtures_of(index, body);
            return;
        }
        let position = self.placed(body.position);
        let angle = body.angle + self.placement_angle;
        // Box2D 2.x keeps the velocity a static body is created with and moves the body
        // by it whenever a joint puts it in an island; static bodies never move.
        let moves = kind != BodyKind::Static;
        let linear_velocity =
            if moves { rotate(self.options.placement.q, body.linear_velocity) } else { Vec2::ZERO };
        let angular_velocity = if moves { body.angular_velocity } else { 0.0 };
        let linear_damping = self.damping(index, body, body.linear_damping, "LinearDamping");
        let angular_damping = self.damping(index, body, body.angular_damping, "AngularDamping");
        let first = self.plan.shape_count();
        let fixtures = self.make_fixtures(index, body);
        let shapes = Range::between(first, self.plan.shape_count());
        let dense = fixtures.iter().any(|f| f.density > 0.0);
        let from_fixtures = match kind {
            BodyKind::Dynamic => {
                reset_mass(&fixtures, body.fixed_rotation, self.version.massless_weighs_one_kg)
            }
            _ => PlanMass::default(),
        };
        let given = self.mass_to_set(index, body, from_fixtures);
        let held = match (given, kind) {
            (Some(mass), BodyKind::Dynamic) => set_mass(mass, body.fixed_rotation),
            _ => from_fixtures,
        };
        let made = Body::new(position, angle, held, kind);
        self.bodies[index as usize] = Some(made);
        let set_velocity = self.version.velocity_after_mass
            && kind == BodyKind::Dynamic
            && body.awake
            && angular_velocity != 0.0;
        let velocity_after_mass = if set_velocity {
            center_velocity(made, linear_velocity, angular_velocity)
        } else {
            Vec2::ZERO
        };
        self.plan.push_body(PlanBody {
            body: index,
            kind: body.kind,
            position,
            angle,
            rotation: rotation(angle),
            linear_velocity,
            angular_velocity,
            linear_damping,
            angular_damping,
            gravity_scale: body.gravity_scale,
            name: Str::NULL,
            shapes,
            // What GetMassData will give: inertia about the origin.
            mass: given.unwrap_or(about_origin(held)),
            velocity_after_mass,
            allow_sleep: body.allow_sleep,
            awake: body.awake,
            fixed_rotation: body.fixed_rotation,
            bullet: body.bullet,
            enabled: body.active,
            apply_mass_from_shapes: dense,
            set_mass: given.is_some(),
            set_velocity,
        });
    }

    fn body_check(&self, body: &SceneBody, kind: BodyKind) -> Check {
        let range = self.range;
        let mut check = self.check();
        check.vector("Position", body.position, range.max_length, "m");
        check.magnitude("Angle", body.angle, range.max_angle, "rad");
        check.vector("LinearVelocity", body.linear_velocity, range.max_speed, "m/s");
        check.magnitude("AngularVelocity", body.angular_velocity, range.max_speed, "rad/s");
        check.magnitude("LinearDamping", body.linear_damping, range.max_damping, "1/s");
        check.magnitude("AngularDamping", body.angular_damping, range.max_damping, "1/s");
        check.magnitude("GravityScale", body.gravity_scale, range.max_gravity_scale, "");
        if kind == BodyKind::Dynamic {
            let gravity = mul_sv(body.gravity_scale, self.options.gravity);
            check.vector(
                "GravityScale times the world's gravity",
                gravity,
                range.max_acceleration,
                "m/s^2",
            );
        }
        if body.mass_data.center_given {
            check.vector("MassData Center", body.mass_data.center, range.max_length, "m");
        }
        if check.passed() {
            check.vector("its placed Position", self.placed(body.position), range.max_length, "m");
        }
        check
    }

    /// The fixture slots of `body` that lie in the scene's pool.
    fn slots(&self, body: &SceneBody) -> std::ops::Range<u32> {
        let pool = self.scene.fixture_id_pool().len() as u64;
        let end = (u64::from(body.fixtures.first) + u64::from(body.fixtures.count)).min(pool);
        body.fixtures.first..end.max(u64::from(body.fixtures.first)) as u32
    }

    /// The fixtures of a body that was not created: they depend on it.
    fn skip_fixtures_of(&mut self, body_index: u32, body: &SceneBody) {
        for slot in self.slots(body) {
            let index = self.scene.fixture_id_pool()[slot as usize];
            let name = self.scene.fixtures().get(index as usize).map_or(Str::NULL, |f| f.name);
            self.report(
                Code::SkippedDependent,
                Object::Fixture,
                index,
                name,
                format_args!(
                    "fixture {index} of body {body_index}: the body was not created; fixture \
                     skipped"
                ),
            );
        }
    }

    /// The mass Box2D 2.x will give a dynamic body, as the executor has the engine compute
    /// it: from all of its fixtures at once (`ResetMassData`, which asserts that an
    /// inertia it centres stays positive), then MassData. `check` fails when the engine
    /// would assert or the result lies beyond the working range, and in 2.3 when the
    /// MassData leaves no positive inertia about the centre of mass.
    fn predicted_mass(&self, body: &SceneBody, check: &mut Check) -> PlanMass {
        let created: Vec<FixtureMass> = self
            .slots(body)
            .map(|slot| self.scene.fixture_id_pool()[slot as usize])
            .filter(|&index| self.fixture_creatable(index))
            .map(|index| self.fixture_mass(index))
            .collect();
        let range = self.range;
        let engine = self.version.name;
        let mass = reset_mass(&created, body.fixed_rotation, self.version.massless_weighs_one_kg);
        if inertia_centred(&created, body.fixed_rotation) && !(mass.inertia > 0.0) {
            check.fail(format_args!(
                "with fixtures that have a density, it has no positive inertia about its \
                 centre of mass in {engine}'s float arithmetic (which asserts)"
            ));
        }
        // The new centre of mass moves the body's velocity (w x its shift), even where
        // MassData then moves it again: a centre made NaN by a subnormal mass (0 * infinity)
        // would stay in the velocity.
        check.vector(
            "with fixtures that have a density, its centre of mass",
            mass.center,
            range.max_length,
            "m",
        );
        if self.version.refuses_inconsistent_mass && !mass_data_consistent(mass, body) {
            check.fail(format_args!(
                "its MassData leaves no positive inertia about the centre of mass (Inertia <= \
                 Mass * |Center|^2), which {engine} asserts against"
            ));
        }
        let mass = with_mass_data(mass, body);
        check.zero_or_within("its mass", mass.mass, range.min_mass, range.max_mass, "kg");
        check.vector("its centre of mass", mass.center, range.max_length, "m");
        check.zero_or_within(
            "its inertia about the centre of mass",
            mass.inertia,
            range.min_inertia,
            range.max_inertia,
            "kg m^2",
        );
        mass
    }

    /// A created fixture's density and its shape's mass at it.
    fn fixture_mass(&self, index: u32) -> FixtureMass {
        let fixture = &self.scene.fixtures()[index as usize];
        let made = self.shapes[fixture.shape as usize].as_ref().expect("a creatable fixture");
        let mass = made.mass.mass(fixture.density, self.version.polygon_reference);
        FixtureMass { density: fixture.density, mass }
    }

    /// Box2D 2.x asserts against a negative damping, which the format does not forbid.
    fn damping(&mut self, index: u32, body: &SceneBody, value: f32, field: &str) -> f32 {
        if value >= 0.0 {
            return value;
        }
        self.report(
            Code::NegativeValue,
            Object::Body,
            index,
            body.name,
            format_args!(
                "{field} {} is negative, which {} does not allow; 0 was used",
                F(value),
                self.version.name
            ),
        );
        0.0
    }

    /// The fixtures of a created body, planned; what each gives its mass.
    fn make_fixtures(&mut self, index: u32, body: &SceneBody) -> Vec<FixtureMass> {
        let end = u64::from(body.fixtures.first) + u64::from(body.fixtures.count);
        if end > self.scene.fixture_id_pool().len() as u64 {
            self.report(
                Code::IdOutOfRange,
                Object::Body,
                index,
                body.name,
                format_args!("its fixture list lies outside the scene's fixture ID pool"),
            );
            return Vec::new();
        }
        let mut created = Vec::new();
        for slot in body.fixtures.indices() {
            let fixture = self.scene.fixture_id_pool()[slot];
            if let Some(shape) = self.make_fixture(index, slot as u32, fixture) {
                self.plan.push_shape(shape);
                created.push(self.fixture_mass(fixture));
            }
        }
        created
    }

    /// The mass the executor sets after the fixtures (`SetMassData`, inertia about the
    /// origin), where the file's MassData gives one the engine can take; a datum it leaves
    /// out keeps the value computed from the fixtures.
    fn mass_to_set(&mut self, index: u32, body: &SceneBody, central: PlanMass) -> Option<PlanMass> {
        if !mass_data_given(&body.mass_data) {
            return None;
        }
        let mass = overwritten(about_origin(central), &body.mass_data);
        if !central_inertia_positive(mass, body.fixed_rotation) {
            self.report(
                Code::InconsistentMassData,
                Object::Body,
                index,
                body.name,
                format_args!(
                    "its MassData leaves no positive inertia about the centre of mass \
                     (Inertia < Mass * |Center|^2); the mass computed from the fixtures was kept"
                ),
            );
            return None;
        }
        Some(mass)
    }
}

/// Whether the body's MassData, written over `mass` (from the fixtures, inertia about the
/// centre), leaves the inertia about the centre of mass positive where it is used.
fn mass_data_consistent(mass: PlanMass, body: &SceneBody) -> bool {
    !mass_data_given(&body.mass_data)
        || central_inertia_positive(
            overwritten(about_origin(mass), &body.mass_data),
            body.fixed_rotation,
        )
}

/// The velocity of a created body's centre of mass whose origin moves at `origin` turning
/// at `w` (`v + w x (c - p)`, as 2.x's `SetMassData` moves it), what the executor gives it
/// once its mass is final.
pub(crate) fn center_velocity(body: Body, origin: Vec2, w: f32) -> Vec2 {
    let arm = sub(transform(body.frame, body.mass.center), body.frame.p);
    add(origin, cross_sv(w, arm))
}

/// `mass` (from the fixtures, inertia about the centre) as the MassData leaves it.
fn with_mass_data(mass: PlanMass, body: &SceneBody) -> PlanMass {
    if !mass_data_given(&body.mass_data) {
        return mass;
    }
    let data = overwritten(about_origin(mass), &body.mass_data);
    if central_inertia_positive(data, body.fixed_rotation) {
        set_mass(data, body.fixed_rotation)
    } else {
        mass
    }
}

fn mass_data_given(given: &MassData) -> bool {
    given.mass_given || given.center_given || given.inertia_given
}

/// `mass` (inertia about the body origin) with what the body's MassData gives written
/// over it.
fn overwritten(mut mass: PlanMass, given: &MassData) -> PlanMass {
    if given.mass_given {
        mass.mass = given.mass;
    }
    if given.center_given {
        mass.center = given.center;
    }
    if given.inertia_given {
        mass.inertia = given.inertia;
    }
    mass
}
