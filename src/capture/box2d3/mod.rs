//! Box2D v3.1 and v3.2 on the way back: a held body, shape or joint as the scene's, each
//! inverse searching the value whose forward computation, the plan's own
//! (`crate::plan::box2d3`), gives back what the engine holds, and what the format cannot
//! hold said once. `version.rs` holds what the two versions read back differently beside
//! the plan's; `shapes.rs` the shapes, chains and filters; `bodies.rs` the bodies and the
//! one report of the rotations no angle gives; `joints.rs` the joints and their frames.

mod bodies;
mod joints;
mod shapes;
mod version;

#[cfg(test)]
mod tests;

use std::fmt;

use self::bodies::Turned;
use crate::plan::Object;
use crate::plan::box2d3::V3;

/// Where a family says what it loses: the object it concerns and the message; the caller
/// adds the code (`lossy-capture`), the object's index and its name.
pub(crate) type Say<'a> = dyn FnMut(Object, fmt::Arguments<'_>) + 'a;

/// One capture's v3 family: the version, and the rotations no angle gave, said once after
/// the bodies.
#[derive(Debug)]
pub(crate) struct Family {
    v3: V3,
    turned: Turned,
}

impl Family {
    pub(crate) fn new(v3: V3) -> Family {
        Family { v3, turned: Turned::default() }
    }

    /// After the bodies: the one report of the rotations no angle gives exactly.
    pub(crate) fn bodies_done(&self, say: &mut Say<'_>) {
        self.turned.report(say);
    }
}
