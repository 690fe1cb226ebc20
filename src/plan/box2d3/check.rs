//! The checks of the working range: the first value of one object found beyond what the
//! engine holds, said as the executor's reports always said it.

use std::fmt;

use super::version::V3;
use crate::plan::printf::{G, G9};
use crate::scene::Vec2;

/// The first problem found with one object, if any.
#[derive(Debug, Default)]
pub(super) struct Check {
    problem: Option<String>,
}

impl Check {
    pub(super) fn passed(&self) -> bool {
        self.problem.is_none()
    }

    pub(super) fn problem(&self) -> &str {
        self.problem.as_deref().unwrap_or_default()
    }

    /// Notes a problem unless one is noted already.
    pub(super) fn fail(&mut self, problem: fmt::Arguments<'_>) {
        if self.problem.is_none() {
            self.problem = Some(fmt::format(problem));
        }
    }

    pub(super) fn magnitude(&mut self, v3: V3, field: &str, value: f32, bound: f32, unit: &str) {
        if !(value.abs() <= bound) {
            self.fail(format_args!(
                "{field} {} lies beyond {}'s working range (within +-{} {unit})",
                G9(value),
                v3.name(),
                G(bound)
            ));
        }
    }

    pub(super) fn vector(&mut self, v3: V3, field: &str, v: Vec2, bound: f32, unit: &str) {
        if !(v.x.abs() <= bound && v.y.abs() <= bound) {
            self.fail(format_args!(
                "{field} ({}, {}) lies beyond {}'s working range (each component within +-{} \
                 {unit})",
                G9(v.x),
                G9(v.y),
                v3.name(),
                G(bound)
            ));
        }
    }

    pub(super) fn zero_or_within(
        &mut self,
        v3: V3,
        field: &str,
        value: f32,
        (low, high): (f32, f32),
        unit: &str,
    ) {
        if value != 0.0 && !(low <= value && value <= high) {
            self.fail(format_args!(
                "{field} {} {unit} lies beyond {}'s working range (0 or within [{}, {}] {unit})",
                G9(value),
                v3.name(),
                G(low),
                G(high)
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_first_problem_is_kept() {
        let mut check = Check::default();
        check.magnitude(V3::V31, "Radius", 2e4, 1e4, "m");
        check.vector(V3::V31, "Position", Vec2 { x: 2e4, y: 0.0 }, 1e4, "m");
        assert!(!check.passed());
        assert_eq!(
            check.problem(),
            "Radius 20000 lies beyond Box2D v3's working range (within +-10000 m)"
        );
    }

    #[test]
    fn a_vector_and_a_range_as_reports_say_them() {
        let mut check = Check::default();
        check.vector(V3::V32, "Position", Vec2 { x: 0.1, y: 2e4 }, 1e4, "m");
        assert_eq!(
            check.problem(),
            "Position (0.100000001, 20000) lies beyond Box2D v3.2's working range (each \
             component within +-10000 m)"
        );
        let mut check = Check::default();
        check.zero_or_within(V3::V31, "its mass", 1e-21, (1e-20, 1e10), "kg");
        assert_eq!(
            check.problem(),
            "its mass 9.99999968e-22 kg lies beyond Box2D v3's working range (0 or within \
             [1e-20, 1e+10] kg)"
        );
        let mut check = Check::default();
        check.zero_or_within(V3::V31, "its mass", 0.0, (1e-20, 1e10), "kg");
        check.magnitude(V3::V31, "Friction", f32::NAN, 1e5, "");
        assert_eq!(
            check.problem(),
            "Friction nan lies beyond Box2D v3's working range (within +-100000 )"
        );
    }
}
