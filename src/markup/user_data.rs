//! The content of a `<UserData>` as markup: kept verbatim, never interpreted, plus the type
//! name and value text when it has the editor's form `<Type>T</Type><Value><x>V</x></Value>`
//! (docs/format.md, "UserData"). One walk reads it, for the reader's handler and for a
//! fragment the builder is given alike.

use super::{Node, Tag, Tokenizer};
use crate::error::{Code, Parsed, Problem, problem};
use crate::input::Source;
use crate::options::LoadOptions;
use crate::text::trim_xml;

/// Where a UserData is written: inside `<World>`, a container, an item and `<UserData>`.
pub(crate) const USER_DATA_DEPTH: u32 = 4;

/// Reads `raw` as the content of a `<UserData>` element, exactly as the loader would read
/// it from a written file with the default options, inside `depth` open elements
/// ([`USER_DATA_DEPTH`] for UserData): the type name and value text when it has the
/// editor's form. Fails when `raw` is not well-formed XML content, or when the loader
/// would refuse it there.
pub(crate) fn user_data_fragment(
    raw: &str,
    depth: u32,
) -> Parsed<(Option<String>, Option<String>)> {
    let document = format!("<UserData>{raw}</UserData>");
    // Here it lies inside one element, `<UserData>`.
    let default = LoadOptions::default();
    let options = LoadOptions { max_depth: default.max_depth + 1 - depth, ..default };
    let source = Source::memory(document.as_bytes(), &options)
        .map_err(|e| problem::<Problem>(e.code, 0, e.message))?;
    let mut tok = Tokenizer::new(source, &options);
    let read = |tok: &mut Tokenizer| -> Parsed<EditorForm> {
        let Node::Open(tag) = tok.next_node()? else {
            unreachable!("the document starts with <UserData>")
        };
        let (_, form) = walk_user_data(tok, &tag)?;
        match tok.next_node()? {
            Node::Eof => Ok(form),
            _ => Err(problem(Code::MalformedXml, 0, "closes <UserData> early")),
        }
    };
    let form = read(&mut tok).map_err(|p| -> Problem {
        problem(p.code, 0, format!("the UserData is not well-formed XML content: {}", p.message))
    })?;
    Ok(form.texts())
}

/// What a walk over a UserData subtree saw of the editor's form.
#[derive(Default)]
pub(crate) struct EditorForm {
    type_name: Option<String>,
    value: Option<String>,
    types: u32,
    values: u32,
    value_children: u32,
    /// The value's child holds elements (an object of a program's own class): the type name
    /// stands, the value has no text of its own.
    value_tree: bool,
    /// Anything else: other elements, other nesting, loose text.
    other: bool,
}

impl EditorForm {
    fn complete(&self) -> bool {
        !self.other && self.types == 1 && self.values == 1 && self.value_children == 1
    }

    /// The type name, trimmed, when the content has the editor's form, and the value text,
    /// trimmed, when the value's child holds only text.
    pub(crate) fn texts(self) -> (Option<String>, Option<String>) {
        match self.complete() {
            true => (
                self.type_name.map(|t| trim_xml(&t).to_owned()),
                self.value.filter(|_| !self.value_tree).map(|v| trim_xml(&v).to_owned()),
            ),
            false => (None, None),
        }
    }
}

/// Where the walk is.
#[derive(Clone, Copy, PartialEq)]
enum Inside {
    Type,
    Value,
    ValueChild,
    /// Inside the value's child: the fields of an object.
    ValueTree,
    Other,
}

/// Reads to the end of `tag`; returns its inner XML and what it saw of the editor's form.
pub(crate) fn walk_user_data(tok: &mut Tokenizer, tag: &Tag) -> Parsed<(String, EditorForm)> {
    let at = tok.position();
    tok.kept.pin(at);
    let mut form = EditorForm::default();
    let mut path: Vec<Inside> = Vec::new();
    loop {
        match tok.next_node()? {
            Node::Open(child) => {
                tok.check_attributes(&child)?;
                let inside = match path.as_slice() {
                    [] if child.is("type") => {
                        form.types += 1;
                        form.type_name.get_or_insert_with(String::new);
                        Inside::Type
                    }
                    [] if child.is("value") => {
                        form.values += 1;
                        Inside::Value
                    }
                    [Inside::Value] => {
                        form.value_children += 1;
                        form.value.get_or_insert_with(String::new);
                        Inside::ValueChild
                    }
                    [Inside::Value, Inside::ValueChild, ..] => {
                        form.value_tree = true;
                        Inside::ValueTree
                    }
                    _ => {
                        form.other = true;
                        Inside::Other
                    }
                };
                if !child.empty {
                    path.push(inside);
                }
            }
            Node::Text(t) => {
                let t = tok.text_of(&t);
                match path.last() {
                    Some(Inside::Type) => {
                        form.type_name.get_or_insert_with(String::new).push_str(t)
                    }
                    Some(Inside::ValueChild) => {
                        form.value.get_or_insert_with(String::new).push_str(t)
                    }
                    Some(Inside::ValueTree) => {}
                    _ => form.other |= !trim_xml(t).is_empty(),
                }
            }
            Node::Close(at) => {
                if path.pop().is_none() {
                    return Ok((tok.unpin(at), form));
                }
            }
            Node::Eof => return Err(tok.unclosed(tag)),
        }
    }
}
