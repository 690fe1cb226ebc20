//! What Box2D v3 computes of a shape before a body takes it (`geometry.c`): a polygon's
//! centroid (`b2MakePolygon`) and the mass of a polygon and a circle, operation for
//! operation. v3.1 gives a shape's inertia about the body origin, v3.2 about its centroid.

use super::math::{add, cross, dot, mul_add, sub, vec2};
use super::version::V3;
use crate::plan::range::PI;
use crate::scene::Vec2;

/// A shape's or a body's mass as Box2D v3 holds it (`b2MassData`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Mass {
    /// kg.
    pub mass: f32,
    /// m, in the body's frame.
    pub center: Vec2,
    /// kg m^2, about the point the version measures it from.
    pub inertia: f32,
}

/// `b2ComputePolygonCentroid` of a hull's points.
pub(super) fn polygon_centroid(vertices: &[Vec2]) -> Vec2 {
    let mut center = vec2(0.0, 0.0);
    let mut area = 0.0f32;
    let origin = vertices[0];
    let inv3 = 1.0f32 / 3.0;
    for i in 1..vertices.len() - 1 {
        let e1 = sub(vertices[i], origin);
        let e2 = sub(vertices[i + 1], origin);
        let a = 0.5 * cross(e1, e2);
        center = mul_add(center, a * inv3, add(e1, e2));
        area += a;
    }
    let inverse = 1.0 / area;
    center.x *= inverse;
    center.y *= inverse;
    add(origin, center)
}

/// The signed area of a hull as the executor's check sums it: v3 asserts, as it computes
/// the centroid, that it exceeds `FLT_EPSILON`.
pub(super) fn hull_area(hull: &[Vec2]) -> f32 {
    let mut area = 0.0f32;
    for i in 1..hull.len().saturating_sub(1) {
        area += cross(sub(hull[i], hull[0]), sub(hull[i + 1], hull[0]));
    }
    0.5 * area
}

/// `b2ComputePolygonMass` of a polygon of radius 0 made of a hull of three points or more.
pub(crate) fn polygon_mass(v3: V3, vertices: &[Vec2], density: f32) -> Mass {
    let mut center = vec2(0.0, 0.0);
    let mut area = 0.0f32;
    let mut inertia = 0.0f32;
    let r = vertices[0];
    let inv3 = 1.0f32 / 3.0;
    for i in 1..vertices.len() - 1 {
        let e1 = sub(vertices[i], r);
        let e2 = sub(vertices[i + 1], r);
        let d = cross(e1, e2);
        let triangle_area = 0.5 * d;
        area += triangle_area;
        center = mul_add(center, triangle_area * inv3, add(e1, e2));
        let intx2 = e1.x * e1.x + e2.x * e1.x + e2.x * e2.x;
        let inty2 = e1.y * e1.y + e2.y * e1.y + e2.y * e2.y;
        inertia += (0.25 * inv3 * d) * (intx2 + inty2);
    }
    let mass = density * area;
    let inverse = 1.0 / area;
    center.x *= inverse;
    center.y *= inverse;
    let centroid = add(r, center);
    let mut rotational = density * inertia;
    if v3.inertia_about_origin() {
        rotational += mass * (dot(centroid, centroid) - dot(center, center));
    } else {
        rotational -= mass * dot(center, center);
    }
    Mass { mass, center: centroid, inertia: rotational }
}

/// `b2ComputeCircleMass`.
pub(crate) fn circle_mass(v3: V3, center: Vec2, radius: f32, density: f32) -> Mass {
    let rr = radius * radius;
    let mass = density * PI * rr;
    let inertia = if v3.inertia_about_origin() {
        mass * (0.5 * rr + dot(center, center))
    } else {
        mass * 0.5 * rr
    };
    Mass { mass, center, inertia }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square() -> Vec<Vec2> {
        [(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)].map(|(x, y)| vec2(x, y)).to_vec()
    }

    #[test]
    fn a_square_off_the_origin_has_its_centre_as_centroid() {
        assert_eq!(polygon_centroid(&square()), vec2(2.0, 2.0));
        assert_eq!(hull_area(&square()), 4.0);
    }

    #[test]
    fn v31_measures_inertia_about_the_origin_and_v32_about_the_centroid() {
        // A 2 m square of density 1: 4 kg, 4 * (4 + 4) / 12 kg m^2 about its centre.
        let v32 = polygon_mass(V3::V32, &square(), 1.0);
        assert_eq!((v32.mass, v32.center), (4.0, vec2(2.0, 2.0)));
        assert!((v32.inertia - 32.0 / 12.0).abs() < 1e-5, "{}", v32.inertia);
        let v31 = polygon_mass(V3::V31, &square(), 1.0);
        assert!((v31.inertia - (32.0 / 12.0 + 4.0 * 8.0)).abs() < 1e-4, "{}", v31.inertia);

        let circle31 = circle_mass(V3::V31, vec2(3.0, 4.0), 2.0, 0.5);
        let circle32 = circle_mass(V3::V32, vec2(3.0, 4.0), 2.0, 0.5);
        assert_eq!(circle31.mass, 0.5 * PI * 4.0);
        assert_eq!(circle32.inertia, circle32.mass * 0.5 * 4.0);
        assert_eq!(circle31.inertia, circle31.mass * (2.0 + 25.0));
    }
}
