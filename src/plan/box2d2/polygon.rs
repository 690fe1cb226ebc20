//! The mass Box2D 2.x gives a polygon (`b2PolygonShape::ComputeMass`), of the hull that
//! `b2PolygonShape::Set` keeps (`rules::polygon_hull`).

use super::math::{add, cross, dot, mul_sv, sub};
use super::version::PolygonReference;
use crate::plan::records::PlanMass;
use crate::scene::Vec2;

/// `b2PolygonShape::ComputeMass` of the hull `vertices` at `density`: the triangles fanned
/// from the version's reference point summed, the inertia about the body origin.
pub(crate) fn mass(vertices: &[Vec2], density: f32, reference: PolygonReference) -> PlanMass {
    let third = 1.0f32 / 3.0;
    let s = match reference {
        PolygonReference::First => vertices[0],
        PolygonReference::Mean => {
            let sum = vertices.iter().fold(Vec2::ZERO, |s, &v| add(s, v));
            mul_sv(1.0 / vertices.len() as f32, sum)
        }
    };
    let mut center = Vec2::ZERO;
    let mut area = 0.0f32;
    let mut inertia = 0.0f32;
    for (i, &v) in vertices.iter().enumerate() {
        let e1 = sub(v, s);
        let e2 = sub(vertices.get(i + 1).copied().unwrap_or(vertices[0]), s);
        let d = cross(e1, e2);
        let triangle = 0.5 * d;
        area += triangle;
        center = add(center, mul_sv(triangle * third, add(e1, e2)));
        let x2 = e1.x * e1.x + e2.x * e1.x + e2.x * e2.x;
        let y2 = e1.y * e1.y + e2.y * e1.y + e2.y * e2.y;
        inertia += (0.25 * third * d) * (x2 + y2);
    }
    let mass = density * area;
    center = mul_sv(1.0 / area, center);
    let centroid = add(center, s);
    let about_s = density * inertia;
    PlanMass {
        mass,
        center: centroid,
        inertia: about_s + mass * (dot(centroid, centroid) - dot(center, center)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f32, y: f32) -> Vec2 {
        Vec2::new(x, y)
    }

    #[test]
    fn a_square_s_mass_is_its_area_times_density_with_the_box_inertia() {
        let square =
            crate::rules::polygon_hull(&[v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)]);
        let m = mass(&square, 3.0, PolygonReference::First);
        assert_eq!(m.mass, 12.0);
        assert_eq!(m.center, v(1.0, 1.0));
        // about the centre m (a^2 + b^2) / 12 = 8, plus m |c|^2 = 24 about the origin
        assert!((m.inertia - 32.0).abs() < 1e-4, "{}", m.inertia);
        assert_eq!(mass(&square, 3.0, PolygonReference::Mean), m);
    }

    /// Box2D 2.3 fans the triangles from the mean of the vertices, 2.4 from the first: the
    /// same polygon gets other bits. The 2.3 values are pybox2d 2.3.10's `massData` of a
    /// fixture of density 1.3 on this polygon.
    #[test]
    fn box2d_2_3_fans_a_polygon_from_the_mean_of_its_vertices() {
        let points =
            [v(7.5, -1.4), v(10.5, -0.099_999_905), v(9.1, -2.0), v(8.6, 0.5), v(10.3, -1.5)];
        let hull = crate::rules::polygon_hull(&points);
        let mean = mass(&hull, 1.3, PolygonReference::Mean);
        let pybox2d = PlanMass {
            mass: 6.324_500_1,
            center: v(9.111_750_6, -0.806_372_05),
            inertia: 534.347_84,
        };
        assert_eq!(mean, pybox2d);
        let first = mass(&hull, 1.3, PolygonReference::First);
        assert_ne!(first.mass, mean.mass);
        assert_ne!(first.inertia, mean.inertia);
    }
}
