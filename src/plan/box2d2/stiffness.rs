//! Box2D 2.4's springs from a frequency and a damping ratio (`b2LinearStiffness` in
//! `b2_joint.cpp`, and the same arithmetic for the mass a joint's spring moves).

use crate::plan::range::PI;

/// A spring's stiffness and damping.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Spring {
    pub stiffness: f32,
    pub damping: f32,
}

/// The spring of `hertz` and `ratio` that moves a mass `mass`: stiffness m w^2, damping
/// 2 m zeta w, w = 2 pi hertz.
pub(crate) fn spring(mass: f32, hertz: f32, ratio: f32) -> Spring {
    let omega = 2.0 * PI * hertz;
    Spring { stiffness: mass * omega * omega, damping: 2.0 * mass * ratio * omega }
}

/// `b2LinearStiffness`, from the bodies' `GetMass`: both masses in series where both have
/// one, else the one that has.
pub(crate) fn linear(hertz: f32, ratio: f32, mass_a: f32, mass_b: f32) -> Spring {
    let mass = if mass_a > 0.0 && mass_b > 0.0 {
        mass_a * mass_b / (mass_a + mass_b)
    } else if mass_a > 0.0 {
        mass_a
    } else {
        mass_b
    };
    spring(mass, hertz, ratio)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_masses_in_series_move_as_their_reduced_mass() {
        let omega = 2.0 * PI * 2.0;
        let s = linear(2.0, 0.5, 2.0, 6.0);
        assert_eq!(s.stiffness, 1.5 * omega * omega);
        assert_eq!(s.damping, 2.0 * 1.5 * 0.5 * omega);
        assert_eq!(linear(2.0, 0.5, 0.0, 6.0), spring(6.0, 2.0, 0.5));
        assert_eq!(linear(2.0, 0.5, 6.0, 0.0), spring(6.0, 2.0, 0.5));
        assert_eq!(linear(1.0, 1.0, 0.0, 0.0), Spring::default());
    }
}
