//! The floats near a guess for which a forward computation gives the wanted bits: an
//! inverse computed in floats is off by a few ulps, and the engine's own arithmetic, run
//! forward, decides which float is the one.

/// `x` moved by `steps` representable floats (negative: down).
pub(crate) fn ulps_away(x: f32, steps: i32) -> f32 {
    let mut x = x;
    for _ in 0..steps.unsigned_abs() {
        x = if steps < 0 { x.next_down() } else { x.next_up() };
    }
    x
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
