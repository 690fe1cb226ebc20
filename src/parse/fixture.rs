//! `<Fixture>`: a shape ID, material and filtering.

use super::{Element, Reader, Seen, Tag, attributes, elements};
use crate::error::Parsed;
use crate::scene::{Filter, Fixture, Object};
use crate::text;

elements! {
    enum FixtureChild {
        Shape,
        Name,
        Density,
        Friction,
        Restitution,
        IsSensor,
        FilterData,
        UserData,
        Tag,
    }
}

elements! {
    enum FilterChild { CategoryBits, MaskBits, GroupIndex, CollisionIgnores }
}

impl<'a> Reader<'a> {
    pub(super) fn fixture(&mut self, tag: &Tag) -> Parsed<()> {
        self.begin_object(Object::Fixture(self.arena.scene.fixtures.len() as u32));
        let known: &[&str] = if self.arena.id_is_informational() { &["Id"] } else { &[] };
        let attrs = attributes!(self, tag, known);
        self.arena.origins.signs.ids |= !known.is_empty() && attrs.iter().any(|a| a.is("id"));
        let mut fixture = Fixture::default();
        let mut name_str = None;
        let mut shape_at = None;
        let mut seen = Seen::default();
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            if repeated {
                self.duplicate(tag, &child)?;
            }
            use FixtureChild::*;
            // Farseer 3.3.1 (and the editor) write the filter before the friction;
            // box2scene's own writer after: a Version 2 file without `Id`s in that order is
            // Farseer 3.3.1's, even with no joint to show it.
            self.arena.origins.signs.farseer_3_3 |= name == Friction && seen.contains(FilterData);
            match name {
                // A Version 3 body's Pairs give each of its fixtures a shape, and the shape's
                // Density attribute its density (spec section 8.2).
                Shape | Density if self.arena.farseer_layout() => {
                    let words = || {
                        format!(
                            "<{}> in a Version 3 <Fixture> ignored: a body's <Pair> gives the \
                             fixture its shape, and the shape's Density attribute its density",
                            child.name()
                        )
                    };
                    self.discard(&child, words)?;
                }
                Shape => {
                    let (shape, at) = self.id(&child)?;
                    (fixture.shape, shape_at) = (shape, Some(self.spot(at)));
                }
                Name => name_str = Some(self.string(&child)?),
                Density => fixture.density = self.non_negative(&child)?,
                Friction => fixture.friction = self.non_negative(&child)?,
                Restitution => fixture.restitution = self.non_negative(&child)?,
                IsSensor => fixture.is_sensor = self.boolean(&child)?,
                FilterData => {
                    let filter = &mut fixture.filter;
                    self.within(FilterData.name(), |p| p.filter(&child, filter))?
                }
                UserData => fixture.user_data = self.user_data(&child)?,
                FixtureChild::Tag => match self.arena.tag_is_user_data() {
                    true => fixture.user_data = self.tagged_user_data(&child)?,
                    false => self.unknown(tag, &child, &[])?,
                },
            }
        }
        // In Farseer's layout a fixture is a template: bodies pair it with shapes.
        if !seen.contains(FixtureChild::Shape) && !self.arena.farseer_layout() {
            return Err(self.tok.missing(tag, "<Shape>: a fixture with no shape is malformed"));
        }
        self.end_object();
        // A Version 3 template has none: its bodies' Pairs give it one.
        let origin = shape_at.unwrap_or_else(|| self.spot(tag.at));
        self.arena.origins.fixture_shapes.push(origin);
        self.arena.scene.push_fixture(fixture, name_str);
        Ok(())
    }

    fn filter(&mut self, tag: &Tag, filter: &mut Filter) -> Parsed<()> {
        let mut seen = Seen::default();
        let mut child = Tag::slot();
        while self.tok.child(tag, &mut child)? {
            let Some((name, repeated)) = self.known(tag, &child, &mut seen)? else {
                continue;
            };
            if repeated {
                self.duplicate(tag, &child)?;
            }
            match name {
                FilterChild::CategoryBits => filter.category_bits = self.bits(&child)?,
                FilterChild::MaskBits => filter.mask_bits = self.bits(&child)?,
                FilterChild::GroupIndex => filter.group_index = self.value(&child, text::int16)?.0,
                // Farseer's per-body collision exceptions: Box2D has no such thing.
                FilterChild::CollisionIgnores => {
                    self.arena.origins.signs.collision_ignores = true;
                    self.tok.skip(&child)?
                }
            }
        }
        Ok(())
    }

    /// Collision bits, all 32 kept.
    fn bits(&mut self, tag: &Tag) -> Parsed<u32> {
        Ok(self.value(tag, text::bits)?.0)
    }
}
