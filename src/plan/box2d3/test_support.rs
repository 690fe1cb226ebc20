//! What the unit tests of the v3 plan share: a scene planned from its parts, and its
//! reports as (code, object, index, message).

use crate::plan::records::{PlanOptions, Rot, Transform};
use crate::plan::{Engine, Object, Plan, make};
use crate::scene::Vec2;

pub(super) const IDENTITY: Transform =
    Transform { p: Vec2 { x: 0.0, y: 0.0 }, q: Rot { c: 1.0, s: 0.0 } };

pub(super) fn options(engine: Engine, placement: Transform) -> PlanOptions {
    PlanOptions {
        engine: engine as u32,
        placement,
        gravity: Vec2 { x: 0.0, y: -10.0 },
        max_linear_speed: 1500.0,
        name_bytes: 0,
    }
}

/// The plan of a Version 2 scene of these parts (the containers' contents), unplaced.
pub(super) fn plan_of(
    engine: Engine,
    shapes: &str,
    fixtures: &str,
    bodies: &str,
    joints: &str,
) -> Plan {
    let text = format!(
        "<World Version=\"2\"><Gravity>0 -10</Gravity><Shapes>{shapes}</Shapes><Fixtures>{fixtures}\
         </Fixtures><Bodies>{bodies}</Bodies><Joints>{joints}</Joints></World>"
    );
    let scene = crate::load(text.as_bytes(), &Default::default()).unwrap();
    make(&scene, &options(engine, IDENTITY)).unwrap()
}

pub(super) fn messages(plan: &Plan) -> Vec<(u32, &str, u32, &str)> {
    plan.reports()
        .iter()
        .map(|r| {
            let objects =
                [Object::World, Object::Shape, Object::Fixture, Object::Body, Object::Joint];
            let object = objects
                .into_iter()
                .find(|o| o.name().as_ptr() == r.object.as_ptr())
                .and_then(|o| o.name().to_str().ok())
                .unwrap();
            (r.code, object, r.index, plan.text(r.message).unwrap())
        })
        .collect()
}

/// A ball of radius 0.5 as shape 0, fixture 0 of density 1.
pub(super) const BALL: (&str, &str) = (
    "<Shape Type=\"Circle\"><Radius>0.5</Radius><Position>0 0</Position></Shape>",
    "<Fixture><Shape>0</Shape><Density>1</Density></Fixture>",
);
