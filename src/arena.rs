//! What a load builds as it reads: the scene's records and pools, where each object was
//! written (for the checks that need the whole file), and the warnings found (and, in a
//! load that goes on past errors, the errors). It only builds; the reader fills it, and
//! the check stage finishes it.
#![forbid(unsafe_code)]

use crate::error::{Code, Finding, MAX_ERRORS, MAX_WARNINGS, Parsed, Position, Problem, Spot};
use crate::place::Spots;
use crate::scene::{SceneBuilder, Vec2};

/// A scene under construction, with what the later stages need to check it.
pub(crate) struct Arena {
    /// The file's Version; 0 for an unversioned legacy file.
    pub version: u32,
    pub scene: SceneBuilder,
    pub origins: Origins,
    pub findings: Findings,
}

/// The warnings a load found and, in a load that goes on past errors, the errors: apart
/// from the scene, so that a check can note what it finds while it reads the scene.
pub(crate) struct Findings {
    /// Every warning becomes the load's error.
    strict: bool,
    /// The load goes on past the errors it can: see [`Findings::recover`].
    recovering: bool,
    /// The errors gone on past, each placed, in the order found.
    errors: Vec<Finding>,
    /// The warnings kept, at most [`MAX_WARNINGS`], in the order found, each placed.
    warnings: Vec<Finding>,
    /// Warnings past [`MAX_WARNINGS`]: how many, and the first (only its place is read, so
    /// [`Findings::note_worded`] leaves its message empty).
    dropped: (u64, Option<Finding>),
}

/// Where the checks made after the whole file is read point.
#[derive(Debug, Default)]
pub(crate) struct Origins {
    /// The root's start tag.
    pub world: Spot,
    /// Per fixture: its `Shape` value.
    pub fixture_shapes: Spots,
    /// Per body: its tag.
    pub bodies: Spots,
    /// Per entry of the fixture ID pool: its `ID` value.
    pub fixture_ids: Spots,
    pub joints: JointOrigins,
    /// Version 3 (Farseer): per shape, its `Density` attribute (0 when absent).
    pub shape_densities: Vec<f32>,
    /// Version 3: every body's `Bindings`, in body order.
    pub pairs: Vec<Pair>,
    /// The joints whose axis the file gave as Farseer's world `Axis`, with that axis:
    /// turned into body A's frame once the bodies are read.
    pub world_axes: Vec<(u32, Vec2)>,
    /// The chains with no `Has` flag and no loop flag: in Farseer's files, ghosts are
    /// present unless (0, 0) and a loop repeats its first vertex.
    pub flagless_chains: Vec<u32>,
    /// What the file showed of its writer (see [`Signs`]).
    pub signs: Signs,
}

/// What a file shows of the writer that wrote it, for the dialect a scene remembers.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Signs {
    /// A `<Fixture>` or `<Body>` with an `Id` attribute (Farseer from July 2013 on).
    pub ids: bool,
    /// A `<CollisionIgnores>` (Farseer 3.5 and Velcro write one in every `FilterData`).
    pub collision_ignores: bool,
    /// A `<Tag>` read as user data (Aether.Physics2D).
    pub tags: bool,
    /// What only Farseer 3.3.1 writes: `LocalXAxis1`, `LocalXAxis`, `Breakpoint` (outside
    /// Farseer-only joints), a Line joint with a wheel's fields, a fixture's `FilterData`
    /// before its `Friction` (in Version 2; the editor's Version 1 files have it too).
    pub farseer_3_3: bool,
}

impl Signs {
    fn or(self, other: Signs) -> Signs {
        Signs {
            ids: self.ids || other.ids,
            collision_ignores: self.collision_ignores || other.collision_ignores,
            tags: self.tags || other.tags,
            farseer_3_3: self.farseer_3_3 || other.farseer_3_3,
        }
    }
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

/// The [`JointOrigin`]s, in [`Spots`]: four per joint.
#[derive(Default)]
pub(crate) struct JointOrigins(Spots);

impl JointOrigins {
    pub fn push(&mut self, origin: JointOrigin) {
        let JointOrigin { body_a, body_b, joint_a, joint_b } = origin;
        self.0.extend([body_a, body_b, joint_a, joint_b]);
    }

    pub fn iter(&self) -> impl Iterator<Item = JointOrigin> + '_ {
        let mut spots = self.0.iter();
        std::iter::from_fn(move || {
            Some(JointOrigin {
                body_a: spots.next()?,
                body_b: spots.next()?,
                joint_a: spots.next()?,
                joint_b: spots.next()?,
            })
        })
    }
}

impl std::fmt::Debug for JointOrigins {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl Arena {
    pub fn new(strict: bool, recovering: bool) -> Arena {
        Arena {
            version: 0,
            scene: SceneBuilder::default(),
            origins: Origins::default(),
            findings: Findings {
                strict,
                recovering,
                errors: Vec::new(),
                warnings: Vec::new(),
                dropped: (0, None),
            },
        }
    }

    /// Appends `other`, what was read right after what this arena holds, from the text at
    /// `start` on: its bodies are numbered after these, its positions counted from `start`,
    /// and its warnings were found after these, so the warnings kept and counted are those
    /// one arena reading both would have.
    pub fn append(&mut self, other: Arena, start: Position) {
        let before = Before {
            shapes: self.scene.shapes.len() as u32,
            bodies: self.scene.bodies.len() as u32,
            joints: self.scene.joints.len() as u32,
        };
        self.scene.append(other.scene);
        self.origins.append(other.origins, before, start);
        self.findings.append(other.findings, start);
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

impl Findings {
    /// Records `warning`; in strict mode it is an error instead (see [`Findings::recover`]).
    pub fn note(&mut self, warning: Finding) -> Parsed<()> {
        if self.strict {
            let message = format!("{} (strict mode)", warning.message);
            return self.recover(Box::new(Finding { message, ..warning }));
        }
        self.keep(warning);
        Ok(())
    }

    /// Records `warning` as [`Findings::note`] does, its message the words `words` give,
    /// asked for only if the warning is kept: a scene keeps [`MAX_WARNINGS`], and a file can
    /// give many more.
    pub fn note_worded(
        &mut self,
        mut warning: Finding,
        words: impl FnOnce() -> String,
    ) -> Parsed<()> {
        if self.strict || self.warnings.len() < MAX_WARNINGS {
            warning.message = words();
        }
        self.note(warning)
    }

    /// An error after which the reading can go on as if the object had not said what it
    /// got wrong (a value, a reference). A load that stops at its first error stops at it;
    /// one that goes on records it, up to [`MAX_ERRORS`], and goes on.
    pub fn recover(&mut self, error: Problem) -> Parsed<()> {
        if !self.recovering || self.errors.len() >= MAX_ERRORS {
            return Err(error);
        }
        self.errors.push(*error);
        Ok(())
    }

    /// Whether the load went on past an error: then nothing is checked that needs the
    /// scene whole, and no scene is made.
    pub fn has_errors(&self) -> bool {
        !self.errors.is_empty()
    }

    /// The errors gone on past, in the order found.
    pub fn take_errors(&mut self) -> Vec<Finding> {
        std::mem::take(&mut self.errors)
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

    /// Appends the warnings of `other`, found after these in the text from `start` on. It
    /// has no errors: a piece whose reading found one is never appended.
    fn append(&mut self, other: Findings, start: Position) {
        let after = |w: Finding| Finding { at: w.at.after(start), ..w };
        for warning in other.warnings {
            self.keep(after(warning));
        }
        let (count, first) = other.dropped;
        if self.dropped.1.is_none() {
            self.dropped.1 = first.map(after);
        }
        self.dropped.0 += count;
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
}

/// How many objects of a kind an arena held before another was appended to it.
#[derive(Clone, Copy)]
struct Before {
    shapes: u32,
    bodies: u32,
    joints: u32,
}

impl Origins {
    /// Appends those of what was read after this one's last object (not the root), whose
    /// objects are numbered after those `before` read here and whose positions are counted
    /// from `start`.
    fn append(&mut self, other: Origins, before: Before, start: Position) {
        let Origins {
            fixture_shapes,
            bodies,
            fixture_ids,
            joints,
            shape_densities,
            pairs,
            world_axes,
            flagless_chains,
            signs,
            ..
        } = other;
        let bodies_before = before.bodies;
        self.world_axes.extend(world_axes.into_iter().map(|(j, axis)| (j + before.joints, axis)));
        self.flagless_chains.extend(flagless_chains.into_iter().map(|s| s + before.shapes));
        self.signs = self.signs.or(signs);
        let after = |s: Spot| s.after(start);
        self.fixture_shapes.extend(fixture_shapes.iter().map(after));
        self.bodies.extend(bodies.iter().map(after));
        self.fixture_ids.extend(fixture_ids.iter().map(after));
        self.joints.0.extend(joints.0.iter().map(after));
        self.shape_densities.extend(shape_densities);
        self.pairs.extend(pairs.into_iter().map(|p| Pair {
            body: p.body + bodies_before,
            fixture: (p.fixture.0, after(p.fixture.1)),
            shape: (p.shape.0, after(p.shape.1)),
        }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Joint origins come back as they went in, four spots each, whatever the spots.
    #[test]
    fn joint_origins_come_back_as_they_went_in() {
        let at = |line, column, byte_offset| Spot::placed(Position { line, column, byte_offset });
        let spots: Vec<Spot> = (0..200)
            .map(|i: u32| match i % 7 {
                0 => Spot::offset(i as usize * 13),
                3 => at(u32::MAX - i, i, 1 << 40),
                _ => at(3 * i + 1, i % 90 + 1, u64::from(i) * 97),
            })
            .collect();
        let mut joints = JointOrigins::default();
        let origins: Vec<_> = spots
            .windows(4)
            .map(|w| JointOrigin { body_a: w[0], body_b: w[1], joint_a: w[2], joint_b: w[3] })
            .collect();
        for &origin in &origins {
            joints.push(origin);
        }
        assert_eq!(format!("{joints:?}"), format!("{origins:?}"));
    }
}
