//! The root: `<World Version="N">`, its gravity and its four containers.

use super::{Element, Parsed, Parser, Seen, Tag, elements, problem};
use crate::error::Code;

elements! {
    enum WorldChild { Gravity, Shapes, Fixtures, Bodies, Joints }
}

impl<'a> Parser<'a> {
    /// The whole document: prolog, `<World>`, epilog.
    pub(super) fn document(&mut self) -> Parsed<()> {
        let root = loop {
            match self.next_node()? {
                super::Node::Open(tag) => break tag,
                super::Node::Text(t) if !self.is_blank(&t) => {
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
        self.world(&root)?;
        loop {
            match self.next_node()? {
                super::Node::Eof => return Ok(()),
                super::Node::Text(t) if self.is_blank(&t) => {}
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

    fn world(&mut self, root: &Tag) -> Parsed<()> {
        self.read_version(root)?;
        let mut seen = Seen::default();
        while let Some(child) = self.child(root)? {
            let Some((name, repeated)) = self.known(root, &child, &mut seen)? else {
                continue;
            };
            if name == WorldChild::Gravity {
                if repeated {
                    self.duplicate(root, &child)?;
                }
                self.scene.gravity = Some(self.vector(&child)?);
                continue;
            }
            if repeated {
                return Err(self.duplicate_container(root, &child));
            }
            match name {
                WorldChild::Shapes => self.items(&child, "Shape", Self::shape)?,
                WorldChild::Fixtures => self.items(&child, "Fixture", Self::fixture)?,
                WorldChild::Bodies => self.items(&child, "Body", Self::body)?,
                _ => self.items(&child, "Joint", Self::joint)?,
            }
        }
        use WorldChild::*;
        for container in [Shapes, Fixtures, Bodies, Joints] {
            if !seen.contains(container) {
                let message = format!("the file has no <{}>; read as empty", container.name());
                self.warn(Code::MissingContainer, root.at, message)?;
            }
        }
        Ok(())
    }

    fn read_version(&mut self, root: &Tag) -> Parsed<()> {
        let attrs = self.attributes(root)?;
        self.unknown_attributes(root, &attrs, &["version"])?;
        let Some(version) = attrs.iter().find(|a| a.is("version")) else {
            return self.warn(
                Code::LegacyUnversioned,
                root.at,
                "the file has no Version: read as a legacy (2010) editor file, whose joints name \
                 their bodies with JointA and JointB",
            );
        };
        self.version = match super::trim_xml(&version.value) {
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
        self.scene.version = self.version;
        Ok(())
    }
}
