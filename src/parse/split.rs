//! A large file read on two threads: a stage above the reader. The text is cut into pieces
//! before items (a `<Body>` directly in `<Bodies>`), and each piece is read by the ordinary
//! reader from its start to its end: the first from the start of the file, each other from
//! its item in its container, with the root's start tag and Version read once from the
//! file's start. The reader knows nothing of this: it is given a
//! text that ends where its piece ends (see [`Source::ends_early`]) and reads it as a file.
//! The calling thread reads the pieces from the first on, into one arena, and a second
//! thread from the last back, each into an arena of its own, until they meet; the second
//! thread's arenas are then appended in order.
//!
//! Where the pieces begin is looked for near every [`PIECE_BYTES`] of the text, not found
//! by a scan of the whole: an item's start tag right after the end tag of another (white
//! space between), as the items of a container follow one another. That is a guess, which
//! the reading of each piece settles: a piece is taken only when its reader read it
//! without a problem (warnings are fine: they are appended in the order one reader finds
//! them) and ended directly in the container the next piece was read in, with nothing
//! read waiting (a comment goes with the item after it), the limits still hold and no
//! world element was read in two pieces. Otherwise the whole file is read again on the
//! calling thread alone. Either way the scene, the warnings and the first error are those
//! of one reader reading the whole file; a busy core only moves where the two meet. The
//! text may be in memory or in a file: each thread reads a file's pieces with a handle of
//! its own, each through a window as a whole file is read, so that neither holds a whole
//! piece.

use std::sync::{Mutex, PoisonError, mpsc};

use super::names::Element as _;
use super::world::{WorldChild, end_world};
use super::{Read, Reader, Seen, Tag, Tokenizer, read_whole};
use crate::arena::Arena;
use crate::bytes::{ENDS_NAME, is_xml_space_byte};
use crate::containers::Container;
use crate::error::Position;
use crate::input::{Shared, Source};
use crate::markup::Name;
use crate::options::LoadOptions;
use crate::place::Placer;

/// The smallest text worth a second thread: below it, starting one costs more than it
/// saves.
const MIN_BYTES: usize = 1 << 20;

/// About how long a piece is. The calling thread may wait for the piece the second thread
/// is reading when they meet, so pieces are short; each costs a reader and a merge.
const PIECE_BYTES: usize = 256 << 10;

/// At most this many pieces, however large the text.
const MAX_PIECES: usize = 64;

/// How much of the text is looked at a time for where a piece begins, and how much of its
/// start holds the root's start tag.
const SEARCH_BYTES: usize = 4 << 10;
const ROOT_BYTES: usize = 16 << 10;

/// Where a piece begins: the `<` of an item, and the container it is assumed to be in.
pub(super) type Boundary = (usize, Container);

/// The text of `source`, when the options allow a second thread and it is large enough to
/// be worth it: a text whose pieces readers of their own may read (see [`Source::shared`]).
/// None for a load on one thread, which then never enters this module's code again.
pub(super) fn shared<'a>(source: &Source<'a>, options: &LoadOptions) -> Option<Shared<'a>> {
    if options.threads == 1 {
        return None;
    }
    source.shared().filter(|text| text.len() >= MIN_BYTES)
}

/// Reads `text`, the whole of `source`, in pieces on two threads. For tests, `forced`
/// gives the boundaries and the first piece that is the second thread's from the start,
/// from which on it reads them whatever the timing.
pub(super) fn read<'a>(
    source: Source<'a>,
    text: Shared<'a>,
    options: &'a LoadOptions,
    forced: Option<(Vec<Boundary>, usize)>,
) -> Read<'a> {
    let mut buffer = Vec::new();
    let (boundaries, theirs_from) = match forced {
        Some((boundaries, theirs)) => (boundaries, theirs.saturating_add(1)),
        None => (boundaries(&text, &mut buffer), usize::MAX),
    };
    let root = boundaries.first().and_then(|&(first, _)| root(&text, options, first, &mut buffer));
    let (Some(root), Some(pieces)) = (root, pieces(&boundaries, text.len())) else {
        return read_whole(source, options, false);
    };
    let claims = Mutex::new(Claims { mine: 0, theirs: theirs_from.min(pieces.len()) });
    let (mine, theirs) = std::thread::scope(|scope| {
        let (sender, received) = mpsc::channel();
        let (root, pieces, claims, text) = (&root, &pieces, &claims, &text);
        scope.spawn(move || read_theirs(text, options, root, pieces, claims, &sender));
        let mine = read_mine(text, options, root, pieces, claims);
        (mine, received.into_iter().collect::<Vec<_>>())
    });
    match mine.and_then(|mine| merged(mine, theirs, &pieces, &text, options)) {
        Some(arena) => (Ok(arena), Placer::new(text.whole().unwrap_or(source))),
        None => read_whole(source, options, false),
    }
}

/// One piece of the text: from `from` to `to`, from the start of the file (`container`
/// None) or from an item of `container`.
struct Piece {
    from: usize,
    to: usize,
    container: Option<Container>,
}

/// The pieces `boundaries` cut a text of `len` bytes into; None when they do not go
/// forward through it.
fn pieces(boundaries: &[Boundary], len: usize) -> Option<Vec<Piece>> {
    let mut pieces = vec![Piece { from: 0, to: len, container: None }];
    for &(at, container) in boundaries {
        let last = pieces.last_mut()?;
        if at <= last.from || at >= len {
            return None;
        }
        last.to = at;
        pieces.push(Piece { from: at, to: len, container: Some(container) });
    }
    Some(pieces)
}

/// The root's start tag and the Version it says.
struct Root {
    name: Name,
    at: usize,
    version: u32,
}

/// The root's start tag and the Version it says, read from the start of the text (before
/// `first`, the first piece's start, and its last `<` within the first [`ROOT_BYTES`]),
/// a file's into `buffer`.
fn root(text: &Shared, options: &LoadOptions, first: usize, buffer: &mut Vec<u8>) -> Option<Root> {
    let head = text.bytes(0, first.min(ROOT_BYTES), buffer)?;
    let end = memchr::memrchr(b'<', head)?;
    let mut reader = Reader::new(Tokenizer::new(text.source(0, end)?, options), false);
    let root = reader.root().ok()?;
    reader.read_version(&root).ok()?;
    Some(Root { name: root.name, at: root.at, version: reader.arena.version })
}

/// How the reading of one piece ended: how many elements it read, the world's elements it
/// read, where it ended.
struct Ended {
    elements: u64,
    seen: Seen,
    /// Where it ended, when it placed what it found as it read (a piece of a file): counted
    /// from where its positions were counted from (see [`read_piece`]).
    end: Option<Position>,
    /// The container it ended in, before the next piece's item; None for the piece that
    /// ends the file.
    container: Option<Container>,
}

/// What the second thread read of one piece, by its index: what it built (its kept text
/// copied out of the piece's text, which is let go; its positions counted from the piece's
/// start) and how its reading ended.
type Done = (usize, Arena, Ended);

/// Reads `piece` of `text` with the ordinary reader into `arena` (a file's through a
/// window, as a whole file is read):
/// None when it does not read to its end without a problem. Positions are counted on from
/// `start`, where the piece begins, when it is known (the calling thread's pieces, each
/// after the one before); else from the piece's start.
fn read_piece(
    text: &Shared,
    options: &LoadOptions,
    (root, piece): (&Root, &Piece),
    arena: Arena,
    start: Option<Position>,
) -> Option<(Arena, Ended)> {
    let source = text.source(piece.from, piece.to)?;
    let mut reader = Reader::with_arena(Tokenizer::new(source, options), arena);
    let mut seen = Seen::default();
    let read = match piece.container {
        None => reader.document(&mut seen),
        Some(container) => {
            reader.arena.version = root.version;
            let (root, item) = (Tag::item(root.name.clone(), root.at), Name::new(container.name()));
            let open = vec![(root.name.clone(), root.at), (item.clone(), piece.from)];
            reader.tok.start_item(piece.from, open, start);
            seen.bits |= 1 << WorldChild::of(container).index();
            reader.document_from_item((&root, &Tag::item(item, piece.from)), container, &mut seen)
        }
    };
    read.ok()?;
    let container = match piece.to == text.len() {
        true => {
            reader.epilog().ok()?;
            None
        }
        false => {
            let name = reader.tok.open_container()?.key();
            Some(Container::ALL.into_iter().find(|c| Name::new(c.name()).key() == name)?)
        }
    };
    let Reader { mut tok, arena, .. } = reader;
    let end = tok.placed_end();
    Some((arena, Ended { elements: tok.elements(), seen, end, container }))
}

/// Who reads which piece: the calling thread those before `mine`, the second thread those
/// from `theirs` on. Each claims a piece before it reads it, so they never read the same
/// one: the second thread only one from `mine` on, the calling thread only one before
/// `theirs`.
struct Claims {
    mine: usize,
    theirs: usize,
}

/// The calling thread's pieces, from the first on, until it reaches the second thread's,
/// read into one arena: how the reading of each ended. None when one could not be used.
fn read_mine(
    text: &Shared,
    options: &LoadOptions,
    root: &Root,
    pieces: &[Piece],
    claims: &Mutex<Claims>,
) -> Option<(Arena, Vec<Ended>)> {
    let (mut arena, mut ended) = (Arena::new(options.strict, false), Vec::<Ended>::new());
    for (k, piece) in pieces.iter().enumerate() {
        {
            let mut claims = claims.lock().unwrap_or_else(PoisonError::into_inner);
            if k >= claims.theirs {
                break;
            }
            claims.mine = k + 1;
        }
        // Each piece is placed on from where the one before ended.
        let start = ended.last().and_then(|ended| ended.end);
        let Some((read, end)) = read_piece(text, options, (root, piece), arena, start) else {
            // The whole is read again: the second thread starts no more pieces.
            claims.lock().unwrap_or_else(PoisonError::into_inner).mine = usize::MAX;
            return None;
        };
        arena = read;
        ended.push(end);
    }
    Some((arena, ended))
}

/// The second thread: claims and reads the pieces from the last one back until it reaches
/// one the calling thread has claimed, or one it cannot use, sending what it read of each.
fn read_theirs(
    text: &Shared,
    options: &LoadOptions,
    root: &Root,
    pieces: &[Piece],
    claims: &Mutex<Claims>,
    sender: &mpsc::Sender<Option<Done>>,
) {
    for (k, piece) in pieces.iter().enumerate().skip(1).rev() {
        {
            let mut claims = claims.lock().unwrap_or_else(PoisonError::into_inner);
            if k < claims.mine {
                break;
            }
            claims.theirs = claims.theirs.min(k);
        }
        let arena = Arena::new(options.strict, false);
        let done =
            read_piece(text, options, (root, piece), arena, None).map(|(mut arena, ended)| {
                // Appended to the calling thread's and let go: on the thread that read it.
                arena.scene.shrink_to_fit();
                (k, arena, ended)
            });
        let usable = done.is_some();
        if sender.send(done).is_err() || !usable {
            break;
        }
    }
}

/// The arena of the whole text: the calling thread's (`mine`, with how the reading of each
/// of its pieces ended), the second thread's pieces appended to it in order (`theirs`, as
/// they were sent, the last first), when every piece was read to where the next begins in
/// the container that one was read in, no world element was read in two pieces and the
/// limits hold; None otherwise.
fn merged(
    (mut arena, mine): (Arena, Vec<Ended>),
    mut theirs: Vec<Option<Done>>,
    pieces: &[Piece],
    text: &Shared,
    options: &LoadOptions,
) -> Option<Arena> {
    theirs.reverse();
    let theirs = theirs.into_iter().collect::<Option<Vec<Done>>>()?;
    let read = theirs.iter().map(|(k, ..)| *k).eq(mine.len()..pieces.len());
    let ended: Vec<&Ended> = mine.iter().chain(theirs.iter().map(|(.., ended)| ended)).collect();
    if !read || !fit(&ended, pieces, options) {
        return None;
    }
    let seen = ended.iter().fold(0, |seen, ended| seen | ended.seen.bits);
    // The second thread's pieces, placed on from where the calling thread's last one ended.
    let mut start = mine.last().and_then(|ended| ended.end).unwrap_or_default();
    for (_, piece, ended) in theirs {
        arena.append(piece, start);
        start = ended.end.map_or(start, |end| end.after(start));
    }
    end_world(&mut arena, &Seen { bits: seen }).ok()?;
    if let Some(whole) = text.whole() {
        arena.scene.pool_kept_text(|from, to| whole.slice(from, to));
    }
    Some(arena)
}

/// Whether the pieces, read as `ended` says, fit together as one reading of the whole: each
/// begins in the container the one before ended in, none read a world element another read
/// (but the container between them), the last ends the file, and all the elements together
/// keep the limit.
fn fit(ended: &[&Ended], pieces: &[Piece], options: &LoadOptions) -> bool {
    let (mut seen, mut elements) = (0, 0);
    for (k, piece) in pieces.iter().enumerate() {
        let before = k.checked_sub(1).map(|k| ended[k].container);
        if before.is_some_and(|container| container != piece.container) {
            return false;
        }
        let own = piece.container.map_or(0, |container| 1 << WorldChild::of(container).index());
        if seen & ended[k].seen.bits & !own != 0 {
            return false;
        }
        (seen, elements) = (seen | ended[k].seen.bits, elements + ended[k].elements);
    }
    ended.last().is_some_and(|last| last.container.is_none()) && elements <= options.max_elements
}

/// Where the pieces of the text begin: at the first item from every [`PIECE_BYTES`] or so
/// on, looked for near there (see [`item_from`]).
fn boundaries(text: &Shared, buffer: &mut Vec<u8>) -> Vec<Boundary> {
    let len = text.len();
    let pieces = (len / PIECE_BYTES).clamp(2, MAX_PIECES);
    let step = len / pieces;
    let mut boundaries: Vec<Boundary> = Vec::with_capacity(pieces - 1);
    for k in 1..pieces {
        let from = boundaries.last().map_or(0, |&(at, _)| at + 1).max(step * k);
        boundaries.extend(item_from(text, from, step * (k + 1), buffer));
    }
    boundaries
}

/// The first item that begins from `from` on, before `to`, read [`SEARCH_BYTES`] at a time
/// (a file's into `buffer`): a start tag that names a container's item, right after the end
/// tag of another of the same name.
fn item_from(text: &Shared, from: usize, to: usize, buffer: &mut Vec<u8>) -> Option<Boundary> {
    // The longest tag looked at, `</Fixture>`, is looked at again in the next window.
    const OVERLAP: usize = 16;
    let mut at = from;
    while at < to.min(text.len()) {
        let start = at.saturating_sub(SEARCH_BYTES);
        let end = (at + SEARCH_BYTES).min(text.len());
        let bytes = text.bytes(start, end, buffer)?;
        if let Some((i, container)) = item_in(bytes, at - start) {
            return Some((start + i, container));
        }
        at = (end - OVERLAP).max(at + 1);
        if end == text.len() {
            break;
        }
    }
    None
}

/// The first item in `bytes` from `from` on, by its offset in them: see [`item_from`].
fn item_in(bytes: &[u8], from: usize) -> Option<(usize, Container)> {
    memchr::memchr_iter(b'<', &bytes[from..]).map(|i| from + i).find_map(|lt| {
        let container = Container::ALL.into_iter().find(|c| names(&bytes[lt + 1..], c.item()))?;
        let before = &bytes[..lt];
        let end = before.len() - before.iter().rev().take_while(|&&b| is_xml_space_byte(b)).count();
        let before = before[..end].strip_suffix(b">")?;
        let before = before.strip_suffix(container.item().as_bytes())?;
        before.ends_with(b"</").then_some((lt, container))
    })
}

/// Whether `bytes` begin with the name `name`, whole.
fn names(bytes: &[u8], name: &str) -> bool {
    bytes
        .strip_prefix(name.as_bytes())
        .and_then(|after| after.first())
        .is_some_and(|&b| ENDS_NAME[usize::from(b)])
}

#[cfg(test)]
mod tests;
