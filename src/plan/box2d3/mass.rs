//! A dynamic body's mass, predicted bit for bit before the body is made, so that the
//! working range can be checked first: summed from its shapes as the version's
//! `b2Body_ApplyMassFromShapes` sums them, then given what its MassData says as Box2D 2.x's
//! `SetMassData` would.

use super::V3;
use super::geometry::Mass;
use super::math::{ZERO, dot, mul_add, mul_sv, sub};
use crate::plan::check::Check;
use crate::plan::range::WorkingRange;
use crate::scene::Body;

/// A shape's mass, with the density it was made at (a shape of density 0 adds nothing).
#[derive(Clone, Copy, Debug)]
pub(crate) struct ShapeMass {
    pub mass: Mass,
    pub density: f32,
}

/// The mass the version gives a dynamic body with these shapes (in creation order; the
/// engine walks a body's shapes newest first), and whether its inertia about the centre of
/// mass stays positive (v3.1 asserts that it does; v3.2's sum cannot go negative).
pub(crate) fn from_shapes(v3: V3, shapes: &[ShapeMass], fixed_rotation: bool) -> (Mass, bool) {
    let mut body = Mass::default();
    let mut center = ZERO;
    let counted = || shapes.iter().rev().filter(|s| s.density != 0.0);
    for s in counted() {
        body.mass += s.mass.mass;
        center = mul_add(center, s.mass.mass, s.mass.center);
        if v3.inertia_about_origin() {
            body.inertia += s.mass.inertia;
        }
    }
    if body.mass > 0.0 {
        let inverse = 1.0 / body.mass;
        center = mul_sv(inverse, center);
    }
    let mut kept = true;
    if v3.inertia_about_origin() {
        if body.inertia > 0.0 && !fixed_rotation {
            body.inertia -= body.mass * dot(center, center);
            kept = body.inertia > 0.0;
        } else {
            body.inertia = 0.0;
        }
    } else {
        for s in counted().filter(|s| s.mass.mass != 0.0) {
            let offset = sub(center, s.mass.center);
            body.inertia += s.mass.inertia + s.mass.mass * dot(offset, offset);
        }
        if fixed_rotation {
            body.inertia = 0.0;
        }
    }
    body.center = center;
    (body, kept)
}

/// Whether the file gives any of a body's mass data.
pub(super) fn given(body: &Body) -> bool {
    let m = &body.mass_data;
    m.mass_given || m.center_given || m.inertia_given
}

/// Box2D 2.x, which the format's files were made for, gives a dynamic body without mass
/// 1 kg; v3 would leave it at 0, unmoved by gravity.
fn positive(mass: f32) -> f32 {
    if mass > 0.0 { mass } else { 1.0 }
}

/// A dynamic body's final mass, as Box2D 2.x's `SetMassData` makes it: from its shapes,
/// then what its MassData gives, a mass of 0 counted as 1 kg. The file's inertia is about
/// the body origin, v3's about the centre of mass; a rotation that is fixed has none.
pub(crate) fn final_mass(computed: Mass, body: &Body) -> Mass {
    let given_data = &body.mass_data;
    let mut out = Mass { mass: positive(computed.mass), ..computed };
    if !given(body) {
        return out;
    }
    let mut origin_inertia =
        computed.inertia + computed.mass * dot(computed.center, computed.center);
    if given_data.mass_given {
        out.mass = positive(given_data.mass);
    }
    if given_data.center_given {
        out.center = given_data.center;
    }
    if given_data.inertia_given {
        origin_inertia = given_data.inertia;
    }
    out.inertia = if body.fixed_rotation || !(origin_inertia > 0.0) {
        0.0
    } else {
        origin_inertia - out.mass * dot(out.center, out.center)
    };
    out
}

/// The checks of a predicted mass: what v3 asserts against, and the working range.
pub(super) fn check(
    v3: V3,
    range: &WorkingRange,
    computed: Mass,
    kept: bool,
    final_mass: Mass,
    check: &mut Check,
) {
    if !kept {
        check.fail(format_args!(
            "its shapes leave no positive inertia about its centre of mass in {}'s float \
             arithmetic (which asserts)",
            v3.name()
        ));
    }
    check.vector("its centre of mass", computed.center, range.max_length, "m");
    check.zero_or_within("its mass", final_mass.mass, range.min_mass, range.max_mass, "kg");
    check.vector("its centre of mass", final_mass.center, range.max_length, "m");
    if final_mass.inertia < 0.0 {
        check.fail(format_args!(
            "its MassData leaves a negative inertia about the centre of mass (Inertia < Mass * \
             |Center|^2), which {} asserts against",
            v3.name()
        ));
    }
    check.zero_or_within(
        "its inertia about the centre of mass",
        final_mass.inertia,
        range.min_inertia,
        range.max_inertia,
        "kg m^2",
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Vec2;

    fn shape(mass: f32, x: f32, inertia: f32, density: f32) -> ShapeMass {
        ShapeMass { mass: Mass { mass, center: Vec2 { x, y: 0.0 }, inertia }, density }
    }

    #[test]
    fn shapes_of_density_zero_add_nothing_and_the_centre_is_mass_weighted() {
        let shapes =
            [shape(1.0, 0.0, 0.5, 1.0), shape(3.0, 2.0, 1.5, 1.0), shape(9.0, 9.0, 9.0, 0.0)];
        // v3.2: inertias about each centroid, moved to the common centre (1.5, 0).
        let (m, kept) = from_shapes(V3::V32, &shapes, false);
        assert!(kept);
        assert_eq!((m.mass, m.center.x), (4.0, 1.5));
        assert_eq!(m.inertia, 1.5 + 3.0 * 0.25 + (0.5 + 1.0 * 2.25));
        let (m, _) = from_shapes(V3::V32, &shapes, true);
        assert_eq!(m.inertia, 0.0);
    }

    #[test]
    fn v31_reports_an_inertia_its_float_sum_leaves_non_positive() {
        // About the origin: 1 kg m^2 of 1 kg at 1 m is all point mass, none about the centre.
        let (m, kept) = from_shapes(V3::V31, &[shape(1.0, 1.0, 1.0, 1.0)], false);
        assert_eq!(m.inertia, 0.0);
        assert!(!kept);
    }

    #[test]
    fn a_body_without_mass_gets_one_kilogram_and_mass_data_overrides() {
        let mut body = Body::new(crate::scene::BodyKind::Dynamic);
        assert_eq!(final_mass(Mass::default(), &body).mass, 1.0);
        body.mass_data.mass_given = true;
        body.mass_data.mass = 2.0;
        body.mass_data.inertia_given = true;
        body.mass_data.inertia = 10.0;
        body.mass_data.center_given = true;
        body.mass_data.center = Vec2 { x: 1.0, y: 1.0 };
        let m = final_mass(Mass::default(), &body);
        assert_eq!((m.mass, m.inertia), (2.0, 10.0 - 2.0 * 2.0));
        body.fixed_rotation = true;
        assert_eq!(final_mass(Mass::default(), &body).inertia, 0.0);
    }
}
