//! A polygon as Box2D 2.x holds it: the convex hull `b2PolygonShape::Set` makes of the
//! points it is given, and the mass `b2PolygonShape::ComputeMass` gives it.

use super::math::{add, cross, dot, scale, sub};
use crate::plan::records::PlanMass;
use crate::scene::Vec2;

/// `b2_maxPolygonVertices` in `b2_settings.h`.
pub(crate) const MAX_POLYGON_VERTICES: usize = 8;

/// `b2_linearSlop` at one length unit per metre.
const LINEAR_SLOP: f32 = 0.005;

/// The vertices `b2PolygonShape::Set` keeps of `points`, counter-clockwise from the
/// rightmost (lowest of the rightmost): points closer than half the linear slop to an
/// earlier one are welded to it, and of the rest the gift-wrapped hull is kept, without
/// collinear points between its corners. `None` where the engine finds no polygon (fewer
/// than three points left, or a hull of fewer than three), which it asserts against.
pub(crate) fn hull(points: &[Vec2]) -> Option<Vec<Vec2>> {
    let weld = (0.5 * LINEAR_SLOP) * (0.5 * LINEAR_SLOP);
    let mut kept: Vec<Vec2> = Vec::with_capacity(MAX_POLYGON_VERTICES);
    for &p in points.iter().take(MAX_POLYGON_VERTICES) {
        if kept.iter().all(|&q| !(distance_squared(p, q) < weld)) {
            kept.push(p);
        }
    }
    if kept.len() < 3 {
        return None;
    }
    let first = rightmost(&kept);
    let mut corners = Vec::with_capacity(kept.len());
    let mut current = first;
    loop {
        corners.push(current);
        current = next_corner(&kept, current);
        if current == first {
            break;
        }
        if corners.len() == MAX_POLYGON_VERTICES {
            return None;
        }
    }
    (corners.len() >= 3).then(|| corners.iter().map(|&i| kept[i]).collect())
}

fn distance_squared(a: Vec2, b: Vec2) -> f32 {
    let d = sub(a, b);
    dot(d, d)
}

/// The point of greatest x, of those the one of least y: where the wrapping starts.
fn rightmost(points: &[Vec2]) -> usize {
    let mut best = 0;
    let mut x0 = points[0].x;
    for (i, p) in points.iter().enumerate().skip(1) {
        if p.x > x0 || (p.x == x0 && p.y < points[best].y) {
            best = i;
            x0 = p.x;
        }
    }
    best
}

/// The hull's corner after `from`: the point every other lies left of, the farthest of
/// those in line with it.
fn next_corner(points: &[Vec2], from: usize) -> usize {
    let origin = points[from];
    let mut candidate = 0;
    for j in 1..points.len() {
        if candidate == from {
            candidate = j;
            continue;
        }
        let r = sub(points[candidate], origin);
        let v = sub(points[j], origin);
        let c = cross(r, v);
        if c < 0.0 {
            candidate = j;
        }
        if c == 0.0 && dot(v, v) > dot(r, r) {
            candidate = j;
        }
    }
    candidate
}

/// `b2PolygonShape::ComputeMass` of the hull `vertices` at `density`: the triangles fanned
/// from the first vertex summed, the inertia about the body origin.
pub(crate) fn mass(vertices: &[Vec2], density: f32) -> PlanMass {
    let third = 1.0f32 / 3.0;
    let s = vertices[0];
    let mut center = Vec2::ZERO;
    let mut area = 0.0f32;
    let mut inertia = 0.0f32;
    for (i, &v) in vertices.iter().enumerate() {
        let e1 = sub(v, s);
        let e2 = sub(vertices.get(i + 1).copied().unwrap_or(vertices[0]), s);
        let d = cross(e1, e2);
        let triangle = 0.5 * d;
        area += triangle;
        center = add(center, scale(triangle * third, add(e1, e2)));
        let x2 = e1.x * e1.x + e2.x * e1.x + e2.x * e2.x;
        let y2 = e1.y * e1.y + e2.y * e1.y + e2.y * e2.y;
        inertia += (0.25 * third * d) * (x2 + y2);
    }
    let mass = density * area;
    center = scale(1.0 / area, center);
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
    fn the_hull_starts_at_the_rightmost_lowest_point_and_turns_counter_clockwise() {
        let square = [v(-1.0, -1.0), v(-1.0, 1.0), v(1.0, 1.0), v(1.0, -1.0)];
        assert_eq!(
            hull(&square).unwrap(),
            vec![v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0), v(-1.0, -1.0)]
        );
    }

    #[test]
    fn the_hull_drops_inner_and_collinear_points_and_welds_near_ones() {
        let points = [
            v(0.0, 0.0),
            v(2.0, 0.0),
            v(1.0, 0.0), // on an edge
            v(1.0, 0.5), // inside
            v(2.0, 2.0),
            v(2.001, 2.0), // within half the linear slop of the last
            v(0.0, 2.0),
        ];
        assert_eq!(
            hull(&points).unwrap(),
            vec![v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0), v(0.0, 0.0)]
        );
    }

    #[test]
    fn the_hull_keeps_only_the_first_eight_points() {
        let mut points: Vec<Vec2> = (0..8).map(|i| v(i as f32, (i * i) as f32)).collect();
        points.push(v(100.0, -100.0));
        assert_eq!(hull(&points).unwrap().len(), 8);
    }

    #[test]
    fn points_that_weld_or_lie_in_a_line_make_no_polygon() {
        assert_eq!(hull(&[v(0.0, 0.0), v(0.001, 0.0), v(0.0, 0.001)]), None);
        assert_eq!(hull(&[v(0.0, 0.0), v(1.0, 0.0), v(2.0, 0.0)]), None);
    }

    #[test]
    fn a_square_s_mass_is_its_area_times_density_with_the_box_inertia() {
        let square = hull(&[v(0.0, 0.0), v(2.0, 0.0), v(2.0, 2.0), v(0.0, 2.0)]).unwrap();
        let m = mass(&square, 3.0);
        assert_eq!(m.mass, 12.0);
        assert_eq!(m.center, v(1.0, 1.0));
        // about the centre m (a^2 + b^2) / 12 = 8, plus m |c|^2 = 24 about the origin
        assert!((m.inertia - 32.0).abs() < 1e-4, "{}", m.inertia);
    }
}
