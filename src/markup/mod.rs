//! The markup stage, below the reader: XML read into nodes (`tokenizer/`), element names as
//! 128-bit keys (`name.rs`), and the content of a `<UserData>` read as the reader reads it
//! (`user_data.rs`), which the builder and `holds` read a fragment with. It knows XML and
//! no scene object: the reader (`parse`) makes its nodes into records.
#![forbid(unsafe_code)]

mod name;
mod tokenizer;
mod user_data;

use std::borrow::Cow;

pub(crate) use name::{Name, SHORT, key};
pub(crate) use tokenizer::{Attr, Node, Tag, Text, Tokenizer};
pub(crate) use user_data::{EditorForm, USER_DATA_DEPTH, user_data_fragment, walk_user_data};

/// At most 40 characters of `text`, for messages.
pub(crate) fn shorten(text: &str) -> Cow<'_, str> {
    match text.char_indices().nth(40) {
        Some((cut, _)) => Cow::Owned(format!("{}...", &text[..cut])),
        None => Cow::Borrowed(text),
    }
}
