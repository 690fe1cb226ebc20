//! The vector arithmetic every Box2D version writes alike (2.x's `b2_math.h`, v3's
//! `math_functions.h`), one float operation at a time in the engines' order, so that what a
//! plan predicts agrees with the engine to the bit. Rust neither reorders nor fuses float
//! operations, as the engines' builds do not. What a version does its own way (normalising
//! a short vector, its distance) stays in its module's `math.rs`.

use super::records::Rot;
use crate::scene::Vec2;

pub(crate) fn add(a: Vec2, b: Vec2) -> Vec2 {
    Vec2::new(a.x + b.x, a.y + b.y)
}

pub(crate) fn sub(a: Vec2, b: Vec2) -> Vec2 {
    Vec2::new(a.x - b.x, a.y - b.y)
}

/// `s * v` (2.x `b2Vec2 operator*`, v3 `b2MulSV`).
pub(crate) fn mul_sv(s: f32, v: Vec2) -> Vec2 {
    Vec2::new(s * v.x, s * v.y)
}

/// `end` continued by one segment away from `inner`: a ghost vertex for an open chain end
/// that has none (Box2D 2.4's `CreateChain` and v3's chains need both).
pub(crate) fn extrapolated(end: Vec2, inner: Vec2) -> Vec2 {
    add(end, sub(end, inner))
}

pub(crate) fn dot(a: Vec2, b: Vec2) -> f32 {
    a.x * b.x + a.y * b.y
}

/// The 2D cross product of two vectors (`b2Cross(a, b)`).
pub(crate) fn cross(a: Vec2, b: Vec2) -> f32 {
    a.x * b.y - a.y * b.x
}

/// A scalar crossed with a vector, `s x v` (2.x `b2Cross(s, v)`, v3 `b2CrossSV`): what a
/// turning at `s` gives a point at `v` from the axis.
pub(crate) fn cross_sv(s: f32, v: Vec2) -> Vec2 {
    Vec2::new(-s * v.y, s * v.x)
}

pub(crate) fn length(v: Vec2) -> f32 {
    (v.x * v.x + v.y * v.y).sqrt()
}

/// The rotation of an angle as its cosine and sine: the C library's `cosf` and `sinf`,
/// which Rust's `f32` methods call (2.x `b2Rot(angle)`; not v3's `b2MakeRot`, which
/// approximates).
pub(crate) fn rotation(angle: f32) -> Rot {
    Rot { c: angle.cos(), s: angle.sin() }
}

/// `v` turned by `q` (2.x `b2Mul(q, v)`, v3 `b2RotateVector`).
pub(crate) fn rotate(q: Rot, v: Vec2) -> Vec2 {
    Vec2::new(q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y)
}
