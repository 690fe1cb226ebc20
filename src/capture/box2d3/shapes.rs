//! Shapes and fixtures: a v3 shape as the format's, a chain regrouped from the segments the
//! build made of it, and a filter in the format's widths.

use crate::capture::HeldShape;
use crate::capture::world::Say;
use crate::plan::PlanShapeKind;
use crate::plan::box2d3::V3;
use crate::plan::math::extrapolated;
use crate::plan::printf::G9;
use crate::scene::{Filter, Fixture, NONE, Shape, ShapeKind, Vec2};

/// A chain segment's points, `[ghost, ends, ghost]`, or `None` where it has not four.
fn segment(held: &HeldShape, points: &[Vec2]) -> Option<[Vec2; 4]> {
    points.get(held.shape.points.indices())?.try_into().ok()
}

/// Whether segment `next` continues `cur` as the build makes consecutive edges.
fn continues(cur: &[Vec2; 4], next: &[Vec2; 4]) -> bool {
    next[0] == cur[1] && next[1] == cur[2] && next[2] == cur[3]
}

/// Whether a held shape is a chain's segment.
pub(super) fn in_chain(held: &HeldShape) -> bool {
    held.chain != NONE
}

/// How many of `rest`, a body's held shapes from a chain's first segment on, make that
/// chain: v3.1's chain object whole (the segments marked with its `chain`); of v3.2's loose
/// segments those that continue the first, up to the one that closes a loop (a loop built
/// beside another of the same points must not run into it).
pub(crate) fn chain_length(v3: V3, rest: &[HeldShape], points: &[Vec2]) -> usize {
    let chain = rest[0].chain;
    let marked = rest.iter().take_while(|s| s.chain == chain);
    if v3.chains_are_objects() {
        return marked.count();
    }
    let mut segments = marked.map(|s| segment(s, points));
    let Some(Some(head)) = segments.next() else { return 1 };
    let mut cur = head;
    let mut length = 1;
    for next in segments {
        match next {
            Some(next) if !(length >= 3 && continues(&cur, &head)) && continues(&cur, &next) => {
                cur = next;
                length += 1;
            }
            _ => break,
        }
    }
    length
}

/// The scene shape (no name) and its vertices for one held shape, or for a chain's
/// segments in their order.
pub(crate) fn shape(
    v3: V3,
    run: &[HeldShape],
    points: &[Vec2],
    say: &mut Say,
) -> Option<(Shape, Vec<Vec2>)> {
    let held = &run[0];
    if in_chain(held) {
        let segments: Option<Vec<[Vec2; 4]>> = run.iter().map(|s| segment(s, points)).collect();
        if segments.is_none() {
            say.lossy(format_args!("a chain segment without its four points; not written"));
        }
        return segments.map(|segments| chain(v3, &segments));
    }
    let Some(vertices) = points.get(held.shape.points.indices()).map(<[Vec2]>::to_vec) else {
        say.lossy(format_args!("its points lie outside the held points; not written"));
        return None;
    };
    let Ok(kind) = PlanShapeKind::try_from(held.shape.kind) else {
        say.lossy(format_args!(
            "a shape of kind {} has no Box2Scene form; not written",
            held.shape.kind
        ));
        return None;
    };
    let shape = match kind {
        PlanShapeKind::Circle => {
            let mut circle = Shape::new(ShapeKind::Circle);
            circle.radius = held.shape.radius;
            circle.position = held.shape.center;
            return Some((circle, Vec::new()));
        }
        PlanShapeKind::Polygon => {
            if held.shape.radius > 0.0 {
                say.lossy(format_args!(
                    "a rounded polygon (radius {} m): written without its rounding",
                    G9(held.shape.radius)
                ));
            }
            Shape::new(ShapeKind::Polygon)
        }
        PlanShapeKind::Segment => Shape::new(ShapeKind::Edge),
        PlanShapeKind::Chain | PlanShapeKind::Loop => {
            let looped = kind == PlanShapeKind::Loop;
            return whole_chain(looped, vertices, say).map(|segments| chain(v3, &segments));
        }
    };
    Some((shape, vertices))
}

/// The fixture (its shape left for the caller) that carries the shape of `run`: the
/// material of its first shape, a chain's without density (it has no mass).
pub(crate) fn fixture(held: &HeldShape, say: &mut Say) -> Fixture {
    Fixture {
        density: if in_chain(held) { 0.0 } else { held.shape.density },
        friction: held.shape.friction,
        restitution: held.shape.restitution,
        is_sensor: held.shape.is_sensor,
        filter: filter(held, say),
        ..Fixture::default()
    }
}

/// The segments of a chain held whole, as the plan gives it (a binding that cannot read a
/// chain's segments keeps the build's): an open chain's points `[ghost, vertices..., ghost]`,
/// a loop's its vertices. A ghost the binding could not read (NaN) is extrapolated from its
/// end, as the plan extrapolates one the file leaves out, and reported.
fn whole_chain(looped: bool, mut points: Vec<Vec2>, say: &mut Say) -> Option<Vec<[Vec2; 4]>> {
    let n = points.len();
    let least = if looped { 3 } else { 4 };
    if n < least {
        let what = if looped { "a loop" } else { "an open chain" };
        say.lossy(format_args!("{what} of {n} points, where one has {least} or more; not written"));
        return None;
    }
    if looped {
        let at = |i: usize| points[i % n];
        return Some((0..n).map(|i| [at(i + n - 1), at(i), at(i + 1), at(i + 2)]).collect());
    }
    let unread = [0, n - 1].into_iter().filter(|&i| points[i].x.is_nan() || points[i].y.is_nan());
    let unread: Vec<usize> = unread.collect();
    for &i in &unread {
        let (end, inner) =
            if i == 0 { (points[1], points[2]) } else { (points[n - 2], points[n - 3]) };
        points[i] = extrapolated(end, inner);
    }
    if !unread.is_empty() {
        say.lossy(format_args!(
            "its ghost points were not read: extrapolated from the chain's ends"
        ));
    }
    Some(points.windows(4).map(|w| [w[0], w[1], w[2], w[3]]).collect())
}

/// The chain (or edge with ghost vertices) that a chain's segments make: a loop when the
/// last continues into the first, else open with its ghosts.
fn chain(v3: V3, segments: &[[Vec2; 4]]) -> (Shape, Vec<Vec2>) {
    let (head, tail) = (&segments[0], &segments[segments.len() - 1]);
    let lone = segments.len() == 1;
    let mut shape = Shape::new(if lone { v3.lone_segment() } else { ShapeKind::Chain });
    let mut vertices: Vec<Vec2> = segments.iter().map(|s| s[1]).collect();
    if segments.len() >= 3 && continues(tail, head) {
        shape.is_loop = true;
    } else {
        vertices.push(tail[2]);
        shape.has_prev_vertex = true;
        shape.prev_vertex = head[0];
        shape.has_next_vertex = true;
        shape.next_vertex = tail[3];
    }
    (shape, vertices)
}

/// The filter in the format's widths (its fields' sizes say them): a mask with every
/// higher bit set is "all"; what is beyond them is reported and the low bits written.
fn filter(held: &HeldShape, say: &mut Say) -> Filter {
    let (category, mask, group) = (held.category_bits, held.mask_bits, held.group_index);
    let low = u64::from(u32::MAX);
    let high_mask = mask & !low;
    let group_fits = i16::try_from(group).is_ok();
    let exact = category & !low == 0 && (high_mask == 0 || high_mask == !low) && group_fits;
    if !exact {
        let (bits, group_bits) = (u32::BITS, i16::BITS);
        say.lossy(format_args!(
            "its filter (category 0x{category:x}, mask 0x{mask:x}, group {group}) has bits \
             above the format's {bits} or a group beyond {group_bits} bits; the low {bits} bits \
             were written"
        ));
    }
    Filter {
        category_bits: (category & low) as u32,
        mask_bits: (mask & low) as u32,
        group_index: group.clamp(i32::from(i16::MIN), i32::from(i16::MAX)) as i16,
    }
}
