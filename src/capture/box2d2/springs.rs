//! The inverses of a 2.x joint's derived values: the FrequencyHz and DampingRatio from
//! which the build computes the stiffness and damping the engine holds, and an axis that
//! `b2Vec2::Normalize` turns into the unit axis the engine holds.

use crate::capture::search::{solve_nondecreasing, ulps_away};
use crate::plan::box2d2::math::normalized;
use crate::plan::box2d2::stiffness::Spring;
use crate::scene::Vec2;

/// A spring's FrequencyHz and DampingRatio, and whether they give the held spring back
/// exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Hertz {
    pub hz: f32,
    pub ratio: f32,
    pub exact: bool,
}

/// The FrequencyHz and DampingRatio from which `spring_of`, what the build computes for
/// the joint on the same two bodies, gives back `held` bit for bit; where none do, the
/// nearest. A zero stiffness is no spring: Box2D 2.4 then ignores the damping.
pub(super) fn spring_giving(spring_of: impl Fn(f32, f32) -> Spring, held: Spring) -> Hertz {
    if held.stiffness == 0.0 {
        return Hertz { hz: 0.0, ratio: 0.0, exact: true };
    }
    let stiffness_at = |hz: f32| spring_of(hz, 0.0).stiffness;
    let per_hz_squared = stiffness_at(1.0);
    if !(per_hz_squared > 0.0) {
        // neither body has mass: no frequency gives a stiffness
        return Hertz { hz: 0.0, ratio: 0.0, exact: false };
    }
    let guess = (held.stiffness / per_hz_squared).sqrt();
    let (hz, hz_exact) = solve_nondecreasing(stiffness_at, held.stiffness, guess);
    let damping_at = |ratio: f32| spring_of(hz, ratio).damping;
    let per_ratio = damping_at(1.0);
    let (ratio, ratio_exact) =
        solve_nondecreasing(damping_at, held.damping, held.damping / per_ratio);
    Hertz { hz, ratio, exact: hz_exact && ratio_exact }
}

/// An axis that `b2Vec2::Normalize` turns into `unit` bit for bit, and whether there is
/// one (else `unit` itself): the build normalises every axis it is given. A vector and
/// twice it normalise alike, so scales in [1, 2) with their neighbouring floats cover the
/// candidates; the axis itself comes first.
pub(super) fn axis_normalising_to(unit: Vec2) -> (Vec2, bool) {
    for i in 0..32 {
        let scale = 1.0 + i as f32 / 32.0;
        for dx in [0, -1, 1] {
            for dy in [0, -1, 1] {
                let candidate =
                    Vec2::new(ulps_away(unit.x * scale, dx), ulps_away(unit.y * scale, dy));
                let normal = normalized(candidate);
                if normal.x.to_bits() == unit.x.to_bits() && normal.y.to_bits() == unit.y.to_bits()
                {
                    return (candidate, true);
                }
            }
        }
    }
    (unit, false)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::box2d2::stiffness::linear;

    #[test]
    fn a_spring_s_hertz_and_ratio_give_back_its_stiffness_and_damping_bit_for_bit() {
        let (ma, mb) = (1.7f32, 3.1f32);
        for (hz, ratio) in [(4.0f32, 0.7f32), (0.3, 0.05), (29.5, 1.9)] {
            let held = linear(hz * 1.0001, ratio * 0.9999, ma, mb);
            let found = spring_giving(|h, r| linear(h, r, ma, mb), held);
            assert!(found.exact, "{hz} {ratio}");
            let back = linear(found.hz, found.ratio, ma, mb);
            assert_eq!(back.stiffness.to_bits(), held.stiffness.to_bits());
            assert_eq!(back.damping.to_bits(), held.damping.to_bits());
        }
    }

    #[test]
    fn no_spring_is_no_frequency_and_bodies_without_mass_give_none() {
        let none = Spring::default();
        assert_eq!(
            spring_giving(|h, r| linear(h, r, 1.0, 1.0), none),
            Hertz { hz: 0.0, ratio: 0.0, exact: true }
        );
        let held = Spring { stiffness: 5.0, damping: 1.0 };
        assert!(!spring_giving(|h, r| linear(h, r, 0.0, 0.0), held).exact);
    }

    #[test]
    fn an_axis_is_found_that_normalises_to_the_held_unit_axis() {
        let mut found = 0;
        for i in 0..200 {
            let angle = i as f32 * 0.0313;
            let unit = normalized(Vec2::new(angle.cos() * 3.0, angle.sin() * 3.0));
            let (axis, exact) = axis_normalising_to(unit);
            if exact {
                let back = normalized(axis);
                assert_eq!(
                    (back.x.to_bits(), back.y.to_bits()),
                    (unit.x.to_bits(), unit.y.to_bits())
                );
                found += 1;
            }
        }
        assert!(found >= 195, "{found} of 200");
        assert_eq!(axis_normalising_to(Vec2::new(1.0, 0.0)), (Vec2::new(1.0, 0.0), true));
    }
}
