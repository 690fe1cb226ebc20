//! Box2D 2.x's vector arithmetic (`b2_math.h`) where it is its own: the rest is the plan's
//! shared `math.rs`, which this module hands on.

pub(crate) use crate::plan::math::{
    add, cross, cross_sv, dot, length, mul_sv, rotate, rotation, sub,
};
use crate::plan::records::{Rot, Transform};
use crate::scene::Vec2;

pub(crate) fn distance(a: Vec2, b: Vec2) -> f32 {
    length(sub(a, b))
}

/// `b2Vec2::Normalize`: the unit vector, or `v` unchanged when shorter than `FLT_EPSILON`.
pub(crate) fn normalized(v: Vec2) -> Vec2 {
    let length = length(v);
    if length < f32::EPSILON {
        return v;
    }
    let inverse = 1.0 / length;
    Vec2::new(v.x * inverse, v.y * inverse)
}

/// `b2Rot::GetAngle`.
pub(crate) fn angle(q: Rot) -> f32 {
    q.s.atan2(q.c)
}

/// `b2Mul(xf, v)`: a point of the frame in world terms.
pub(crate) fn transform(xf: Transform, v: Vec2) -> Vec2 {
    Vec2::new((xf.q.c * v.x - xf.q.s * v.y) + xf.p.x, (xf.q.s * v.x + xf.q.c * v.y) + xf.p.y)
}

/// `b2MulT(xf, v)`: a world point in the frame's terms.
pub(crate) fn untransform(xf: Transform, v: Vec2) -> Vec2 {
    let px = v.x - xf.p.x;
    let py = v.y - xf.p.y;
    Vec2::new(xf.q.c * px + xf.q.s * py, -xf.q.s * px + xf.q.c * py)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalising_keeps_a_vector_too_short_to_have_a_direction() {
        let tiny = Vec2::new(1e-8, 0.0);
        assert_eq!(normalized(tiny), tiny);
        assert_eq!(normalized(Vec2::new(3.0, 4.0)), Vec2::new(3.0 * 0.2, 4.0 * 0.2));
    }

    #[test]
    fn a_transform_and_its_inverse_take_a_point_there_and_back() {
        let xf = Transform { p: Vec2::new(1.0, 2.0), q: rotation(std::f32::consts::FRAC_PI_2) };
        let p = transform(xf, Vec2::new(1.0, 0.0));
        assert!((p.x - 1.0).abs() < 1e-6 && (p.y - 3.0).abs() < 1e-6);
        let back = untransform(xf, p);
        assert!((back.x - 1.0).abs() < 1e-6 && back.y.abs() < 1e-6);
        assert_eq!(angle(rotation(0.5)), 0.5f32.sin().atan2(0.5f32.cos()));
    }
}
