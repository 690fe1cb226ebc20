//! How a Box2D 2.x body sums its mass: `b2Body::ResetMassData` over its fixtures, and
//! `b2Body::SetMassData`, each as the engine does it, so that the predicted bits agree.
//! Both leave the inertia about the centre of mass (`m_I`); `b2Body::GetMassData` gives it
//! about the origin.

use super::math::{add, dot, mul_sv};
use crate::plan::records::PlanMass;

/// One fixture of a body: its density and its shape's mass at it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FixtureMass {
    pub density: f32,
    pub mass: PlanMass,
}

/// What `ResetMassData` leaves in a dynamic body holding `fixtures` in the order they were
/// created (the engine walks them newest first): fixtures without density left out, the
/// centre the mass-weighted mean, the inertia moved to it unless the rotation is fixed or
/// there is none. Box2D 2.3 gives a body without mass 1 kg (`massless_weighs_one_kg`);
/// 2.4 leaves it 0.
pub(crate) fn reset_mass(
    fixtures: &[FixtureMass],
    fixed_rotation: bool,
    massless_weighs_one_kg: bool,
) -> PlanMass {
    let mut body = PlanMass::default();
    for f in fixtures.iter().rev().filter(|f| f.density != 0.0) {
        body.mass += f.mass.mass;
        body.center = add(body.center, mul_sv(f.mass.mass, f.mass.center));
        body.inertia += f.mass.inertia;
    }
    if body.mass > 0.0 {
        let inverse = 1.0 / body.mass;
        body.center = mul_sv(inverse, body.center);
    } else if massless_weighs_one_kg {
        body.mass = 1.0;
    }
    if body.inertia > 0.0 && !fixed_rotation {
        body.inertia -= body.mass * dot(body.center, body.center);
    } else {
        body.inertia = 0.0;
    }
    body
}

/// Whether `ResetMassData` moves the summed inertia of `fixtures` to the centre of mass,
/// after which it asserts that some is left.
pub(crate) fn inertia_centred(fixtures: &[FixtureMass], fixed_rotation: bool) -> bool {
    let sum = fixtures
        .iter()
        .rev()
        .filter(|f| f.density != 0.0)
        .fold(0.0f32, |sum, f| sum + f.mass.inertia);
    sum > 0.0 && !fixed_rotation
}

/// What `SetMassData(&given)` (inertia about the origin) leaves in a dynamic body: a mass
/// not above 0 becomes 1, the inertia is moved to the centre where it is used.
pub(crate) fn set_mass(given: PlanMass, fixed_rotation: bool) -> PlanMass {
    let mass = if given.mass > 0.0 { given.mass } else { 1.0 };
    let mut body = PlanMass { mass, center: given.center, inertia: 0.0 };
    if given.inertia > 0.0 && !fixed_rotation {
        body.inertia = given.inertia - mass * dot(given.center, given.center);
    }
    body
}

/// Whether `SetMassData(&given)` keeps a positive inertia about the centre of mass where it
/// uses one: the engine asserts that it does.
pub(crate) fn central_inertia_positive(given: PlanMass, fixed_rotation: bool) -> bool {
    let used = given.inertia > 0.0 && !fixed_rotation;
    !used || set_mass(given, fixed_rotation).inertia > 0.0
}

/// `b2Body::GetMassData` of a body holding `central` (inertia about the centre of mass):
/// the inertia about the origin.
pub(crate) fn about_origin(central: PlanMass) -> PlanMass {
    PlanMass {
        inertia: central.inertia + central.mass * dot(central.center, central.center),
        ..central
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Vec2;

    fn fixture(density: f32, mass: f32, x: f32, inertia: f32) -> FixtureMass {
        FixtureMass { density, mass: PlanMass { mass, center: Vec2::new(x, 0.0), inertia } }
    }

    #[test]
    fn the_sum_skips_fixtures_without_density_and_centres_the_inertia() {
        let fixtures =
            [fixture(1.0, 2.0, 1.0, 5.0), fixture(0.0, 9.0, 9.0, 9.0), fixture(1.0, 2.0, 3.0, 7.0)];
        let body = reset_mass(&fixtures, false, false);
        assert_eq!(body.mass, 4.0);
        assert_eq!(body.center, Vec2::new(2.0, 0.0));
        assert_eq!(body.inertia, 12.0 - 4.0 * 4.0 * 1.0 + 0.0);
        assert!(inertia_centred(&fixtures, false));
        assert!(!inertia_centred(&fixtures, true));
        assert_eq!(reset_mass(&fixtures, true, false).inertia, 0.0);
    }

    #[test]
    fn the_sum_runs_newest_first_as_the_engine_s_fixture_list() {
        // 1e8 + 1 - 1e8 is 0 in floats, 1e8 - 1e8 + 1 is 1: the order shows in the bits
        let fixtures = [
            fixture(1.0, 1.0, 0.0, 1.0),
            fixture(1.0, 1.0, 0.0, -1e8),
            fixture(1.0, 1.0, 0.0, 1e8),
        ];
        assert_eq!(reset_mass(&fixtures, false, false).inertia, 1.0);
    }

    #[test]
    fn box2d_2_3_gives_a_dynamic_body_without_mass_one_kilogram_and_2_4_none() {
        let fixtures = [fixture(0.0, 9.0, 9.0, 9.0), fixture(1.0, 0.0, 2.0, 0.0)];
        let one = reset_mass(&fixtures, false, true);
        assert_eq!(one, PlanMass { mass: 1.0, center: Vec2::ZERO, inertia: 0.0 });
        assert_eq!(reset_mass(&fixtures, false, false), PlanMass::default());
        assert_eq!(reset_mass(&[], true, true).mass, 1.0);
    }

    #[test]
    fn set_mass_gives_a_body_without_mass_one_kilogram() {
        let given = PlanMass { mass: 0.0, center: Vec2::new(1.0, 0.0), inertia: 3.0 };
        assert_eq!(
            set_mass(given, false),
            PlanMass { mass: 1.0, center: Vec2::new(1.0, 0.0), inertia: 2.0 }
        );
        assert!(central_inertia_positive(given, false));
        let too_little = PlanMass { inertia: 0.5, ..given };
        assert!(!central_inertia_positive(too_little, false));
        assert!(central_inertia_positive(too_little, true));
    }

    #[test]
    fn the_inertia_about_the_origin_adds_the_centre_s_lever() {
        let central = PlanMass { mass: 2.0, center: Vec2::new(3.0, 0.0), inertia: 1.0 };
        assert_eq!(about_origin(central).inertia, 19.0);
    }
}
