//! The world's four containers and the item each holds, in the order writers list them:
//! the one list the reader, the cutting of a file into pieces and the writer all follow.
//! It imports nothing, so that any of them may use it.
#![forbid(unsafe_code)]

/// One of the containers in `<World>`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Container {
    Shapes,
    Fixtures,
    Bodies,
    Joints,
}

impl Container {
    /// Every container, in the order writers list them.
    pub(crate) const ALL: [Container; 4] =
        [Container::Shapes, Container::Fixtures, Container::Bodies, Container::Joints];

    /// The container's element.
    pub fn name(self) -> &'static str {
        match self {
            Container::Shapes => "Shapes",
            Container::Fixtures => "Fixtures",
            Container::Bodies => "Bodies",
            Container::Joints => "Joints",
        }
    }

    /// The element of each of its items, as the editor spells it.
    pub fn item(self) -> &'static str {
        match self {
            Container::Shapes => "Shape",
            Container::Fixtures => "Fixture",
            Container::Bodies => "Body",
            Container::Joints => "Joint",
        }
    }
}
