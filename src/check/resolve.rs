//! Once the whole file is read (containers come in any order): Farseer's Version 3 layout
//! is normalised into the ordinary model, then every ID is checked against its container
//! and gear joints against the joints they couple; the file's dialect is told from what it
//! showed of its writer, Farseer's chains are read as that writer meant them, and Farseer's
//! world axes are turned into body A's frame.
#![forbid(unsafe_code)]

use crate::arena::Arena;
use crate::containers::Container;
use crate::error::{Code, Finding, MAX_ERRORS, Parsed, Problem, Spot};
use crate::rules;
use crate::scene::{Dialect, JointKind, KeptAt, NONE, Object, Range, Vec2};

/// Normalises the dialects and checks every reference. A load that goes on past errors
/// records every reference that names nothing, and stops there if it found any error.
pub(crate) fn resolve(p: &mut Arena) -> Parsed<()> {
    if p.farseer_layout() {
        normalise_farseer_layout(p)?;
    }
    for error in check_references(p) {
        p.findings.recover(error)?;
    }
    if p.findings.has_errors() {
        return Ok(());
    }
    let dialect = dialect(p);
    p.scene.dialect = Some(dialect);
    if matches!(dialect, Dialect::Farseer2013 | Dialect::Farseer35 | Dialect::Aether) {
        farseer_chains(p);
    }
    world_axes(p);
    Ok(())
}

/// The dialect a file is in, from the signs its writer left (spec section 11): Version 3
/// with `<Tag>` is Aether's, with `CollisionIgnores` or `<UserData>` Farseer 3.5's or
/// Velcro's (the two differ only there); Version 2 with `Id` attributes is Farseer's of July
/// 2013, and with Farseer 3.3.1's own spellings (`LocalXAxis1`, `LocalXAxis`, `Breakpoint`,
/// a Line joint with a wheel's fields) or its order (a fixture's `FilterData` before its
/// `Friction`, which box2scene's writer puts after) Farseer 3.3.1's; the rest is the
/// editor's form.
fn dialect(p: &Arena) -> Dialect {
    let signs = p.origins.signs;
    match p.version {
        3.. if signs.tags => Dialect::Aether,
        3.. if signs.collision_ignores || !p.scene.user_data.is_empty() => Dialect::Farseer35,
        3.. => Dialect::Aether,
        2 if signs.ids => Dialect::Farseer2013,
        2 if signs.farseer_3_3 => Dialect::Farseer33,
        _ => Dialect::Box2scene,
    }
}

/// Farseer (2013 on), Velcro and Aether write a chain's ghosts without `Has` flags, `0 0`
/// for none, and a loop as its vertices with the first repeated at the end (spec section
/// 8.2): the chains without flags are read so.
fn farseer_chains(p: &mut Arena) {
    let scene = &mut p.scene;
    for &index in &p.origins.flagless_chains {
        let shape = &mut scene.shapes[index as usize];
        let vertices = &scene.vertices[shape.vertices.indices()];
        let closed = vertices.len() > 3 && vertices.first() == vertices.last();
        let distinct = &vertices[..vertices.len() - usize::from(closed)];
        if closed && rules::chain(distinct, true, 0).is_ok() {
            shape.is_loop = true;
            shape.vertices.count -= 1;
            (shape.prev_vertex, shape.next_vertex) = (Vec2::ZERO, Vec2::ZERO);
            continue;
        }
        shape.has_prev_vertex = shape.prev_vertex != Vec2::ZERO;
        shape.has_next_vertex = shape.next_vertex != Vec2::ZERO;
    }
}

/// Farseer's `Axis` is the world axis the program gave the joint: body A's local axis is
/// it turned by minus body A's angle, as Farseer's own reader computes it (in f32, with the
/// sine and cosine of the angle rounded to f32).
fn world_axes(p: &mut Arena) {
    let scene = &mut p.scene;
    for &(joint, world) in &p.origins.world_axes {
        let joint = &mut scene.joints[joint as usize];
        let angle = scene.bodies[joint.body_a as usize].angle;
        joint.local_axis_a = rules::local_axis(world, angle);
    }
    scene.world_axes = std::mem::take(&mut p.origins.world_axes);
}

/// Version 3: each body's `<Pair FixtureId="f" ShapeId="s"/>` becomes a fixture: the f-th
/// fixture template on the s-th shape, with the density of s (docs/format.md). The
/// templates' `Id` attributes are never consulted: Farseer wrote a process-wide counter
/// there, and bound Pairs by position. When every template is bound, each always to one
/// shape (as the engines write them), each fixture keeps its template's place and is shared
/// by the bodies that bind it; else the fixtures come in the order of the Pairs.
fn normalise_farseer_layout(p: &mut Arena) -> Parsed<()> {
    let templates = std::mem::take(&mut p.scene.fixtures);
    let mut template_names = vec![None; templates.len()];
    for (index, name) in std::mem::take(&mut p.scene.names.fixtures) {
        template_names[index as usize] = Some(name);
    }
    // The templates' own (absent) shapes are replaced by the pairs'.
    p.origins.fixture_shapes.clear();
    let mut shape_of: Vec<Option<u32>> = vec![None; templates.len()];
    let mut one_shape_each = true;
    for pair in &p.origins.pairs {
        if let Some(bound) = shape_of.get_mut(pair.fixture.0 as usize) {
            one_shape_each &= *bound.get_or_insert(pair.shape.0) == pair.shape.0;
        }
    }
    let in_place = one_shape_each && shape_of.iter().all(Option::is_some);
    let mut made_yet = vec![false; templates.len()];
    let mut made = Vec::with_capacity(p.origins.pairs.len());
    let mut shape_spots = Vec::with_capacity(p.origins.pairs.len());
    for (k, pair) in p.origins.pairs.iter().enumerate() {
        let (template, template_at) = pair.fixture;
        let template_index = template as usize;
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
        let index = if in_place { pair.fixture.0 } else { k as u32 };
        if !in_place || !std::mem::replace(&mut made_yet[template_index], true) {
            made.push((index, fixture, template_names[template_index]));
            shape_spots.push((index, shape_at));
        }
        p.scene.fixture_ids.push(index);
        p.origins.fixture_ids.push(template_at);
        let fixtures = &mut p.scene.bodies[pair.body as usize].fixtures;
        if fixtures.count == 0 {
            *fixtures = Range { first: k as u32, count: 0 };
        }
        fixtures.count += 1;
    }
    let first_made: Vec<Option<u32>> = {
        let mut first = vec![None; templates.len()];
        for (k, pair) in p.origins.pairs.iter().enumerate().rev() {
            let template = pair.fixture.0;
            first[template as usize] = Some(if in_place { template } else { k as u32 });
        }
        first
    };
    made.sort_by_key(|&(index, ..)| index);
    shape_spots.sort_by_key(|&(index, _)| index);
    for (_, fixture, name) in made {
        p.scene.push_fixture(fixture, name);
    }
    for (_, spot) in shape_spots {
        p.origins.fixture_shapes.push(spot);
    }
    move_kept_of_templates(p, &first_made);
    Ok(())
}

/// What the file held beyond a template's records goes with the first fixture made from
/// it, so the writer still has it. That of a template no Pair names goes to the world:
/// its unknown attributes to `<World>`, what it held inside to the world's end, as a
/// container holds nothing but its items; the comments around it stay at the end of
/// `<Fixtures>`.
fn move_kept_of_templates(p: &mut Arena, first_made: &[Option<u32>]) {
    for kept in &mut p.scene.kept {
        let Object::Fixture(template) = kept.object else { continue };
        (kept.object, kept.place) = match (first_made[template as usize], kept.place) {
            (Some(made), place) => (Object::Fixture(made), place),
            (None, KeptAt::Attribute) => (Object::World, KeptAt::Attribute),
            (None, KeptAt::Inside { .. }) => {
                (Object::World, KeptAt::Inside { within: "", before: "" })
            }
            (None, _) => {
                let within = Container::Fixtures.name();
                (Object::World, KeptAt::Inside { within, before: "" })
            }
        };
    }
}

/// "the file has 1 shape", "the file has 3 shapes".
fn has(n: usize, one: &str, many: &str) -> String {
    format!("the file has {n} {}", if n == 1 { one } else { many })
}

/// Checks every ID against its container, and the gear joints' targets: the first errors,
/// in the order of the file (see [`FirstErrors`]).
fn check_references(p: &Arena) -> Vec<Problem> {
    let s = &p.scene;
    let mut errors = FirstErrors::default();
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
    // Each unknown fixture ID by its index in the pool, with its body: their spots are
    // found together.
    let (mut pool_indices, mut bodies) = (Vec::new(), Vec::new());
    for (i, b) in s.bodies.iter().enumerate() {
        for k in b.fixtures.indices() {
            if s.fixture_ids[k] as usize >= s.fixtures.len() {
                pool_indices.push(k);
                bodies.push(i);
            }
        }
    }
    let spots = p.origins.fixture_ids.at(&pool_indices);
    for ((at, k), i) in spots.into_iter().zip(pool_indices).zip(bodies) {
        let why = format!(
            "body {i} names fixture {}, but {}",
            s.fixture_ids[k],
            has(s.fixtures.len(), "fixture", "fixtures")
        );
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
    errors.into_sorted()
}

/// The first errors in the order of the file, of however many are found: as many as a load
/// that goes on past errors records, and the one after them, which ends it (see
/// [`crate::arena::Findings::recover`]). A file of a million broken references holds no
/// million errors: whenever twice that many are held, the later half is let go.
#[derive(Default)]
struct FirstErrors(Vec<Problem>);

impl FirstErrors {
    const KEPT: usize = MAX_ERRORS + 1;

    fn push(&mut self, error: Problem) {
        self.0.push(error);
        if self.0.len() == 2 * FirstErrors::KEPT {
            self.settle();
        }
    }

    /// Sorted by place in the file (stable: errors at one place stay in the order found),
    /// the first kept.
    fn settle(&mut self) {
        self.0.sort_by_key(|e| e.order());
        self.0.truncate(FirstErrors::KEPT);
    }

    fn into_sorted(mut self) -> Vec<Problem> {
        self.settle();
        self.0
    }
}

/// A problem at `spot`.
#[cold]
fn placed(code: Code, spot: Spot, why: String) -> Problem {
    Box::new(Finding::at(code, spot, why))
}
