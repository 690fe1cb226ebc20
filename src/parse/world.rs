//! The root: `<World Version="N">`, its gravity and its four containers.

use super::{Element, Reader, Seen, Tag, attributes, elements};
use crate::arena::Arena;
use crate::containers::Container;
use crate::error::{Code, Finding, Parsed, problem};
use crate::scene::{KeptAt, Object};

elements! {
    pub(super) enum WorldChild { Gravity, Shapes, Fixtures, Bodies, Joints }
}

impl WorldChild {
    /// The container this child is, by its name (none for Gravity, which is a value).
    fn container(self) -> Option<Container> {
        Container::ALL.into_iter().find(|c| c.name() == self.name())
    }

    /// The child that is `container` (every container is one: see the test below).
    pub(super) fn of(container: Container) -> WorldChild {
        let is = |child: &&WorldChild| child.container() == Some(container);
        WorldChild::ALL.iter().find(is).copied().unwrap_or(WorldChild::Gravity)
    }
}

impl<'a> Reader<'a> {
    /// The document from its start to `</World>`: prolog and world. `seen` gets the world's
    /// elements read; [`end_world`] and [`Reader::epilog`] end the reading.
    pub(super) fn document(&mut self, seen: &mut Seen) -> Parsed<()> {
        let root = self.root()?;
        self.place_comments(Object::World, KeptAt::Before);
        // Placed now: the warnings about the world come once the file is read.
        self.arena.origins.world = self.spot(root.at);
        self.read_version(&root)?;
        self.world_children(&root, seen)
    }

    /// The document from the item at the tokenizer's offset on to `</World>`, in
    /// `container` (open, with its start tag `tag`) in `root` (as where another reading
    /// stopped, or where a piece of the text begins). `seen` has the world's elements read
    /// before and gets those read now.
    pub(super) fn document_from_item(
        &mut self,
        (root, tag): (&Tag, &Tag),
        container: Container,
        seen: &mut Seen,
    ) -> Parsed<()> {
        self.container(tag, container)?;
        self.world_children(root, seen)
    }

    /// The prolog and the root's start tag, which must be `<World>`.
    pub(super) fn root(&mut self) -> Parsed<Tag> {
        let root = loop {
            match self.tok.next_node()? {
                super::Node::Open(tag) => break tag,
                super::Node::Text(t) if !self.tok.is_blank(&t) => {
                    return Err(problem(
                        Code::MalformedXml,
                        t.at,
                        "malformed XML: text before the root element",
                    ));
                }
                super::Node::Text(..) => {}
                super::Node::Close(at) => {
                    return Err(problem(
                        Code::MalformedXml,
                        at,
                        "malformed XML: an end tag before any start tag",
                    ));
                }
                super::Node::Eof => {
                    return Err(problem(
                        Code::MalformedXml,
                        0,
                        "malformed XML: the file has no root element; expected <World>",
                    ));
                }
            }
        };
        if !root.is("world") {
            return Err(problem(
                Code::NotAScene,
                root.at,
                format!(
                    "the root element is <{}>, not <World>: this is not a Box2Scene file",
                    root.name()
                ),
            ));
        }
        Ok(root)
    }

    /// What follows `</World>`: blank text, comments and processing instructions only (once
    /// read, nothing).
    pub(super) fn epilog(&mut self) -> Parsed<()> {
        // `</World>` lies between what was kept in the world and what is kept after it.
        self.tok.kept.release();
        loop {
            match self.tok.next_node()? {
                super::Node::Eof => {
                    self.place_comments(Object::World, KeptAt::After);
                    return Ok(());
                }
                super::Node::Text(t) if self.tok.is_blank(&t) => {}
                super::Node::Open(tag) => {
                    return Err(problem(
                        Code::MalformedXml,
                        tag.at,
                        format!(
                            "malformed XML: a second root element <{}> after </World>",
                            tag.name()
                        ),
                    ));
                }
                super::Node::Text(super::Text { at, .. }) | super::Node::Close(at) => {
                    return Err(problem(
                        Code::MalformedXml,
                        at,
                        "malformed XML: content after </World>",
                    ));
                }
            }
        }
    }

    /// The root's children up to `</World>`.
    pub(super) fn world_children(&mut self, root: &Tag, seen: &mut Seen) -> Parsed<()> {
        let mut child = Tag::slot();
        while self.tok.child(root, &mut child)? {
            let Some((name, repeated)) = self.known::<WorldChild>(root, &child, seen)? else {
                continue;
            };
            let Some(container) = name.container() else {
                if repeated {
                    self.duplicate(root, &child)?;
                }
                self.arena.scene.gravity = Some(self.vector(&child)?);
                continue;
            };
            if repeated {
                return Err(self.tok.duplicate_container(root, &child));
            }
            self.container(&child, container)?;
        }
        self.place_comments(Object::World, KeptAt::Inside { within: "", before: "" });
        Ok(())
    }

    /// The items of a container, to its end.
    fn container(&mut self, tag: &Tag, name: Container) -> Parsed<()> {
        let each: fn(&mut Self, &Tag) -> Parsed<()> = match name {
            Container::Shapes => Self::shape,
            Container::Fixtures => Self::fixture,
            Container::Bodies => Self::body,
            Container::Joints => Self::joint,
        };
        self.items(tag, name.item(), each)?;
        self.place_comments(Object::World, KeptAt::Inside { within: name.name(), before: "" });
        Ok(())
    }

    pub(super) fn read_version(&mut self, root: &Tag) -> Parsed<()> {
        let attrs = attributes!(self, root, &["Version"]);
        let Some(version) = attrs.iter().find(|a| a.is("version")) else {
            return self.warn(Code::LegacyUnversioned, root.at, || {
                "the file has no Version: read as a legacy (2010) editor file, whose joints \
                     name their bodies with JointA and JointB"
            });
        };
        self.arena.version = match super::trim_xml(&version.value) {
            "1" => 1,
            "2" => 2,
            "3" => 3,
            other => {
                return Err(problem(
                    Code::UnsupportedVersion,
                    version.at,
                    format!(
                        "Version \"{}\" is not supported: box2scene reads Versions 1, 2 and 3 and unversioned files",
                        super::shorten(other)
                    ),
                ));
            }
        };
        self.arena.scene.version = self.arena.version;
        Ok(())
    }
}

/// Once the world is read into `arena`, with `seen` its elements: warns of each container it
/// did not have.
pub(super) fn end_world(arena: &mut Arena, seen: &Seen) -> Parsed<()> {
    for container in Container::ALL {
        if !seen.contains(WorldChild::of(container)) {
            let missing = Finding::at(Code::MissingContainer, arena.origins.world, String::new());
            let words = || format!("the file has no <{}>; read as empty", container.name());
            arena.findings.note_worded(missing, words)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::WorldChild;
    use crate::containers::Container;
    use crate::parse::names::Element;

    /// The reader knows every container of the list by its name, and Gravity is none.
    #[test]
    fn every_container_is_a_child_of_the_world() {
        for container in Container::ALL {
            assert_eq!(WorldChild::of(container).name(), container.name());
            assert_eq!(WorldChild::of(container).container(), Some(container));
        }
        assert_eq!(WorldChild::Gravity.container(), None);
    }
}
