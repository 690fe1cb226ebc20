//! The mass each kind of Box2D 2.x shape gives at a density (its `ComputeMass`), the
//! inertia about the body origin.

use super::math::{add, dot, mul_sv};
use super::polygon;
use super::version::PolygonReference;
use crate::plan::records::PlanMass;
use crate::scene::Vec2;

use crate::plan::range::PI;

/// A shape as the engine holds it, for its mass.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum MassShape {
    Circle {
        center: Vec2,
        radius: f32,
    },
    /// The hull `b2PolygonShape::Set` keeps.
    Polygon(Vec<Vec2>),
    /// An edge (also a polygon of two vertices): its ends.
    Edge(Vec2, Vec2),
    Chain,
}

impl MassShape {
    /// `ComputeMass(&data, density)`, a polygon's fanned from `reference`.
    pub(crate) fn mass(&self, density: f32, reference: PolygonReference) -> PlanMass {
        match self {
            MassShape::Circle { center, radius } => {
                let mass = density * PI * radius * radius;
                PlanMass {
                    mass,
                    center: *center,
                    inertia: mass * (0.5 * radius * radius + dot(*center, *center)),
                }
            }
            MassShape::Polygon(vertices) => polygon::mass(vertices, density, reference),
            MassShape::Edge(a, b) => {
                PlanMass { mass: 0.0, center: mul_sv(0.5, add(*a, *b)), inertia: 0.0 }
            }
            MassShape::Chain => PlanMass::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_circle_s_inertia_is_about_the_body_origin() {
        let circle = MassShape::Circle { center: Vec2::new(3.0, 4.0), radius: 1.0 };
        let m = circle.mass(2.0, PolygonReference::First);
        assert_eq!(m.mass, 2.0 * PI);
        assert_eq!(m.center, Vec2::new(3.0, 4.0));
        assert_eq!(m.inertia, m.mass * (0.5 + 25.0));
    }

    #[test]
    fn edges_and_chains_have_no_mass() {
        let edge = MassShape::Edge(Vec2::new(0.0, 0.0), Vec2::new(2.0, 4.0))
            .mass(5.0, PolygonReference::First);
        assert_eq!(edge, PlanMass { mass: 0.0, center: Vec2::new(1.0, 2.0), inertia: 0.0 });
        assert_eq!(MassShape::Chain.mass(5.0, PolygonReference::First), PlanMass::default());
    }
}
