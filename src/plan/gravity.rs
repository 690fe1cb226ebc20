//! The gravity a world is made with: the file's, where the engine version holds it (each
//! component within its working range's `max_acceleration`); else the host's fallback.

use super::range::{Engine, WorkingRange};
use crate::scene::{Scene, Vec2};

/// Whether a gravity lies within the working range.
pub(super) fn gravity_fits(range: &WorkingRange, g: Vec2) -> bool {
    g.x.abs() <= range.max_acceleration && g.y.abs() <= range.max_acceleration
}

/// The file's gravity for a world of `engine`, or `None` where the file gives none or one
/// beyond the engine's working range (the plan reports that), and the host's fallback
/// applies.
pub fn world_gravity(scene: &Scene, engine: Engine) -> Option<Vec2> {
    scene.gravity().filter(|&g| gravity_fits(engine.working_range(), g))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(gravity: &str) -> Scene {
        let text = format!("<World Version=\"2\">{gravity}</World>");
        crate::load(text.as_bytes(), &Default::default()).unwrap()
    }

    #[test]
    fn the_files_gravity_where_the_engine_holds_it() {
        let g = Vec2 { x: 0.0, y: -10.0 };
        assert_eq!(world_gravity(&scene("<Gravity>0 -10</Gravity>"), Engine::Box2d31), Some(g));
        assert_eq!(world_gravity(&scene(""), Engine::Box2d31), None);
        let strong = scene("<Gravity>0 -5000</Gravity>");
        assert_eq!(world_gravity(&strong, Engine::Box2d32), None);
        assert_eq!(
            world_gravity(&scene("<Gravity>1000 0</Gravity>"), Engine::Box2d24).map(|g| g.x),
            Some(1000.0)
        );
    }
}
