//! The first value of one object found beyond a Box2D 2.x version's working range: what its report
//! says. Later values of the object are not looked at once one is found.

use std::fmt;

use crate::plan::printf::{G, G9};
use crate::scene::Vec2;

#[derive(Clone, Debug)]
pub(super) struct Check {
    /// The version, as its reports name it.
    engine: &'static str,
    problem: Option<String>,
}

impl Check {
    pub(super) fn new(engine: &'static str) -> Check {
        Check { engine, problem: None }
    }

    pub(super) fn passed(&self) -> bool {
        self.problem.is_none()
    }

    pub(super) fn problem(&self) -> &str {
        self.problem.as_deref().unwrap_or_default()
    }

    pub(super) fn magnitude(&mut self, field: &str, value: f32, bound: f32, unit: &str) {
        if self.passed() && !(value.abs() <= bound) {
            self.beyond(format!("{field} {}", G9(value)), format!("within +-{} {unit}", G(bound)));
        }
    }

    pub(super) fn vector(&mut self, field: &str, v: Vec2, bound: f32, unit: &str) {
        if self.passed() && !(v.x.abs() <= bound && v.y.abs() <= bound) {
            self.beyond(
                format!("{field} ({}, {})", G9(v.x), G9(v.y)),
                format!("each component within +-{} {unit}", G(bound)),
            );
        }
    }

    /// `vector` of each point in turn, each named by its place only where it is reported.
    pub(super) fn vectors(
        &mut self,
        name: impl Fn(usize) -> String,
        points: &[Vec2],
        bound: f32,
        unit: &str,
    ) {
        let beyond = |v: &Vec2| !(v.x.abs() <= bound && v.y.abs() <= bound);
        if let Some(i) = points.iter().position(beyond).filter(|_| self.passed()) {
            self.vector(&name(i), points[i], bound, unit);
        }
    }

    pub(super) fn within(&mut self, field: &str, value: f32, low: f32, high: f32, unit: &str) {
        if self.passed() && !(low <= value && value <= high) {
            self.beyond(
                format!("{field} {}", G9(value)),
                format!("within [{}, {}] {unit}", G(low), G(high)),
            );
        }
    }

    pub(super) fn at_least(&mut self, field: &str, value: f32, bound: f32, unit: &str) {
        if self.passed() && !(value >= bound) {
            self.beyond(format!("{field} {}", G9(value)), format!("at least {} {unit}", G(bound)));
        }
    }

    /// 0, or within [low, high]: a derived quantity such as a body's mass.
    pub(super) fn zero_or_within(
        &mut self,
        field: &str,
        value: f32,
        low: f32,
        high: f32,
        unit: &str,
    ) {
        if self.passed() && value != 0.0 && !(low <= value && value <= high) {
            self.beyond(
                format!("{field} {} {unit}", G9(value)),
                format!("0 or within [{}, {}] {unit}", G(low), G(high)),
            );
        }
    }

    /// A problem other than a value beyond its bound (what the engine asserts against,
    /// whatever the bounds), unless one is found already.
    pub(super) fn fail(&mut self, problem: fmt::Arguments<'_>) {
        if self.passed() {
            self.problem = Some(fmt::format(problem));
        }
    }

    fn beyond(&mut self, value: String, range: String) {
        self.problem =
            Some(format!("{value} lies beyond {}'s working range ({range})", self.engine));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_value_beyond_its_bound_is_the_one_reported() {
        let mut check = Check::new("Box2D 2.4");
        check.magnitude("Angle", 1.0, 2.0, "rad");
        assert!(check.passed());
        check.vector("Position", Vec2::new(0.5, -300.0), 100.0, "m");
        check.magnitude("Angle", 9.0, 2.0, "rad");
        assert_eq!(
            check.problem(),
            "Position (0.5, -300) lies beyond Box2D 2.4's working range (each component \
             within +-100 m)"
        );
    }

    #[test]
    fn nan_is_beyond_every_bound_and_an_empty_unit_leaves_a_space() {
        let mut check = Check::new("Box2D 2.4");
        check.magnitude("Friction", f32::NAN, 1e6, "");
        assert_eq!(
            check.problem(),
            "Friction nan lies beyond Box2D 2.4's working range (within +-1e+06 )"
        );
        let mut mass = Check::new("Box2D 2.4");
        mass.zero_or_within("its mass", 0.0, 1e-3, 1e9, "kg");
        assert!(mass.passed());
        mass.zero_or_within("its mass", 1e-6, 1e-3, 1e9, "kg");
        assert_eq!(
            mass.problem(),
            "its mass 9.99999997e-07 kg lies beyond Box2D 2.4's working range (0 or within \
             [0.001, 1e+09] kg)"
        );
        let mut axis = Check::new("Box2D 2.4");
        axis.at_least("The length of LocalAxisA", 0.0, 1e-3, "m");
        axis.within("CorrectionFactor", 2.0, 0.0, 1.0, "");
        assert!(axis.problem().starts_with("The length of LocalAxisA 0 lies beyond"));
    }

    #[test]
    fn a_report_names_the_engine_version_and_keeps_the_first_problem() {
        let mut check = Check::new("Box2D v3.2");
        check.vector("Position", Vec2::new(0.1, 2e4), 1e4, "m");
        check.fail(format_args!("a later problem"));
        assert_eq!(
            check.problem(),
            "Position (0.100000001, 20000) lies beyond Box2D v3.2's working range (each \
             component within +-10000 m)"
        );
        let mut asserted = Check::new("Box2D v3");
        asserted.fail(format_args!("a negative Density, which Box2D v3 asserts against"));
        asserted.magnitude("Density", 1e9, 1e5, "kg/m^2");
        assert_eq!(asserted.problem(), "a negative Density, which Box2D v3 asserts against");
    }

    #[test]
    fn of_many_points_the_first_beyond_is_named_and_only_it() {
        let points = [Vec2::new(1.0, 1.0), Vec2::new(2e5, 0.0), Vec2::new(3e5, 0.0)];
        let mut check = Check::new("Box2D 2.4");
        check.vectors(|i| format!("Vertex {i}"), &points, 1e5, "m");
        assert_eq!(
            check.problem(),
            "Vertex 1 (200000, 0) lies beyond Box2D 2.4's working range (each component within \
             +-100000 m)"
        );
        let mut earlier = Check::new("Box2D 2.4");
        earlier.magnitude("Radius", -1.0, 0.5, "m");
        earlier.vectors(|_| unreachable!("not named once a value is reported"), &points, 1e5, "m");
        assert!(earlier.problem().starts_with("Radius -1 "));
    }
}
