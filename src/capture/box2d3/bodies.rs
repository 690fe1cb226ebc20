//! Bodies: the angle whose rotation the engine holds, the velocity of the origin, and the
//! mass written only where the build would not compute the same from the shapes. Each
//! inverse searches the value whose forward computation, the plan's, gives the held bits.

use super::shapes::in_chain;
use crate::capture::search::nearest;
use crate::capture::world::Say;
use crate::capture::{HeldBody, HeldShape};
use crate::plan::box2d3::V3;
use crate::plan::box2d3::bodies::center_velocity;
use crate::plan::box2d3::geometry::{Mass, circle_mass, polygon_mass};
use crate::plan::box2d3::mass::{ShapeMass, final_mass, from_shapes};
use crate::plan::box2d3::math::{dot, rotation};
use crate::plan::printf::G3;
use crate::plan::{PlanMass, PlanShapeKind, Rot, Transform};
use crate::scene::{Body, BodyKind, MassData, Vec2};

/// Says once, of all the held bodies, those whose rotation no float angle gives exactly:
/// the solver turns nearly every body it moves to such a rotation, so one report says how
/// many, the first, and the largest turn between a rotation and the angle written.
pub(crate) fn turned(bodies: &[HeldBody], say: &mut Say) {
    let mut count = 0u32;
    let (mut first, mut largest) = (0usize, 0.0f64);
    for (index, held) in bodies.iter().enumerate() {
        let q = held.body.rotation;
        let Err(angle) = angle_of(q) else { continue };
        let (c, s) = (f64::from(q.c), f64::from(q.s));
        let (cos, sin) = (f64::from(angle).cos(), f64::from(angle).sin());
        let turn = (s * cos - c * sin).atan2(c * cos + s * sin).abs();
        if count == 0 {
            first = index;
        }
        count += 1;
        largest = if turn > largest { turn } else { largest };
    }
    if count > 0 {
        say.lossy(format_args!(
            "rotations no angle gives exactly, as the solver turns bodies: {count} of the bodies \
             (the first body {first}) were written at the nearest angle, at most {} rad from \
             the rotation",
            G3(largest)
        ));
    }
}

/// An angle whose rotation, as the plan makes one, is `q`; `Err` with the nearest.
pub(super) fn angle_of(q: Rot) -> Result<f32, f32> {
    nearest(q.s.atan2(q.c), |angle| rotation(angle) == q)
}

/// The scene body (no name, fixtures or user data) of a held body, given its held shapes
/// that are written, in creation order.
pub(crate) fn body(v3: V3, held: &HeldBody, shapes: &[HeldShape], points: &[Vec2]) -> Body {
    let b = &held.body;
    let mut body = Body::new(BodyKind::Static);
    body.kind = b.kind;
    body.position = b.position;
    body.angle = angle_of(b.rotation).unwrap_or_else(|nearest| nearest);
    let dynamic = b.kind == BodyKind::Dynamic as u32;
    body.linear_velocity = if dynamic { origin_velocity(b) } else { b.linear_velocity };
    body.angular_velocity = b.angular_velocity;
    body.linear_damping = b.linear_damping;
    body.angular_damping = b.angular_damping;
    body.gravity_scale = b.gravity_scale;
    body.allow_sleep = b.allow_sleep;
    body.awake = b.awake;
    body.bullet = b.bullet;
    body.fixed_rotation = b.fixed_rotation;
    body.active = b.enabled;
    if dynamic {
        let computed = from_shapes(v3, &masses(v3, shapes, points), b.fixed_rotation).0;
        let built = final_mass(computed, &Body::new(BodyKind::Dynamic));
        if !same_mass(built, b.mass) {
            body.mass_data = mass_data(computed, b.mass);
        }
    }
    body
}

/// The masses of the shapes the capture writes with their density, in creation order.
fn masses(v3: V3, shapes: &[HeldShape], points: &[Vec2]) -> Vec<ShapeMass> {
    let massive = shapes.iter().filter(|s| s.other.is_null() && !in_chain(s));
    massive
        .filter_map(|s| {
            let density = s.shape.density;
            let mass = match PlanShapeKind::try_from(s.shape.kind).ok()? {
                PlanShapeKind::Circle => circle_mass(v3, s.shape.center, s.shape.radius, density),
                PlanShapeKind::Polygon => {
                    let vertices = points.get(s.shape.points.indices())?;
                    if vertices.len() < 3 {
                        return None;
                    }
                    polygon_mass(v3, vertices, density)
                }
                _ => return None,
            };
            Some(ShapeMass { mass, density })
        })
        .collect()
}

fn same_mass(a: Mass, b: PlanMass) -> bool {
    a.mass == b.mass && a.center == b.center && a.inertia == b.inertia
}

/// The MassData that gives a body the mass it holds, its inertia about the origin the one
/// the plan turns back into the held inertia about the centre.
fn mass_data(computed: Mass, held: PlanMass) -> MassData {
    let given = |inertia: f32| MassData {
        mass: held.mass,
        center: held.center,
        inertia,
        mass_given: true,
        center_given: true,
        inertia_given: true,
    };
    let central = |inertia: f32| {
        let mut body = Body::new(BodyKind::Dynamic);
        body.mass_data = given(inertia);
        final_mass(computed, &body).inertia
    };
    let guess = held.inertia + held.mass * dot(held.center, held.center);
    let inertia = nearest(guess, |x| central(x) == held.inertia).unwrap_or_else(|x| x);
    given(inertia)
}

/// The velocity of a dynamic body's origin, which the file gives, from its centre of
/// mass's, which the engine holds: each component the one the plan's shift gives back.
fn origin_velocity(b: &crate::plan::PlanBody) -> Vec2 {
    let transform = Transform { p: b.position, q: b.rotation };
    let (w, center) = (b.angular_velocity, b.mass.center);
    let centre_of = |origin: Vec2| center_velocity(transform, center, w, origin);
    let shift = centre_of(Vec2::ZERO);
    let target = b.linear_velocity;
    let x = nearest(target.x - shift.x, |x| centre_of(Vec2::new(x, 0.0)).x == target.x);
    let y = nearest(target.y - shift.y, |y| centre_of(Vec2::new(0.0, y)).y == target.y);
    Vec2::new(x.unwrap_or_else(|x| x), y.unwrap_or_else(|y| y))
}
