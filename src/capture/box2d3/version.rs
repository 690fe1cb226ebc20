//! What differs between Box2D v3.1 and v3.2 on the way back, beside the plan's
//! `box2d3/version.rs`: how a chain's segments are held and what one segment alone was.

use crate::plan::box2d3::V3;
use crate::scene::ShapeKind;

impl V3 {
    /// Whether the engine keeps a chain as an object that lists its segments (v3.1's
    /// `b2ChainId`), so that the segments an adapter marks as one chain are one; v3.2's
    /// build makes loose segments, which are one chain where they continue one another.
    pub(super) fn chains_are_objects(self) -> bool {
        self == V3::V31
    }

    /// What a chain of one segment was built from: an edge with ghost vertices or a chain
    /// of two vertices. v3.1 made a chain of it, v3.2 a loose segment, written as the edge.
    pub(super) fn lone_segment(self) -> ShapeKind {
        match self {
            V3::V31 => ShapeKind::Chain,
            V3::V32 => ShapeKind::Edge,
        }
    }
}
