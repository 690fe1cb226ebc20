//! What a load builds as it reads: the scene's records and pools, where each object was
//! written (for the checks that need the whole file), and the warnings found. It only
//! builds; the reader fills it, and resolve and validate finish it.
#![forbid(unsafe_code)]

use crate::error::{Code, Finding, MAX_WARNINGS, Parsed};
use crate::scene::SceneBuilder;

/// A scene under construction, with what the later stages need to check it.
pub(crate) struct Arena {
    /// The file's Version; 0 for an unversioned legacy file.
    pub version: u32,
    pub scene: SceneBuilder,
    pub origins: Origins,
    /// Every warning becomes the load's error.
    strict: bool,
    /// The warnings kept, at most [`MAX_WARNINGS`], in the order found.
    warnings: Vec<Finding>,
    /// Warnings past [`MAX_WARNINGS`]: how many, and where the first was.
    dropped: (u64, usize),
}

/// The offsets the cross-reference checks need after the whole file is read.
#[derive(Debug, Default)]
pub(crate) struct Origins {
    /// Per fixture: its `Shape` value.
    pub fixture_shapes: Vec<usize>,
    /// Per body: its tag.
    pub bodies: Vec<usize>,
    /// Per entry of the fixture ID pool: its `ID` value.
    pub fixture_ids: Vec<usize>,
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
    pub fixture: (u32, usize),
    pub shape: (u32, usize),
}

/// Where a joint's references are.
#[derive(Clone, Copy, Debug)]
pub(crate) struct JointOrigin {
    pub body_a: usize,
    pub body_b: usize,
    pub joint_a: usize,
    pub joint_b: usize,
}

impl Arena {
    pub fn new(strict: bool) -> Arena {
        Arena {
            version: 0,
            scene: SceneBuilder::default(),
            origins: Origins::default(),
            strict,
            warnings: Vec::new(),
            dropped: (0, 0),
        }
    }

    /// Records a warning; in strict mode it is the load's error instead.
    pub fn warn(&mut self, code: Code, at: usize, message: impl Into<String>) -> Parsed<()> {
        self.note(Finding::new(code, at, message))
    }

    /// Records `warning` (see [`Arena::warn`]).
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
            if *count == 0 {
                *first = warning.at;
            }
            *count += 1;
        }
    }

    /// Whether a warning was recorded.
    pub fn has_warnings(&self) -> bool {
        !self.warnings.is_empty()
    }

    /// The warnings in the order of the file, the last a `warnings-truncated` one when some
    /// were not kept.
    pub fn take_warnings(&mut self) -> Vec<Finding> {
        let mut warnings = std::mem::take(&mut self.warnings);
        warnings.sort_by_key(|w| w.at);
        let (dropped, first) = self.dropped;
        if dropped > 0 {
            let message = format!(
                "{dropped} more warnings from here on were not kept (a scene keeps {MAX_WARNINGS})"
            );
            warnings.push(Finding::new(Code::WarningsTruncated, first, message));
        }
        warnings
    }

    /// Appends `other`, what was read right after what this arena holds: its bodies are
    /// numbered after these, and its warnings were found after these, so the warnings
    /// kept and counted are those one arena reading both would have.
    pub fn append(&mut self, other: Arena) {
        let bodies_before = self.scene.bodies.len() as u32;
        self.scene.append(other.scene);
        self.origins.append(other.origins, bodies_before);
        for warning in other.warnings {
            self.keep(warning);
        }
        let (count, first) = other.dropped;
        if count > 0 && self.dropped.0 == 0 {
            self.dropped.1 = first;
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

    /// Warns that `what` needs Version 2 when the file says less.
    pub fn newer_construct(&mut self, at: usize, what: &str) -> Parsed<()> {
        if self.version >= 2 {
            return Ok(());
        }
        let said = match self.version {
            0 => "has no Version (legacy)".to_string(),
            v => format!("says Version {v}"),
        };
        self.warn(
            Code::ConstructNewerThanVersion,
            at,
            format!("{what} is a Version 2 construct, but the file {said}"),
        )
    }
}

impl Origins {
    /// Appends those of what was read after this one's last object, whose bodies are
    /// numbered after the `bodies_before` read here.
    fn append(&mut self, other: Origins, bodies_before: u32) {
        let Origins { fixture_shapes, bodies, fixture_ids, joints, shape_densities, pairs } = other;
        self.fixture_shapes.extend(fixture_shapes);
        self.bodies.extend(bodies);
        self.fixture_ids.extend(fixture_ids);
        self.joints.extend(joints);
        self.shape_densities.extend(shape_densities);
        self.pairs.extend(pairs.into_iter().map(|p| Pair { body: p.body + bodies_before, ..p }));
    }
}
