use crate::{LoadOptions, Scene, error::Error};
pub fn load(_bytes: &[u8], _options: &LoadOptions) -> Result<Scene, Error> { todo!() }
