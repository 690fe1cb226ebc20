//! The scan stage: the structure of the text, found without reading it.
//!
//! A [`Scanner`] goes over the text once, [`BLOCK`] bytes at a time with the machine's
//! vector instructions, and follows its markup: every tag to its `>` (its quoted values
//! passed over), comments, CDATA and processing instructions to their ends. It counts the
//! elements and the depth as it goes, and lists the items ([`Item`]: the start tags
//! directly in an element of the root, a world container's items in a scene), which are
//! where a two-thread read cuts the text into pieces: facts of the text, not guesses. It
//! carries its state from one window of the text to the next, so a delimiter cut by the end
//! of a window is found once more text comes. It checks nothing: where the text is not
//! well-formed it stops or lists what it saw, and the reader reports the problem.
#![forbid(unsafe_code)]

use crate::bytes::{BLOCK, block_masks, tag_end};

#[cfg(test)]
mod tests;

/// A start tag directly in an element of the root (at depth 2), with the offset of that
/// element's start tag, how many elements began before it, and whether other markup (a
/// comment, CDATA, a processing instruction) comes between it and the tag before it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Item {
    pub at: usize,
    pub parent: usize,
    pub elements_before: u64,
    pub after_markup: bool,
}

/// Where the scanned text stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// In text, between tags.
    Text,
    Comment,
    CData,
    Pi,
    /// At markup after which nothing can be read (a DOCTYPE, `--` in a comment, `<!` that
    /// XML does not have): the reader stops there.
    Stopped,
}

/// The scan's state, carried from one window of the text to the next.
pub(crate) struct Scanner {
    /// The offset up to which the text was scanned: the next byte to look at.
    at: usize,
    mode: Mode,
    tally: Tally,
    /// The tally where the last markup other than a tag began.
    markup: Option<Tally>,
    items: Vec<Item>,
}

/// What the scan counts as it goes: a value, which the loop over the tags keeps in
/// registers.
#[derive(Clone, Copy, Default, PartialEq, Eq)]
struct Tally {
    /// Elements open, and elements begun.
    depth: usize,
    elements: u64,
    /// The start tag of the element open at depth 1.
    parent: usize,
}

impl Scanner {
    /// A scan from the start of a text.
    pub fn new() -> Scanner {
        Scanner {
            at: 0,
            mode: Mode::Text,
            tally: Tally::default(),
            markup: None,
            items: Vec::new(),
        }
    }

    /// The offset up to which the text is scanned: the next call is given the text from
    /// there on.
    pub fn scanned(&self) -> usize {
        self.at
    }

    /// The items found since the last call.
    pub fn take_items(&mut self) -> Vec<Item> {
        std::mem::take(&mut self.items)
    }

    /// Scans `text`, which starts at offset `base`, where the scan stands. Markup that
    /// `text` cuts is left for the next call, with more text.
    pub fn scan(&mut self, text: &[u8], base: usize) {
        debug_assert_eq!(base, self.at, "the text goes on where the scan stands");
        let text_end = base + text.len();
        while self.at < text_end {
            let rest = &text[self.at - base..];
            let paused = match self.mode {
                Mode::Text => self.text(rest),
                Mode::Comment => self.comment(rest),
                Mode::CData => self.until(rest, b"]]>"),
                Mode::Pi => self.until(rest, b"?>"),
                Mode::Stopped => true,
            };
            if paused {
                return;
            }
        }
    }

    /// Text and tags up to other markup; true when the text at hand is too short to go on
    /// (markup it cuts).
    fn text(&mut self, rest: &[u8]) -> bool {
        let (tally, stop) = tags(rest, self.at, self.tally, self.markup, &mut self.items);
        self.tally = tally;
        match stop {
            Stop::End => {
                self.at += rest.len();
                false
            }
            Stop::Cut(at) => {
                self.at = at;
                true
            }
            Stop::Markup(at, mode) => {
                self.markup = Some(tally);
                self.at = at;
                self.mode = mode;
                false
            }
        }
    }

    /// A comment up to its `-->`, or to `--` that does not end it.
    fn comment(&mut self, rest: &[u8]) -> bool {
        let Some(i) = memchr::memmem::find(rest, b"--") else {
            // A `-` at the end may begin the `--`.
            self.at += rest.len() - usize::from(rest.last() == Some(&b'-'));
            return rest.len() < 2;
        };
        let Some(&after) = rest.get(i + 2) else {
            self.at += i;
            return true;
        };
        self.at += i;
        if after == b'>' {
            self.at += 3;
            self.mode = Mode::Text;
        } else {
            self.mode = Mode::Stopped;
        }
        false
    }

    /// CDATA or a processing instruction up to `delimiter`.
    fn until(&mut self, rest: &[u8], delimiter: &[u8]) -> bool {
        let Some(i) = memchr::memmem::find(rest, delimiter) else {
            // The end may hold the start of the delimiter.
            let keep =
                (1..delimiter.len()).rev().find(|&n| rest.ends_with(&delimiter[..n])).unwrap_or(0);
            self.at += rest.len() - keep;
            return keep == rest.len();
        };
        self.at += i + delimiter.len();
        self.mode = Mode::Text;
        false
    }
}

/// Where [`tags`] stopped: at the end of the text, at markup the text cuts, or after the
/// start of other markup, whose mode the scan goes on in.
enum Stop {
    End,
    Cut(usize),
    Markup(usize, Mode),
}

/// The tags of `rest`, text that starts at offset `start`, up to other markup, counted into
/// `tally`, the items pushed on `items`. A block's masks of `<`, `>` and quotes give each
/// tag: its end is the first `>` after its `<`, unless a quote comes before it, and then it
/// is looked for in the bytes, past the quoted values. The byte after a `<` tells start tags
/// from end tags and sends the rest of markup to [`classify`].
fn tags(
    rest: &[u8],
    start: usize,
    mut tally: Tally,
    markup: Option<Tally>,
    items: &mut Vec<Item>,
) -> (Tally, Stop) {
    let mut from = 0;
    'blocks: while from < rest.len() {
        let mut padded = [0; BLOCK];
        let block = match rest[from..].first_chunk::<BLOCK>() {
            Some(block) => block,
            None => {
                // The last bytes, after which zeros match nothing.
                padded[..rest.len() - from].copy_from_slice(&rest[from..]);
                &padded
            }
        };
        let [mut lts, gts, quotes] =
            block_masks(block, [[b'<', b'<'], [b'>', b'>'], [b'"', b'\'']]);
        while lts != 0 {
            let bit = lts.trailing_zeros() as usize;
            let i = from + bit;
            let Some(&next) = rest.get(i + 1) else {
                return (tally, Stop::Cut(start + i));
            };
            if next == b'/' {
                tally.depth = tally.depth.saturating_sub(1);
                lts &= lts - 1;
                continue;
            }
            if next == b'!' || next == b'?' {
                return match classify(&rest[i..]) {
                    Some((mode, len)) => (tally, Stop::Markup(start + i + len, mode)),
                    None => (tally, Stop::Cut(start + i)),
                };
            }
            let end = (gts & above(bit)).trailing_zeros() as usize;
            let (gt, empty) = match end < BLOCK && quotes & above(bit) & below(end) == 0 {
                true => (from + end, block[end - 1] == b'/'),
                false => match tag_end(&rest[i + 1..]) {
                    Some(end) => (i + 1 + end, rest[i + end] == b'/'),
                    None => return (tally, Stop::Cut(start + i)),
                },
            };
            if tally.depth <= 2 {
                tally.parent = near_root(tally, start + i, markup, items);
            }
            tally.elements += 1;
            tally.depth += usize::from(!empty);
            if gt >= from + BLOCK {
                from = gt + 1;
                continue 'blocks;
            }
            lts &= above(gt - from);
        }
        from += BLOCK;
    }
    (tally, Stop::End)
}

/// A start tag at `lt` opens an element directly in the root, or in an element of the root:
/// an item, pushed on `items`; other markup came right before it when the last began at the
/// same tally (`markup`: no tag came since). Returns the start tag of the element open at
/// depth 1 from then on. Out of the loop, which keeps `tally` in registers.
#[cold]
#[inline(never)]
fn near_root(tally: Tally, lt: usize, markup: Option<Tally>, items: &mut Vec<Item>) -> usize {
    match tally.depth {
        1 => return lt,
        2 => items.push(Item {
            at: lt,
            parent: tally.parent,
            elements_before: tally.elements,
            after_markup: markup == Some(tally),
        }),
        _ => {}
    }
    tally.parent
}

/// The bits of a block's mask above bit `bit`.
fn above(bit: usize) -> u64 {
    u64::MAX << bit << 1
}

/// The bits of a block's mask below bit `bit`.
fn below(bit: usize) -> u64 {
    !(u64::MAX << bit)
}

/// The mode that markup other than a tag, `text` (which starts with `<!` or `<?`), begins,
/// and how many bytes say so; None when too few are at hand to tell.
#[cold]
fn classify(text: &[u8]) -> Option<(Mode, usize)> {
    if text.get(1) == Some(&b'?') {
        return Some((Mode::Pi, 2));
    }
    for (prefix, mode) in [(&b"<!--"[..], Mode::Comment), (b"<![CDATA[", Mode::CData)] {
        let n = prefix.len().min(text.len());
        if text[..n] == prefix[..n] {
            return (n == prefix.len()).then_some((mode, n));
        }
    }
    Some((Mode::Stopped, 2))
}
