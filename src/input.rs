#![allow(dead_code)]
pub fn too_big(_max: u64) -> crate::Error { todo!() }
