//! Once the whole file is read (containers come in any order): Farseer's Version 3 layout
//! is normalised into the ordinary model, then every ID is checked against its container
//! and gear joints against the joints they couple.
#![forbid(unsafe_code)]

use crate::arena::Arena;
use crate::containers::Container;
use crate::error::{Code, Parsed, Problem, Spot};
use crate::scene::{JointKind, NONE, Object, Place, Range};

pub(crate) fn resolve(p: &mut Arena) -> Parsed<()> {
    if p.farseer_layout() {
        normalise_farseer_layout(p)?;
    }
    check_references(p)
}

/// Version 3: each body's `<Pair FixtureId="f" ShapeId="s"/>` becomes a fixture: the f-th
/// fixture template on the s-th shape, with the density of s (docs/format.md). The
/// templates' `Id` attributes are never consulted: Farseer wrote a process-wide counter
/// there, and bound Pairs by position.
fn normalise_farseer_layout(p: &mut Arena) -> Parsed<()> {
    let templates = std::mem::take(&mut p.scene.fixtures);
    // The templates' own (absent) shapes are replaced by the pairs'.
    p.origins.fixture_shapes.clear();
    for (k, pair) in p.origins.pairs.iter().enumerate() {
        let (template, template_at) = pair.fixture;
        let Some(&template) = templates.get(template as usize) else {
            let why = format!(
                "body {} binds fixture {template} (a position in <Fixtures>, counted from 0), but {}",
                pair.body,
                has(templates.len(), "fixture", "fixtures")
            );
            return Err(placed(Code::IdOutOfRange, template_at, why));
        };
        let (shape, shape_at) = pair.shape;
        let mut fixture = template;
        fixture.shape = shape;
        fixture.density = p.origins.shape_densities.get(shape as usize).copied().unwrap_or(0.0);
        p.scene.fixtures.push(fixture);
        p.scene.fixture_ids.push(k as u32);
        p.origins.fixture_shapes.push(shape_at);
        p.origins.fixture_ids.push(template_at);
        let fixtures = &mut p.scene.bodies[pair.body as usize].fixtures;
        if fixtures.count == 0 {
            *fixtures = Range { first: k as u32, count: 0 };
        }
        fixtures.count += 1;
    }
    move_kept_of_templates(p, templates.len());
    Ok(())
}

/// What the file held beyond a template's records goes with the first fixture made from
/// it, so the writer still has it. That of a template no Pair names goes to the world:
/// its unknown attributes to `<World>`, what it held inside to the world's end, as a
/// container holds nothing but its items; the comments around it stay at the end of
/// `<Fixtures>`.
fn move_kept_of_templates(p: &mut Arena, templates: usize) {
    let mut first_made = vec![None; templates];
    for (k, pair) in p.origins.pairs.iter().enumerate().rev() {
        first_made[pair.fixture.0 as usize] = Some(k as u32);
    }
    for kept in &mut p.scene.kept {
        let Object::Fixture(template) = kept.object else { continue };
        (kept.object, kept.place) = match (first_made[template as usize], kept.place) {
            (Some(made), place) => (Object::Fixture(made), place),
            (None, Place::Attribute) => (Object::World, Place::Attribute),
            (None, Place::Inside { .. }) => {
                (Object::World, Place::Inside { within: "", before: "" })
            }
            (None, _) => {
                let within = Container::Fixtures.name();
                (Object::World, Place::Inside { within, before: "" })
            }
        };
    }
}

/// "the file has 1 shape", "the file has 3 shapes".
fn has(n: usize, one: &str, many: &str) -> String {
    format!("the file has {n} {}", if n == 1 { one } else { many })
}

/// Checks every ID against its container, and the gear joints' targets; reports the error
/// earliest in the file.
fn check_references(p: &Arena) -> Parsed<()> {
    let s = &p.scene;
    let mut errors: Vec<Problem> = Vec::new();
    for (i, (f, at)) in s.fixtures.iter().zip(p.origins.fixture_shapes.iter()).enumerate() {
        if f.shape as usize >= s.shapes.len() {
            let why = format!(
                "fixture {i} names shape {}, but {}",
                f.shape,
                has(s.shapes.len(), "shape", "shapes")
            );
            errors.push(placed(Code::IdOutOfRange, at, why));
        }
    }
    // Each unknown fixture ID by its index in the pool: their spots are found together.
    let mut unknown_fixtures = Vec::new();
    for (i, b) in s.bodies.iter().enumerate() {
        for k in b.fixtures.indices() {
            let id = s.fixture_ids[k];
            if id as usize >= s.fixtures.len() {
                let why = format!(
                    "body {i} names fixture {id}, but {}",
                    has(s.fixtures.len(), "fixture", "fixtures")
                );
                unknown_fixtures.push((k, why));
            }
        }
    }
    let (pool_indices, whys): (Vec<usize>, Vec<String>) = unknown_fixtures.into_iter().unzip();
    for (at, why) in p.origins.fixture_ids.at(&pool_indices).into_iter().zip(whys) {
        errors.push(placed(Code::IdOutOfRange, at, why));
    }
    for (i, (j, at)) in s.joints.iter().zip(p.origins.joints.iter()).enumerate() {
        for (body, side, at) in [(j.body_a, "BodyA", at.body_a), (j.body_b, "BodyB", at.body_b)] {
            if body as usize >= s.bodies.len() {
                let why = format!(
                    "joint {i} names body {body} as {side}, but {}",
                    has(s.bodies.len(), "body", "bodies")
                );
                errors.push(placed(Code::IdOutOfRange, at, why));
            }
        }
        if j.kind() != Some(JointKind::Gear) {
            continue;
        }
        for (target, side, at) in
            [(j.joint_a, "JointA", at.joint_a), (j.joint_b, "JointB", at.joint_b)]
        {
            let why = match s.joints.get(target as usize).and_then(|t| t.kind()) {
                _ if target as usize == i => "itself".to_string(),
                None if target != NONE => {
                    format!("joint {target}, but {}", has(s.joints.len(), "joint", "joints"))
                }
                Some(JointKind::Revolute | JointKind::Prismatic) | None => continue,
                Some(other) => format!("joint {target}, a {other:?} joint"),
            };
            errors.push(placed(Code::BadGearJoint, at, format!(
                "gear joint {i} names {why} as {side}; a gear couples two revolute or prismatic joints"
            )));
        }
    }
    match errors.into_iter().min_by_key(|e| e.order()) {
        Some(first) => Err(first),
        None => Ok(()),
    }
}

/// A problem at `spot`.
#[cold]
fn placed(code: Code, spot: Spot, why: String) -> Problem {
    Box::new(spot.finding(code, why))
}
