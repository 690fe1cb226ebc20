//! A Box2D 2.x body read back: its state, its MassData only where the fixtures do not give
//! the mass it holds (with the inertia rules of `SetMassData`), and the LinearVelocity that
//! the build's mass updates turn into the velocity it holds.

use crate::capture::search::solve_nondecreasing;
use crate::capture::world::Say;
use crate::capture::{HeldBody, HeldShape};
use crate::plan::box2d2::Version;
use crate::plan::box2d2::bodies::center_velocity;
use crate::plan::box2d2::body::Body as BuiltBody;
use crate::plan::box2d2::body_mass::{
    FixtureMass, about_origin, central_inertia_positive, reset_mass, set_mass,
};
use crate::plan::box2d2::math::{add, cross_sv, sub, transform};
use crate::plan::box2d2::shape_mass::MassShape;
use crate::plan::printf::G9;
use crate::plan::{PlanMass, PlanShapeKind, Transform};
use crate::rules::polygon_hull;
use crate::scene::{Body, BodyKind, MassData, Vec2};

/// The scene body of a held 2.x body whose held `shapes` are written.
pub(crate) fn body(
    version: &Version,
    held: &HeldBody,
    shapes: &[HeldShape],
    points: &[Vec2],
    _level: Option<&Body>,
    say: &mut Say,
) -> Body {
    let b = &held.body;
    let kind = BodyKind::try_from(b.kind).unwrap_or(BodyKind::Static);
    let created: Vec<FixtureMass> =
        shapes.iter().map(|s| fixture_mass(version, s, points)).collect();
    let mass_data = mass_data(version, held, &created, say);
    let linear_velocity = linear_velocity(version, held, &created, &mass_data, say);
    Body {
        position: b.position,
        angle: b.angle,
        linear_velocity,
        angular_velocity: b.angular_velocity,
        linear_damping: b.linear_damping,
        angular_damping: b.angular_damping,
        gravity_scale: b.gravity_scale,
        mass_data,
        active: b.enabled,
        allow_sleep: b.allow_sleep,
        // Box2D never marks a static body awake, and ignores the flag when it makes one.
        awake: kind == BodyKind::Static || b.awake,
        bullet: b.bullet,
        fixed_rotation: b.fixed_rotation,
        ..Body::new(kind)
    }
}

/// A held shape's density and the mass the build's engine gives its shape at it.
fn fixture_mass(version: &Version, held: &HeldShape, points: &[Vec2]) -> FixtureMass {
    let plan = &held.shape;
    let points = points.get(plan.points.indices()).unwrap_or(&[]);
    let shape = match PlanShapeKind::try_from(plan.kind) {
        Ok(PlanShapeKind::Circle) => MassShape::Circle { center: plan.center, radius: plan.radius },
        Ok(PlanShapeKind::Polygon) => MassShape::Polygon(polygon_hull(points)),
        Ok(PlanShapeKind::Segment) if points.len() == 4 => MassShape::Edge(points[1], points[2]),
        Ok(PlanShapeKind::Segment) if points.len() == 2 => MassShape::Edge(points[0], points[1]),
        _ => MassShape::Chain,
    };
    FixtureMass { density: plan.density, mass: shape.mass(plan.density, version.polygon_reference) }
}

fn given(m: &MassData) -> bool {
    m.mass_given || m.center_given || m.inertia_given
}

fn same_bits(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits()
}

/// None given where the fixtures give the body's mass (the build's engine then computes it
/// the same way); else the data that differ from the fixtures'. The engine keeps the
/// inertia about the centre, `m_I = I - m|c|^2` from `SetMassData`, which `GetInertia`
/// turns back into `I`: writing `GetInertia` gives back `m_I`, except where `m_I` is 0
/// (`SetMassData` with no inertia), which only Inertia 0 gives.
fn mass_data(
    version: &Version,
    held: &HeldBody,
    created: &[FixtureMass],
    say: &mut Say,
) -> MassData {
    let b = &held.body;
    let mut out = MassData::default();
    if b.kind != BodyKind::Dynamic as u32 {
        return out; // SetMassData ignores other bodies
    }
    let fixtures = reset_mass(created, b.fixed_rotation, version.massless_weighs_one_kg);
    let fixtures_inertia = about_origin(fixtures).inertia;
    let PlanMass { mass, center, inertia } = b.mass;
    out.mass = mass;
    out.mass_given = !same_bits(mass, fixtures.mass);
    out.center = center;
    out.center_given =
        !(same_bits(center.x, fixtures.center.x) && same_bits(center.y, fixtures.center.y));
    if !given(&out) && same_bits(inertia, fixtures_inertia) {
        return out;
    }
    if b.fixed_rotation {
        return out; // SetMassData ignores its inertia
    }
    let written = |i: f32| PlanMass { mass, center, inertia: i };
    let after = |i: f32| about_origin(set_mass(written(i), false)).inertia;
    let accepted = |i: f32| central_inertia_positive(written(i), false);
    if given(&out) && same_bits(after(fixtures_inertia), inertia) && accepted(fixtures_inertia) {
        return out; // SetMassData with GetMassData's inertia after the fixtures does
    }
    out.inertia_given = true;
    // no inertia given, as GetMassData gives it back
    let none = about_origin(written(0.0)).inertia;
    out.inertia = if same_bits(inertia, none) { 0.0 } else { inertia };
    if !same_bits(after(out.inertia), inertia) || !accepted(out.inertia) {
        say.lossy(format_args!(
            "its MassData Inertia {} does not come back exactly through Box2D's SetMassData",
            G9(inertia)
        ));
    }
    out
}

/// The LinearVelocity to write: the build's mass updates each move the velocity by
/// w x (how far the centre of mass moved), or (2.3) give the centre the origin's velocity
/// again once the mass is final, and it must end at the body's velocity.
fn linear_velocity(
    version: &Version,
    held: &HeldBody,
    created: &[FixtureMass],
    written: &MassData,
    say: &mut Say,
) -> Vec2 {
    let b = &held.body;
    let target = b.linear_velocity;
    if b.kind != BodyKind::Dynamic as u32 {
        return target;
    }
    let after_build = after_build(version, held, created, given(written));
    let guess = sub(target, after_build(Vec2::ZERO));
    let (x, exact_x) = solve_nondecreasing(|x| after_build(Vec2::new(x, 0.0)).x, target.x, guess.x);
    let (y, exact_y) = solve_nondecreasing(|y| after_build(Vec2::new(0.0, y)).y, target.y, guess.y);
    let start = Vec2::new(x, y);
    if !(exact_x && exact_y) {
        // the kicks outweigh the velocity: the floats they land on are sparse
        let miss = sub(after_build(start), target);
        say.lossy(format_args!(
            "no LinearVelocity ends exactly at its velocity once build_world has moved its \
             centre of mass; the nearest misses by ({}, {}) m/s",
            G9(miss.x),
            G9(miss.y)
        ));
    }
    start
}

/// The velocity a dynamic body the build makes holds, given its LinearVelocity: 2.4's
/// `ResetMassData` (once, after the fixtures, when one has a density) and `SetMassData`
/// each add w x (how far the centre of mass moved); 2.3's builder sets the centre's
/// velocity from the origin's once the mass is final, where the body is awake and turns.
fn after_build(
    version: &Version,
    held: &HeldBody,
    created: &[FixtureMass],
    mass_data_written: bool,
) -> impl Fn(Vec2) -> Vec2 {
    let b = held.body;
    let frame = Transform { p: b.position, q: b.rotation };
    let w = b.angular_velocity;
    let mut centres = Vec::new();
    let set_velocity = version.velocity_after_mass && b.awake && w != 0.0;
    if set_velocity {
        let built = BuiltBody { frame, mass: b.mass, kind: BodyKind::Dynamic };
        return Box::new(move |v| center_velocity(built, v, w)) as Box<dyn Fn(Vec2) -> Vec2>;
    }
    if created.iter().any(|f| f.density > 0.0) {
        centres.push(reset_mass(created, b.fixed_rotation, version.massless_weighs_one_kg).center);
    }
    if mass_data_written {
        centres.push(b.mass.center);
    }
    Box::new(move |v: Vec2| {
        let mut centre = frame.p; // where b2Body's constructor puts it
        let mut v = v;
        for &local in &centres {
            let moved = transform(frame, local);
            let kick = cross_sv(w, sub(moved, centre));
            v = add(v, kick);
            centre = moved;
        }
        v
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Builder;
    use crate::capture::tests::{capture_of, held_of, messages};
    use crate::plan::Engine;
    use crate::scene::{Fixture, Shape, ShapeKind};

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    /// A spinning body whose centre of mass is off its origin: the build's mass updates
    /// kick the velocity by w x (how far the centre moved).
    #[test]
    fn the_linear_velocity_is_the_one_the_build_kicks_to_the_held_velocity() {
        let mut b = Builder::new();
        let circle = Shape { radius: 0.5, position: v(0.3, -0.2), ..Shape::new(ShapeKind::Circle) };
        let shape = b.add_shape(&circle, None, &[]).unwrap();
        let fixture = b.add_fixture(&Fixture { shape, density: 2.0, ..Fixture::default() }, None);
        let body = Body {
            position: v(1.0, 2.0),
            angle: 0.7,
            angular_velocity: 3.0,
            ..Body::new(BodyKind::Dynamic)
        };
        b.add_body(&body, None, &[fixture.unwrap()]).unwrap();
        let scene = b.finish();
        for engine in [Engine::Box2d24, Engine::Box2d23] {
            let mut held = held_of(&scene, engine);
            // on the even floats the kicks' sums land on
            let target = v(5.5, -7.25);
            held.bodies[0].body.linear_velocity = target;
            let captured = capture_of(&held, engine, None, &[]);
            assert_eq!(messages(&captured), Vec::<String>::new());
            let written = captured.scene.bodies()[0].linear_velocity;
            assert_ne!(written, target, "{engine:?}: the centre of mass moves the velocity");
            let version = Version::of(engine).unwrap();
            let created: Vec<FixtureMass> =
                held.shapes.iter().map(|s| fixture_mass(version, s, &held.points)).collect();
            let data = captured.scene.bodies()[0].mass_data;
            let after = after_build(version, &held.bodies[0], &created, given(&data))(written);
            assert_eq!(
                (after.x.to_bits(), after.y.to_bits()),
                (target.x.to_bits(), target.y.to_bits())
            );
        }
    }

    #[test]
    fn a_static_body_keeps_its_velocity_as_it_is() {
        let mut b = Builder::new();
        let body = Body { linear_velocity: v(1.0, 2.0), ..Body::new(BodyKind::Static) };
        b.add_body(&body, None, &[]).unwrap();
        let mut held = held_of(&b.finish(), Engine::Box2d24);
        held.bodies[0].body.linear_velocity = v(0.25, 0.5);
        let captured = capture_of(&held, Engine::Box2d24, None, &[]);
        assert_eq!(captured.scene.bodies()[0].linear_velocity, v(0.25, 0.5));
    }
}
