#![allow(dead_code)]
pub fn to_json(_s: &crate::Scene) -> String { todo!() }
