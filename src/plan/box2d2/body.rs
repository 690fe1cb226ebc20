//! A Box2D 2.x body as the executor will have made it, for what the joints read of it:
//! where it is (`b2Body::GetTransform`, its angle through `sinf` and `cosf`) and its mass
//! (`GetMass`, `GetInertia`, `GetLocalCenter`, `GetWorldCenter`).

use super::math::{dot, rotation, transform, untransform};
use crate::plan::records::{PlanMass, Transform};
use crate::scene::{BodyKind, Vec2};

/// A created body: its frame and the mass it holds, the inertia about its centre of mass
/// (`m_I`). A static or kinematic body, or one without mass, holds zeros.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Body {
    pub frame: Transform,
    pub mass: PlanMass,
    pub kind: BodyKind,
}

impl Body {
    /// A body created at `position` and `angle` holding `mass`.
    pub(crate) fn new(position: Vec2, angle: f32, mass: PlanMass, kind: BodyKind) -> Body {
        Body { frame: Transform { p: position, q: rotation(angle) }, mass, kind }
    }

    /// `GetInertia`: about the origin.
    pub(crate) fn inertia(&self) -> f32 {
        let c = self.mass.center;
        self.mass.inertia + self.mass.mass * dot(c, c)
    }

    /// `GetWorldCenter`: the centre of mass where the body is.
    pub(crate) fn world_center(&self) -> Vec2 {
        transform(self.frame, self.mass.center)
    }

    /// `GetWorldPoint`.
    pub(crate) fn world_point(&self, local: Vec2) -> Vec2 {
        transform(self.frame, local)
    }

    /// `GetLocalPoint`.
    pub(crate) fn local_point(&self, world: Vec2) -> Vec2 {
        untransform(self.frame, world)
    }

    /// 1/I about the centre of mass as the adapter has always computed it from the
    /// engine's getters (`GetInertia() - GetMass() * |c|^2`, which need not give back
    /// `m_I`'s bits), 0 for a body that does not turn.
    pub(crate) fn inverse_central_inertia(&self) -> f32 {
        let c = self.mass.center;
        let inertia = self.inertia() - self.mass.mass * dot(c, c);
        if inertia > 0.0 { 1.0 / inertia } else { 0.0 }
    }

    /// 1/m, 0 for a body without mass.
    pub(crate) fn inverse_mass(&self) -> f32 {
        if self.mass.mass > 0.0 { 1.0 / self.mass.mass } else { 0.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_centre_of_mass_turns_with_the_body() {
        let mass = PlanMass { mass: 2.0, center: Vec2::new(1.0, 0.0), inertia: 3.0 };
        let body = Body::new(Vec2::new(5.0, 0.0), std::f32::consts::PI, mass, BodyKind::Dynamic);
        let c = body.world_center();
        assert!((c.x - 4.0).abs() < 1e-6 && c.y.abs() < 1e-6);
        assert_eq!(body.inertia(), 5.0);
        assert_eq!(body.inverse_central_inertia(), 1.0 / 3.0);
        assert_eq!(body.inverse_mass(), 0.5);
        let back = body.local_point(body.world_point(Vec2::new(0.5, 0.25)));
        assert!((back.x - 0.5).abs() < 1e-6 && (back.y - 0.25).abs() < 1e-6);
    }

    #[test]
    fn a_body_without_mass_neither_moves_nor_turns() {
        let body = Body::new(Vec2::ZERO, 0.0, PlanMass::default(), BodyKind::Static);
        assert_eq!(body.inverse_mass(), 0.0);
        assert_eq!(body.inverse_central_inertia(), 0.0);
    }
}
