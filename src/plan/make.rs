//! Which engine module makes a plan: the one of the version the options name.

use super::box2d2::{self, Version};
use super::box2d3::{self, V3};
use super::container::Plan;
use super::range::Engine;
use super::records::PlanOptions;
use crate::error::{Code, Error, Position};
use crate::scene::Scene;

/// The plan of `scene` for the engine version and placement `options` name. An engine
/// number that names no version is an error. A placement the engine cannot
/// take is no error: the plan then holds only its report (see [`Plan::placed`]).
pub fn make(scene: &Scene, options: &PlanOptions) -> Result<Plan, Error> {
    let engine = Engine::try_from(options.engine)
        .map_err(|n| invalid(format!("engine {n} is no b2s_engine: a plan is made for 1 to 4")))?;
    if let Some(version) = Version::of(engine) {
        return Ok(box2d2::plan(scene, options, version));
    }
    let v3 = V3::of(engine).expect("every engine is 2.x or v3");
    Ok(box2d3::plan(scene, options, v3))
}

fn invalid(message: String) -> Error {
    Error { code: Code::InvalidArgument, position: Position::default(), message }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plan::Transform;
    use crate::scene::Vec2;

    fn options(engine: u32) -> PlanOptions {
        PlanOptions {
            engine,
            placement: Transform { p: Vec2::default(), q: crate::plan::Rot { c: 1.0, s: 0.0 } },
            gravity: Vec2 { x: 0.0, y: -10.0 },
            max_linear_speed: f32::MAX,
            name_bytes: 0,
        }
    }

    #[test]
    fn an_engine_number_that_names_no_version_is_an_invalid_argument() {
        let scene = crate::load(b"<World Version=\"2\"/>", &Default::default()).unwrap();
        for n in [0, 5, u32::MAX] {
            let e = make(&scene, &options(n)).unwrap_err();
            assert_eq!(e.code, Code::InvalidArgument);
            assert!(e.message.starts_with(&format!("engine {n} is no b2s_engine")), "{e}");
        }
    }

    #[test]
    fn every_engine_version_is_planned() {
        let scene = crate::load(b"<World Version=\"2\"/>", &Default::default()).unwrap();
        for engine in Engine::ALL {
            assert!(make(&scene, &options(engine as u32)).unwrap().placed(), "{engine:?}");
        }
    }
}
