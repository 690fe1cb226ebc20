//! Box2D 2.4's springs from a frequency and a damping ratio (`b2LinearStiffness` in
//! `b2_joint.cpp`, and the same arithmetic for the mass a joint's spring moves), and Box2D
//! 2.2's springs of the wheel and weld joints as 2.4 is given them.

use super::body::Body;
use super::math::{add, cross, normalized, rotate, sub};
use crate::plan::range::PI;
use crate::scene::Joint;

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

/// Box2D 2.2's soft weld: the angular mass 1/(1/IA + 1/IB) from the inertias about the
/// centres of mass (`b2AngularStiffness` takes those about the origins).
pub(crate) fn weld_spring(joint: &Joint, a: Body, b: Body) -> Spring {
    let inverse = a.inverse_central_inertia() + b.inverse_central_inertia();
    spring(if inverse > 0.0 { 1.0 / inverse } else { 0.0 }, joint.frequency_hz, joint.damping_ratio)
}

/// Box2D 2.2's wheel spring: the effective mass along the axis as the joint starts,
/// 1/(1/mA + 1/mB + sAx^2/IA + sBx^2/IB), as 2.2's InitVelocityConstraints computes it
/// (`b2LinearStiffness` takes mA mB/(mA + mB)).
pub(crate) fn wheel_spring(joint: &Joint, a: Body, b: Body) -> Spring {
    if !(joint.frequency_hz > 0.0) {
        return Spring::default();
    }
    let axis = normalized(joint.local_axis_a);
    let (qa, qb) = (a.frame.q, b.frame.q);
    let ra = rotate(qa, sub(joint.local_anchor_a, a.mass.center));
    let rb = rotate(qb, sub(joint.local_anchor_b, b.mass.center));
    let d = sub(sub(add(b.world_center(), rb), a.world_center()), ra);
    let ax = rotate(qa, axis);
    let s_ax = cross(add(d, ra), ax);
    let s_bx = cross(rb, ax);
    let inverse = a.inverse_mass()
        + b.inverse_mass()
        + a.inverse_central_inertia() * s_ax * s_ax
        + b.inverse_central_inertia() * s_bx * s_bx;
    spring(if inverse > 0.0 { 1.0 / inverse } else { 0.0 }, joint.frequency_hz, joint.damping_ratio)
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
