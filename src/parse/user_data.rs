//! The reader's handler of `<UserData>` (and Aether.Physics2D's `<Tag>`): the content, read
//! by the markup's [`walk_user_data`] as a fragment the builder is given is, stored in the
//! arena.

use super::{Reader, Tag};
use crate::error::Parsed;
use crate::markup::{EditorForm, walk_user_data};
use crate::scene::UserDataText;

impl<'a> Reader<'a> {
    /// [`Reader::user_data`] of Aether.Physics2D's `<Tag>`.
    pub(super) fn tagged_user_data(&mut self, tag: &Tag) -> Parsed<u32> {
        self.arena.origins.signs.tags = true;
        self.user_data(tag)
    }

    /// Stores the user data of `tag` and returns its index.
    pub(super) fn user_data(&mut self, tag: &Tag) -> Parsed<u32> {
        let (raw, form) = match tag.empty {
            true => (String::new(), EditorForm::default()),
            false => walk_user_data(&mut self.tok, tag)?,
        };
        let (type_name, value) = form.texts();
        let mut add = |s: Option<String>| s.map(|s| self.arena.scene.add_str(&s));
        let (type_name, value) = (add(type_name), add(value));
        let raw = self.arena.scene.add_str(&raw);
        self.arena.scene.user_data.push(UserDataText { raw, type_name, value });
        Ok((self.arena.scene.user_data.len() - 1) as u32)
    }
}
