//! Reading a large file on two threads. A second parser starts at an item in the middle
//! of the text (a `<Body>` just after a `</Body>`, say), assuming that it lies directly in
//! its container in `<World>`, and reads from there to the end of the file. When the
//! first parser reaches that point it checks the assumption: its container is open
//! there, spelled as assumed, the second parser met no problem and no warning, and the
//! two together stay within the limits. Then it takes what the second one read and is
//! done; otherwise it reads on itself. Either way the scene, the warnings and the first
//! error are those of one parser reading the whole file.

use std::sync::mpsc;
use std::thread::Scope;

use super::names::{Element, Name};
use super::world::{CONTAINERS, WorldChild};
use super::{Parser, Seen, Tag};
use crate::LoadOptions;
use crate::input::Source;
use crate::text::is_xml_space_byte;

/// The smallest text worth a second thread: below it, starting one costs more than it
/// saves.
const MIN_BYTES: usize = 1 << 20;

/// The second parser, as the first one sees it.
pub(super) struct Ahead<'a> {
    /// Where it started: the `<` of an item.
    at: usize,
    /// The container it assumed the item is in.
    container: WorldChild,
    done: mpsc::Receiver<Option<Done<'a>>>,
}

/// What the second parser read, when it read to the end of the file without a problem.
struct Done<'a> {
    parser: Parser<'a>,
    /// The world's elements it read, its own container among them.
    seen: Seen,
}

/// Starts the second parser on `scope`, when the options allow a thread and `source` is
/// a text in memory large enough to be worth it; `split` forces where (for tests).
pub(super) fn start<'a, 'scope>(
    scope: &'scope Scope<'scope, '_>,
    source: &Source<'a>,
    options: &'a LoadOptions,
    split: Option<(usize, WorldChild)>,
) -> Option<Ahead<'a>>
where
    'a: 'scope,
{
    if options.threads == 1 {
        return None;
    }
    let shared = source.shared()?;
    let (at, container) = match split {
        Some(split) => split,
        None if shared.text().len() >= MIN_BYTES => split_point(shared.text().as_bytes())?,
        None => return None,
    };
    let (sender, done) = mpsc::sync_channel(1);
    scope.spawn(move || {
        let _ = sender.send(read_ahead(shared, options, at, container));
    });
    Some(Ahead { at, container, done })
}

/// The first item from a little before the middle of `text` on (the first thread also
/// takes over what the second read, and its shapes and fixtures cost a little more to
/// read than bodies and joints) that follows an item of its own name, with only white
/// space between: `</Body>` then `<Body`. None when there is none before three quarters
/// of the text.
fn split_point(text: &[u8]) -> Option<(usize, WorldChild)> {
    let (mut from, last) = (text.len() / 100 * 46, text.len() / 4 * 3);
    while from < last {
        let at = from + memchr::memchr(b'<', &text[from..last])?;
        if let Some(container) = item_after_its_twin(text, at) {
            return Some((at, container));
        }
        from = at + 1;
    }
    None
}

/// The container of the item whose start tag begins at `at`, when the tag before it is the
/// end tag of an item of the same name.
fn item_after_its_twin(text: &[u8], at: usize) -> Option<WorldChild> {
    let after = &text[at + 1..];
    let container = CONTAINERS.into_iter().find(|c| {
        let name = c.item().as_bytes();
        after.starts_with(name)
            && after
                .get(name.len())
                .is_some_and(|&b| matches!(b, b'>' | b'/') || is_xml_space_byte(b))
    })?;
    let before = &text[..at];
    let end = before.iter().rposition(|&b| !is_xml_space_byte(b))? + 1;
    let name = container.item().as_bytes();
    let twin = before[..end].strip_suffix(b">")?.strip_suffix(name)?.ends_with(b"</");
    twin.then_some(container)
}

/// The second parser: reads the root's start tag for the Version, then from `at` to the
/// end of the file as if `at` began an item of `container`.
fn read_ahead<'a>(
    source: Source<'a>,
    options: &'a LoadOptions,
    at: usize,
    container: WorldChild,
) -> Option<Done<'a>> {
    let mut parser = Parser::new(source, options);
    let root = parser.root().ok()?;
    parser.read_version(&root).ok()?;
    // The first parser counts and reports everything up to `at`.
    parser.warnings.clear();
    parser.elements = 0;
    let tag = Tag { name: Name::new(container.name()), content: None, at, empty: false };
    parser.open.push(tag.name.clone());
    (parser.pos, parser.started, parser.last) = (at, at, at);
    let mut seen = Seen::default();
    seen.bits |= 1 << container.index();
    let read = parser
        .container(&tag, container, &mut seen)
        .and_then(|_| parser.world_children(&root, &mut seen))
        .and_then(|()| parser.epilog());
    let clean = read.is_ok() && parser.warnings.is_empty() && parser.dropped_warnings.0 == 0;
    clean.then_some(Done { parser, seen })
}

impl Parser<'_> {
    /// Before the next item of `container`: whether the second parser started here and
    /// what it read is taken, so that the whole file is read. `seen` has the world's
    /// elements read so far and gets those the second parser read.
    pub(super) fn take_over(&mut self, container: WorldChild, seen: &mut Seen) -> bool {
        let Some(at) = self.ahead.as_ref().map(|ahead| ahead.at) else { return false };
        if self.open.len() != 2 {
            return false;
        }
        self.skip_space();
        if self.pos < at {
            return false;
        }
        // Here or past it: the second parser is of use here or nowhere.
        let Some(ahead) = self.ahead.take() else { return false };
        let assumed = self.pos == ahead.at
            && container == ahead.container
            && self.open[1].as_str() == container.name();
        if !assumed {
            return false;
        }
        let Ok(Some(Done { parser, seen: seen_ahead })) = ahead.done.recv() else {
            return false;
        };
        let within_limits = self.elements + parser.elements <= self.options.max_elements;
        let repeated = seen.bits & seen_ahead.bits & !(1 << container.index());
        if !within_limits || repeated != 0 {
            return false;
        }
        let bodies_before = self.scene.bodies.len() as u32;
        self.scene.append(parser.scene);
        self.origins.append(parser.origins, bodies_before);
        self.elements += parser.elements;
        (self.pos, self.started, self.last) = (parser.pos, parser.started, parser.last);
        self.open = parser.open;
        seen.bits |= seen_ahead.bits;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    /// The scene (as its dump) or the error of a load on one thread, or on two split at
    /// `split`.
    fn outcome(bytes: &[u8], options: &LoadOptions, split: Option<(usize, WorldChild)>) -> String {
        let threads = if split.is_some() { 2 } else { 1 };
        let options = &LoadOptions { threads, ..*options };
        let loaded: Result<Scene, _> = Source::memory(bytes, options)
            .and_then(|source| super::super::parse_split(source, options, split));
        match loaded {
            Ok(scene) => crate::dump::to_json(&scene),
            Err(e) => format!("{e:?}"),
        }
    }

    /// Where a split is worth trying: every `<`.
    fn tags(bytes: &[u8]) -> impl Iterator<Item = usize> + '_ {
        memchr::memchr_iter(b'<', bytes)
    }

    #[test]
    fn a_split_point_is_an_item_after_its_twin() {
        let text = b"<Bodies><Body/>\n  </Body>\r\n\t<Body Type=\"Static\">";
        let at = text.len() - 20;
        assert_eq!(item_after_its_twin(text, at), Some(WorldChild::Bodies));
        assert_eq!(item_after_its_twin(b"</Body><Bodies>", 7), None);
        assert_eq!(item_after_its_twin(b"</Joint> <Body>", 9), None);
        assert_eq!(item_after_its_twin(b"</Shape><Shape>", 8), Some(WorldChild::Shapes));
        assert_eq!(item_after_its_twin(b"<Shape>", 0), None);
    }

    #[test]
    fn the_split_point_is_the_first_twin_from_near_the_middle_on() {
        let body = "<Body Type=\"Static\"><Fixtures /></Body>\n";
        let text = format!("<World Version=\"1\"><Bodies>{}</Bodies></World>", body.repeat(100));
        let (at, container) = split_point(text.as_bytes()).expect("a split point");
        assert_eq!(container, WorldChild::Bodies);
        assert!(text[at..].starts_with("<Body "), "{}", &text[at..at + 10]);
        let from = text.len() / 100 * 46;
        assert!(at >= from && at - from <= body.len(), "{at}");
        assert_eq!(split_point(b"<World><Bodies></Bodies></World>"), None);
    }

    /// Split at every tag, assuming each container: what the second parser reads is taken
    /// where the assumption holds and dropped elsewhere, and the result never changes.
    #[test]
    fn every_split_of_every_scene_file_loads_as_one_thread_reads_it() {
        let options = LoadOptions::default();
        for (name, bytes) in crate::scene_files() {
            let expected = outcome(&bytes, &options, None);
            for at in tags(&bytes) {
                for container in CONTAINERS {
                    let split = outcome(&bytes, &options, Some((at, container)));
                    assert_eq!(split, expected, "{name} split at {at} in {container:?}");
                }
            }
        }
    }

    /// A change anywhere (a warning, an error, a repeated container, a limit) gives the
    /// load of one thread, wherever the split.
    #[test]
    fn changed_files_load_as_one_thread_reads_them() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = move |below: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % below as u64) as usize
        };
        let strict = LoadOptions { strict: true, ..LoadOptions::default() };
        for (name, bytes) in crate::scene_files() {
            let splits: Vec<_> = tags(&bytes)
                .filter_map(|at| Some((at, item_after_its_twin(&bytes, at)?)))
                .collect();
            for _ in 0..200 {
                let mut changed = bytes.clone();
                let at = next(changed.len());
                changed[at] = b"<>/\"x 1&-"[next(9)];
                for options in [LoadOptions::default(), strict] {
                    let expected = outcome(&changed, &options, None);
                    for &split in &splits {
                        let got = outcome(&changed, &options, Some(split));
                        assert_eq!(got, expected, "{name}, byte {at} changed, split at {split:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn what_the_second_thread_must_not_decide_is_left_to_the_first() {
        let bodies = "<Body Type=\"Static\"><Fixtures /></Body>\n".repeat(4);
        let scene = |before: &str, after: &str| {
            format!(
                "<World Version=\"1\">{before}<Shapes /><Fixtures /><Bodies>{bodies}</Bodies>{after}</World>"
            )
        };
        let cases = [
            ("gravity on both sides", scene("<Gravity>0 -10</Gravity>", "<Gravity>0 -9</Gravity>")),
            ("gravity after the split", scene("", "<Gravity>0 -9</Gravity><Joints />")),
            ("a container read twice", scene("<Joints />", "<Joints />")),
            ("a missing container", scene("", "")),
            ("an unknown element", scene("", "<Joints /><Wind />")),
            ("text after the world", scene("", "<Joints />") + "x"),
            ("a twin in a comment", scene("<!-- </Body> <Body> -->", "<Joints />")),
        ];
        for (case, text) in cases {
            let bytes = text.as_bytes();
            let count = bytes.iter().filter(|&&b| b == b'<').count() as u64;
            for max_elements in [count, count / 2, 3] {
                let options = LoadOptions { max_elements, ..LoadOptions::default() };
                let expected = outcome(bytes, &options, None);
                for at in tags(bytes) {
                    let got = outcome(bytes, &options, Some((at, WorldChild::Bodies)));
                    assert_eq!(got, expected, "{case}, max {max_elements}, split at {at}");
                }
            }
        }
    }

    /// The second thread is used where the assumption holds: given a text with one more
    /// body after the split than the first parser's, the first parser ends with it.
    #[test]
    fn the_first_parser_takes_what_the_second_read() {
        let scene = |bodies: usize| {
            let body = "<Body Type=\"Dynamic\"><Fixtures /></Body>";
            format!(
                "<World Version=\"1\"><Shapes /><Fixtures /><Bodies>{}</Bodies><Joints /></World>",
                body.repeat(bodies)
            )
        };
        let (mine, theirs) = (scene(3), scene(4));
        let at = mine.rfind("<Body ").unwrap();
        let options = LoadOptions::default();
        let mut parser = Parser::new(Source::memory(mine.as_bytes(), &options).unwrap(), &options);
        let second = Source::memory(theirs.as_bytes(), &options).unwrap();
        std::thread::scope(|scope| {
            parser.ahead = start(scope, &second, &options, Some((at, WorldChild::Bodies)));
            parser.document().unwrap();
        });
        assert_eq!(parser.scene.bodies.len(), 4);
        assert_eq!(parser.elements, 4 + 4 * 2 + 1);
        assert_eq!(parser.origins.bodies.last(), Some(&theirs.rfind("<Body ").unwrap()));
    }
}
