//! What a load builds as it reads: the scene's records and pools, where each object was
//! written (for the checks that need the whole file), and the warnings found. It only
//! builds; the reader fills it, and resolve and validate finish it.
#![forbid(unsafe_code)]

use crate::error::{Code, Finding, MAX_WARNINGS, Parsed, Position, Spot};
use crate::scene::SceneBuilder;

/// A scene under construction, with what the later stages need to check it.
pub(crate) struct Arena {
    /// The file's Version; 0 for an unversioned legacy file.
    pub version: u32,
    pub scene: SceneBuilder,
    pub origins: Origins,
    /// Every warning becomes the load's error.
    strict: bool,
    /// The warnings kept, at most [`MAX_WARNINGS`], in the order found, each placed.
    warnings: Vec<Finding>,
    /// Warnings past [`MAX_WARNINGS`]: how many, and the first.
    dropped: (u64, Option<Finding>),
}

/// Where the checks made after the whole file is read point.
#[derive(Debug, Default)]
pub(crate) struct Origins {
    /// The root's start tag.
    pub world: Spot,
    /// Per fixture: its `Shape` value.
    pub fixture_shapes: Vec<Spot>,
    /// Per body: its tag.
    pub bodies: Vec<Spot>,
    /// Per entry of the fixture ID pool: its `ID` value.
    pub fixture_ids: Vec<Spot>,
    pub joints: Vec<JointOrigin>,
    /// Version 3 (Farseer): per shape, its `Density` attribute (0 when absent).
    pub shape_densities: Vec<f32>,
    /// Version 3: every body's `Bindings`, in body order.
    pub pairs: Vec<Pair>,
}

/// A Version 3 `<Pair FixtureId="f" ShapeId="s"/>`: one fixture of a body, made of the
/// f-th fixture template and the s-th shape (positions, with where each is written).
#[derive(Debug)]
pub(crate) struct Pair {
    pub body: u32,
    pub fixture: (u32, Spot),
    pub shape: (u32, Spot),
}

/// Where a joint's references are.
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointOrigin {
    pub body_a: Spot,
    pub body_b: Spot,
    pub joint_a: Spot,
    pub joint_b: Spot,
}

impl Arena {
    pub fn new(strict: bool) -> Arena {
        Arena {
            version: 0,
            scene: SceneBuilder::default(),
            origins: Origins::default(),
            strict,
            warnings: Vec::new(),
            dropped: (0, None),
        }
    }

    /// Records `warning`; in strict mode it is the load's error instead.
    pub fn note(&mut self, warning: Finding) -> Parsed<()> {
        if self.strict {
            let message = format!("{} (strict mode)", warning.message);
            return Err(Box::new(Finding { message, ..warning }));
        }
        self.keep(warning);
        Ok(())
    }

    /// Keeps `warning` unless [`MAX_WARNINGS`] are kept already; then counts it.
    fn keep(&mut self, warning: Finding) {
        if self.warnings.len() < MAX_WARNINGS {
            self.warnings.push(warning);
        } else {
            let (count, first) = &mut self.dropped;
            first.get_or_insert(warning);
            *count += 1;
        }
    }

    /// The warnings in the order of the file, the last a `warnings-truncated` one when some
    /// were not kept.
    pub fn take_warnings(&mut self) -> Vec<Finding> {
        let mut warnings = std::mem::take(&mut self.warnings);
        warnings.sort_by_key(Finding::order);
        if let (dropped @ 1.., Some(first)) = std::mem::take(&mut self.dropped) {
            let message = format!(
                "{dropped} more warnings from here on were not kept (a scene keeps {MAX_WARNINGS})"
            );
            warnings.push(Finding { code: Code::WarningsTruncated, message, ..first });
        }
        warnings
    }

    /// Appends `other`, what was read right after what this arena holds, from the text at
    /// `start` on: its bodies are numbered after these, its positions counted from `start`,
    /// and its warnings were found after these, so the warnings kept and counted are those
    /// one arena reading both would have.
    pub fn append(&mut self, other: Arena, start: Position) {
        let bodies_before = self.scene.bodies.len() as u32;
        self.scene.append(other.scene);
        self.origins.append(other.origins, bodies_before, start);
        let after = |w: Finding| Finding { position: w.position.map(|p| p.after(start)), ..w };
        for warning in other.warnings {
            self.keep(after(warning));
        }
        let (count, first) = other.dropped;
        if self.dropped.1.is_none() {
            self.dropped.1 = first.map(after);
        }
        self.dropped.0 += count;
    }

    /// Whether the file uses Farseer's Version 3 layout (docs/format.md, "Farseer spellings
    /// and the Version 3 layout").
    pub fn farseer_layout(&self) -> bool {
        self.version >= 3
    }

    /// Version 3 (Aether.Physics2D's spelling): `<Tag>` is `<UserData>`.
    pub fn tag_is_user_data(&self) -> bool {
        self.farseer_layout()
    }

    /// Whether a `<Fixture>` or `<Body>` may carry Farseer's informational `Id` attribute
    /// (Version 2 from July 2013, and Version 3), which is accepted and kept nowhere. A
    /// Version 3 Pair names its fixture by position, never by this `Id`.
    pub fn id_is_informational(&self) -> bool {
        self.version >= 2
    }
}

impl Origins {
    /// Appends those of what was read after this one's last object (not the root), whose
    /// bodies are
    /// numbered after the `bodies_before` read here and whose positions are counted from
    /// `start`.
    fn append(&mut self, other: Origins, bodies_before: u32, start: Position) {
        let Origins { fixture_shapes, bodies, fixture_ids, joints, shape_densities, pairs, .. } =
            other;
        let after = |s: Spot| s.after(start);
        self.fixture_shapes.extend(fixture_shapes.into_iter().map(after));
        self.bodies.extend(bodies.into_iter().map(after));
        self.fixture_ids.extend(fixture_ids.into_iter().map(after));
        self.joints.extend(joints.into_iter().map(|j| JointOrigin {
            body_a: after(j.body_a),
            body_b: after(j.body_b),
            joint_a: after(j.joint_a),
            joint_b: after(j.joint_b),
        }));
        self.shape_densities.extend(shape_densities);
        self.pairs.extend(pairs.into_iter().map(|p| Pair {
            body: p.body + bodies_before,
            fixture: (p.fixture.0, after(p.fixture.1)),
            shape: (p.shape.0, after(p.shape.1)),
        }));
    }
}
