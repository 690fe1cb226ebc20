//! Box2D v3's vector arithmetic (`math_functions.h`) where it is its own: the rest is the
//! plan's shared `math.rs`, which this module hands on.

pub(super) use crate::plan::math::{add, cross, cross_sv, length, mul_sv, rotate, sub};
pub(crate) use crate::plan::math::{dot, rotation};
use crate::plan::{Rot, Transform};
use crate::scene::Vec2;

pub(super) const ZERO: Vec2 = Vec2 { x: 0.0, y: 0.0 };
pub(super) const IDENTITY: Rot = Rot { c: 1.0, s: 0.0 };

pub(super) fn vec2(x: f32, y: f32) -> Vec2 {
    Vec2 { x, y }
}

/// `b2MulAdd`: `a + s * b`.
pub(super) fn mul_add(a: Vec2, s: f32, b: Vec2) -> Vec2 {
    vec2(a.x + s * b.x, a.y + s * b.y)
}

pub(super) fn lerp(a: Vec2, b: Vec2, t: f32) -> Vec2 {
    vec2((1.0 - t) * a.x + t * b.x, (1.0 - t) * a.y + t * b.y)
}

pub(super) fn distance(a: Vec2, b: Vec2) -> f32 {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    (dx * dx + dy * dy).sqrt()
}

pub(super) fn distance_squared(a: Vec2, b: Vec2) -> f32 {
    let c = vec2(b.x - a.x, b.y - a.y);
    c.x * c.x + c.y * c.y
}

/// `b2Normalize`: the unit vector, or zero for a vector shorter than `FLT_EPSILON`.
pub(crate) fn normalize(v: Vec2) -> Vec2 {
    let length = (v.x * v.x + v.y * v.y).sqrt();
    if length < f32::EPSILON {
        return ZERO;
    }
    let inverse = 1.0 / length;
    vec2(inverse * v.x, inverse * v.y)
}

/// `b2MinFloat` and `b2MaxFloat` component by component, which keep `a` on a tie or NaN.
pub(super) fn min(a: Vec2, b: Vec2) -> Vec2 {
    vec2(if a.x < b.x { a.x } else { b.x }, if a.y < b.y { a.y } else { b.y })
}

pub(super) fn max(a: Vec2, b: Vec2) -> Vec2 {
    vec2(if a.x > b.x { a.x } else { b.x }, if a.y > b.y { a.y } else { b.y })
}

pub(super) fn mul_rot(q: Rot, r: Rot) -> Rot {
    Rot { s: q.s * r.c + q.c * r.s, c: q.c * r.c - q.s * r.s }
}

pub(super) fn inv_mul_rot(q: Rot, r: Rot) -> Rot {
    Rot { s: q.c * r.s - q.s * r.c, c: q.c * r.c + q.s * r.s }
}

pub(super) fn transform_point(t: Transform, p: Vec2) -> Vec2 {
    vec2((t.q.c * p.x - t.q.s * p.y) + t.p.x, (t.q.s * p.x + t.q.c * p.y) + t.p.y)
}

pub(super) fn inv_transform_point(t: Transform, p: Vec2) -> Vec2 {
    let (vx, vy) = (p.x - t.p.x, p.y - t.p.y);
    vec2(t.q.c * vx + t.q.s * vy, -t.q.s * vx + t.q.c * vy)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalize_gives_zero_below_flt_epsilon() {
        assert_eq!(normalize(vec2(3.0, 4.0)), vec2(0.6, 0.8));
        assert_eq!(normalize(vec2(1e-8, 0.0)), ZERO);
    }

    #[test]
    fn a_point_transformed_and_back_and_rotations_composed() {
        let t = Transform { p: vec2(1.0, 2.0), q: Rot { c: 0.0, s: 1.0 } };
        assert_eq!(transform_point(t, vec2(1.0, 0.0)), vec2(1.0, 3.0));
        assert_eq!(inv_transform_point(t, vec2(1.0, 3.0)), vec2(1.0, 0.0));
        let quarter = Rot { c: 0.0, s: 1.0 };
        assert_eq!(mul_rot(quarter, quarter), Rot { c: -1.0, s: 0.0 });
        assert_eq!(inv_mul_rot(quarter, quarter), IDENTITY);
        assert_eq!(rotate(quarter, vec2(1.0, 0.0)), vec2(0.0, 1.0));
        assert_eq!(cross_sv(2.0, vec2(1.0, 0.0)), vec2(0.0, 2.0));
    }
}
