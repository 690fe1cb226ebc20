//! Box2D v3's `b2ComputeHull` (`hull.c`, the same in v3.1 and v3.2): quickhull over at most
//! eight points, after welding those closer than four linear slops to an earlier one, and
//! with every point within two slops of the line through its neighbours dropped. Ported
//! step for step, so that the hull a plan hands the executor, and the mass it predicts from
//! it, are the engine's own.

use super::math::{add, cross, distance_squared, max, min, mul_sv, normalize, sub, vec2};
use crate::scene::Vec2;

/// `B2_MAX_POLYGON_VERTICES`.
pub(super) const MAX_POLYGON_VERTICES: usize = 8;

/// The hull of `points` counter-clockwise, or none (empty) where the engine finds none: too
/// few or too many points, all of them welded or collinear.
pub(super) fn compute_hull(points: &[Vec2], linear_slop: f32) -> Vec<Vec2> {
    if points.len() < 3 || points.len() > MAX_POLYGON_VERTICES {
        return Vec::new();
    }
    let (mut ps, lower, upper) = welded(points, linear_slop);
    if ps.len() < 3 {
        return Vec::new();
    }
    let center = mul_sv(0.5, add(lower, upper));
    let p1 = ps.swap_remove(farthest(&ps, center));
    let p2 = ps.swap_remove(farthest(&ps, p1));

    let e = normalize(sub(p2, p1));
    let (mut right, mut left) = (Vec::new(), Vec::new());
    for &p in &ps {
        let d = cross(sub(p, p1), e);
        // Points very near the line p1-p2 belong to neither side.
        if d >= 2.0 * linear_slop {
            right.push(p);
        } else if d <= -2.0 * linear_slop {
            left.push(p);
        }
    }
    let hull1 = recurse(p1, p2, &right, linear_slop);
    let hull2 = recurse(p2, p1, &left, linear_slop);
    if hull1.is_empty() && hull2.is_empty() {
        return Vec::new();
    }
    let mut hull = vec![p1];
    hull.extend_from_slice(&hull1);
    hull.push(p2);
    hull.extend_from_slice(&hull2);
    merge_collinear(&mut hull, linear_slop);
    if hull.len() < 3 {
        hull.clear();
    }
    hull
}

/// The points that lie no closer than four slops to an earlier point (the first always
/// stays), with the bounds of all of them.
fn welded(points: &[Vec2], linear_slop: f32) -> (Vec<Vec2>, Vec2, Vec2) {
    let tolerance = 16.0 * linear_slop * linear_slop;
    let (mut lower, mut upper) = (vec2(f32::MAX, f32::MAX), vec2(-f32::MAX, -f32::MAX));
    let mut unique = Vec::with_capacity(points.len());
    for (i, &p) in points.iter().enumerate() {
        lower = min(lower, p);
        upper = max(upper, p);
        if points[..i].iter().all(|&q| !(distance_squared(p, q) < tolerance)) {
            unique.push(p);
        }
    }
    (unique, lower, upper)
}

/// The index of the point farthest from `from`, the first of equals.
fn farthest(points: &[Vec2], from: Vec2) -> usize {
    let mut best = 0;
    let mut best_distance = distance_squared(from, points[0]);
    for (i, &p) in points.iter().enumerate().skip(1) {
        let d = distance_squared(from, p);
        if d > best_distance {
            best = i;
            best_distance = d;
        }
    }
    best
}

/// The hull of the points right of `p1`-`p2`, between them.
fn recurse(p1: Vec2, p2: Vec2, ps: &[Vec2], linear_slop: f32) -> Vec<Vec2> {
    if ps.is_empty() {
        return Vec::new();
    }
    let e = normalize(sub(p2, p1));
    let mut right = Vec::new();
    let mut best = 0;
    let mut best_distance = cross(sub(ps[0], p1), e);
    if best_distance > 0.0 {
        right.push(ps[0]);
    }
    for (i, &p) in ps.iter().enumerate().skip(1) {
        let distance = cross(sub(p, p1), e);
        if distance > best_distance {
            best = i;
            best_distance = distance;
        }
        if distance > 0.0 {
            right.push(p);
        }
    }
    if best_distance < 2.0 * linear_slop {
        return Vec::new();
    }
    let best_point = ps[best];
    let mut hull = recurse(p1, best_point, &right, linear_slop);
    hull.push(best_point);
    hull.extend(recurse(best_point, p2, &right, linear_slop));
    hull
}

/// Drops, one at a time from the start again, each point within two slops of the line
/// through its neighbours.
fn merge_collinear(hull: &mut Vec<Vec2>, linear_slop: f32) {
    let mut searching = true;
    while searching && hull.len() > 2 {
        searching = false;
        let n = hull.len();
        for i in 0..n {
            let (s1, s2, s3) = (hull[i], hull[(i + 1) % n], hull[(i + 2) % n]);
            let r = normalize(sub(s3, s1));
            if cross(sub(s2, s1), r) <= 2.0 * linear_slop {
                hull.remove((i + 1) % n);
                searching = true;
                break;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SLOP: f32 = 0.005;

    fn points(xy: &[(f32, f32)]) -> Vec<Vec2> {
        xy.iter().map(|&(x, y)| vec2(x, y)).collect()
    }

    #[test]
    fn a_clockwise_box_comes_back_counter_clockwise_from_its_farthest_corner() {
        let square = points(&[(-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]);
        // Every corner is as far from the centre: the first stays p1, the farthest from it
        // (the opposite corner) is p2.
        assert_eq!(
            compute_hull(&square, SLOP),
            points(&[(-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0), (1.0, 1.0)])
        );
    }

    #[test]
    fn inner_welded_and_collinear_points_are_dropped() {
        let input = points(&[
            (0.0, 0.0),
            (2.0, 0.0),
            (1.0, 0.001), // within two slops of the bottom edge
            (2.0, 2.0),
            (2.001, 2.001), // welded to the corner before it
            (0.0, 2.0),
            (1.0, 1.0), // inside
        ]);
        let hull = compute_hull(&input, SLOP);
        assert_eq!(hull.len(), 4);
        for corner in points(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]) {
            assert!(hull.contains(&corner), "{corner:?} in {hull:?}");
        }
    }

    #[test]
    fn too_few_too_many_or_collinear_points_make_no_hull() {
        assert!(compute_hull(&points(&[(0.0, 0.0), (1.0, 0.0)]), SLOP).is_empty());
        let nine: Vec<Vec2> = (0..9).map(|i| rotation_point(i, 9)).collect();
        assert!(compute_hull(&nine, SLOP).is_empty());
        let line = points(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.001)]);
        assert!(compute_hull(&line, SLOP).is_empty());
        let welded = points(&[(0.0, 0.0), (0.001, 0.0), (0.0, 0.001)]);
        assert!(compute_hull(&welded, SLOP).is_empty());
    }

    fn rotation_point(i: usize, n: usize) -> Vec2 {
        let a = i as f32 * std::f32::consts::TAU / n as f32;
        vec2(a.cos(), a.sin())
    }
}
