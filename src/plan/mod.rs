//! The plan stage, after the frozen scene: what each Box2D version can be given. Today it
//! holds the working range, one measured table per engine version (`range.rs`), which the
//! executors in C, C++ and Python read instead of holding numbers of their own.

#![forbid(unsafe_code)]

mod box2d2;
mod printed;
mod range;
mod records;

pub use range::{Engine, WorkingRange};
pub use records::*;
