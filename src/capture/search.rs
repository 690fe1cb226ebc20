//! The floats near a guess for which a forward computation gives the wanted bits: an
//! inverse computed in floats is off by a few ulps, and the engine's own arithmetic, run
//! forward (the plan's), decides which float is the one. `nearest` and `nearest_pair` walk
//! out from the guess, nearest first, and stop at the first float that does;
//! `solve_nondecreasing` walks one way along a forward computation that never decreases.

use crate::scene::Vec2;

/// How many ulps from its guess a search looks for one value.
const RADIUS: i32 = 16;
/// How many ulps from its guess, in each component, a search looks for a pair.
const PAIR_RADIUS: i32 = 8;

/// One representable float from `x` toward `FLT_MAX` (`up`) or `-FLT_MAX`, as C's
/// `nextafterf` steps toward them.
fn step(x: f32, up: bool) -> f32 {
    match (up, x) {
        (_, x) if x.is_nan() => x,
        (true, x) if x < f32::MAX => x.next_up(),
        (true, x) if x == f32::MAX => x,
        (true, _) => f32::MAX,
        (false, x) if x > f32::MIN => x.next_down(),
        (false, x) if x == f32::MIN => x,
        (false, _) => f32::MIN,
    }
}

/// `x` moved by `steps` representable floats (upward for positive steps).
pub(crate) fn ulps_away(x: f32, steps: i32) -> f32 {
    (0..steps.unsigned_abs()).fold(x, |x, _| step(x, steps > 0))
}

/// The float nearest `guess` (within 16 ulps, below before above) for which `gives`
/// holds; `Err(guess)` when none does.
pub(crate) fn nearest(guess: f32, gives: impl Fn(f32) -> bool) -> Result<f32, f32> {
    (0..=RADIUS).flat_map(|k| [-k, k]).map(|k| ulps_away(guess, k)).find(|&x| gives(x)).ok_or(guess)
}

/// The pair nearest `guess` (the rings of 8 ulps around it, nearest first) for which
/// `gives` holds; `Err(guess)` when none does.
pub(crate) fn nearest_pair(guess: Vec2, gives: impl Fn(Vec2) -> bool) -> Result<Vec2, Vec2> {
    (0..=PAIR_RADIUS)
        .flat_map(|k| {
            (-k..=k).flat_map(move |dx| {
                (-k..=k).filter(move |dy| dx.abs() == k || dy.abs() == k).map(move |dy| (dx, dy))
            })
        })
        .map(|(dx, dy)| Vec2::new(ulps_away(guess.x, dx), ulps_away(guess.y, dy)))
        .find(|&v| gives(v))
        .ok_or(guess)
}

/// The argument near `guess` for which `f`, which never decreases, gives `target`, and
/// whether it gives it exactly; where no float does, the one that comes nearest. Zeros of
/// either sign count as equal.
pub(crate) fn solve_nondecreasing(f: impl Fn(f32) -> f32, target: f32, guess: f32) -> (f32, bool) {
    let mut x = guess;
    let mut y = f(x);
    if y == target {
        return (x, true);
    }
    let upward = y < target;
    for _ in 0..64 {
        let next = if upward { x.next_up() } else { x.next_down() };
        let z = f(next);
        if z == target {
            return (next, true);
        }
        if (z < target) != upward {
            // stepped over: no float gives it
            let nearer = (z - target).abs() < (y - target).abs();
            return (if nearer { next } else { x }, false);
        }
        x = next;
        y = z;
    }
    (x, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_nextafterf_toward_the_largest_floats() {
        assert_eq!(ulps_away(1.0, 1), 1.0 + f32::EPSILON);
        assert_eq!(ulps_away(1.0, -2), 1.0 - f32::EPSILON);
        assert_eq!(ulps_away(0.0, 1), f32::from_bits(1));
        assert_eq!(ulps_away(f32::MAX, 3), f32::MAX);
        assert_eq!(ulps_away(f32::INFINITY, 1), f32::MAX);
        assert_eq!(ulps_away(f32::NEG_INFINITY, -1), f32::MIN);
        assert!(ulps_away(f32::NAN, 2).is_nan());
    }

    #[test]
    fn the_nearest_float_that_gives_the_bits_below_before_above() {
        let wanted = 1.0 + 4.0 * f32::EPSILON;
        assert_eq!(nearest(1.0, |x| x == wanted), Ok(wanted));
        // Two ulps away on both sides: the one below is met first.
        let (below, above) = (ulps_away(1.5, -2), ulps_away(1.5, 2));
        assert_eq!(nearest(1.5, |x| x == below || x == above), Ok(below));
        assert_eq!(nearest(1.5, |x| x == ulps_away(1.5, 17)), Err(1.5));
    }

    #[test]
    fn the_nearest_pair_walks_rings() {
        let target = Vec2::new(ulps_away(0.6, 3), ulps_away(0.8, -1));
        assert_eq!(nearest_pair(Vec2::new(0.6, 0.8), |v| v == target), Ok(target));
        // Ring 1 before ring 2, whichever component moves.
        let near = Vec2::new(ulps_away(0.6, 1), 0.8);
        let far = Vec2::new(0.6, ulps_away(0.8, 2));
        assert_eq!(nearest_pair(Vec2::new(0.6, 0.8), |v| v == near || v == far), Ok(near));
        let guess = Vec2::new(0.6, 0.8);
        assert_eq!(nearest_pair(guess, |v| v.x == ulps_away(0.6, 9)), Err(guess));
    }

    #[test]
    fn the_search_finds_the_float_a_forward_computation_maps_onto_the_target() {
        let square = |x: f32| x * x;
        let target = square(1.7);
        let (x, exact) = solve_nondecreasing(square, target, ulps_away(1.7, 3));
        assert!(exact);
        assert_eq!(square(x).to_bits(), target.to_bits());
        let (x, exact) = solve_nondecreasing(square, target, ulps_away(1.7, -3));
        assert!(exact);
        assert_eq!(square(x).to_bits(), target.to_bits());
    }

    #[test]
    fn a_target_no_float_reaches_gives_the_nearest_and_says_so() {
        // floor jumps from 1 to 2 between two neighbouring floats: 1.5 lies between
        let below_two = 2.0f32.next_down();
        assert_eq!(solve_nondecreasing(f32::floor, 1.5, below_two), (below_two, false));
        assert_eq!(solve_nondecreasing(f32::floor, 1.75, below_two), (2.0, false));
    }

    #[test]
    fn ulps_away_steps_through_neighbouring_floats() {
        assert_eq!(ulps_away(1.0, 1), 1.0f32.next_up());
        assert_eq!(ulps_away(1.0, -2), 1.0f32.next_down().next_down());
        assert_eq!(ulps_away(1.0, 0), 1.0);
    }
}
