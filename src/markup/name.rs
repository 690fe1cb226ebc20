//! Element names. Nearly every name has at most 16 bytes and is kept in one 128-bit
//! number, so that reading it, matching its end tag and looking it up among an object's
//! known elements take a few integer operations instead of byte loops.

/// The most bytes a name kept in one number has.
pub(crate) const SHORT: usize = 16;

/// An element name.
#[derive(Clone)]
pub(crate) enum Name {
    /// A name of at most [`SHORT`] bytes, none of them a control character or a space:
    /// how many, and its bytes in order, then zeros.
    Short(u8, [u8; SHORT]),
    Long(Box<str>),
}

impl Name {
    pub fn new(name: &str) -> Name {
        let mut short = [0; SHORT];
        match short.get_mut(..name.len()) {
            Some(bytes) if name.bytes().all(|b| b > b' ') => {
                bytes.copy_from_slice(name.as_bytes());
                Name::Short(name.len() as u8, short)
            }
            _ => Name::Long(name.into()),
        }
    }

    /// The name made of the first `len` bytes of `head`, which a caller found to be one.
    #[inline]
    pub fn from_head(head: &[u8; SHORT], len: usize) -> Name {
        let bytes = u128::from_le_bytes(*head) & low_bytes(len);
        Name::Short(len as u8, bytes.to_le_bytes())
    }

    #[inline]
    pub fn len(&self) -> usize {
        match self {
            Name::Short(len, _) => usize::from(*len),
            Name::Long(name) => name.len(),
        }
    }

    pub fn as_bytes(&self) -> &[u8] {
        match self {
            Name::Short(len, bytes) => &bytes[..usize::from(*len)],
            Name::Long(name) => name.as_bytes(),
        }
    }

    pub fn as_str(&self) -> &str {
        // Whole names are copied, so the bytes are text.
        std::str::from_utf8(self.as_bytes()).unwrap_or_default()
    }

    /// The name with ASCII letters folded to lower case; 0 for a long name, which no
    /// known element has.
    #[inline]
    pub fn key(&self) -> u128 {
        match self {
            Name::Short(len, bytes) => fold(u128::from_le_bytes(*bytes), usize::from(*len)),
            Name::Long(_) => 0,
        }
    }

    /// How long this name's usual end tag `</Name>` is, when `text` starts with it. A short
    /// name of at most 13 bytes has its end tag in 16 bytes: one comparison of a number.
    #[inline(always)]
    pub fn end_tag_len(&self, text: &[u8]) -> Option<usize> {
        if let (Name::Short(len @ ..=13, bytes), Some(head)) = (self, text.first_chunk::<SHORT>()) {
            let len = usize::from(*len);
            let end_tag = u128::from_le_bytes(*bytes) << 16 | END_TAGS[len];
            return (u128::from_le_bytes(*head) & low_bytes(len + 3) == end_tag).then_some(len + 3);
        }
        match text {
            [b'<', b'/', after @ ..] if self.ends(after) => Some(3 + self.len()),
            _ => None,
        }
    }

    /// Whether `after_slash`, the text after `</`, is this name and `>`: the usual end tag.
    #[inline]
    pub fn ends(&self, after_slash: &[u8]) -> bool {
        let len = self.len();
        match (self, after_slash.first_chunk::<SHORT>()) {
            (Name::Short(_, bytes), Some(head)) => {
                u128::from_le_bytes(*head) & low_bytes(len) == u128::from_le_bytes(*bytes)
                    && after_slash.get(len) == Some(&b'>')
            }
            _ => after_slash.get(len) == Some(&b'>') && after_slash.starts_with(self.as_bytes()),
        }
    }
}

impl std::fmt::Display for Name {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The key of a known element's name, as [`Name::key`] gives it for that name in any case.
/// Known names are ASCII letters and digits, at most [`SHORT`] of them.
#[inline]
pub(crate) const fn key(name: &str) -> u128 {
    let bytes = name.as_bytes();
    assert!(bytes.len() <= SHORT, "a known element name has at most 16 bytes");
    let mut raw = 0u128;
    let mut i = bytes.len();
    while i > 0 {
        i -= 1;
        assert!(bytes[i].is_ascii_alphanumeric(), "known element names are letters and digits");
        raw = raw << 8 | bytes[i] as u128;
    }
    fold(raw, bytes.len())
}

/// Sets bit 5 of each of the first `len` bytes: that makes ASCII letters lower case and
/// leaves digits as they are. Another byte of a short name could only meet a letter or a
/// digit of a known name this way if it were a control character, which short names
/// never hold, or a byte of 0x80 or above, which a known name never has.
const fn fold(bytes: u128, len: usize) -> u128 {
    bytes | (u128::from_le_bytes([0x20; SHORT]) & low_bytes(len))
}

/// A mask of the first `len` bytes (`len` at most [`SHORT`]).
const fn low_bytes(len: usize) -> u128 {
    LOW_BYTES[len]
}

/// The end tag of a name of each length up to 13 without the name: `</`, then zeros where
/// the name goes, then `>`.
const END_TAGS: [u128; SHORT - 2] = {
    let mut tags = [0; SHORT - 2];
    let mut len = 0;
    while len < SHORT - 2 {
        tags[len] = (b'<' as u128) | (b'/' as u128) << 8 | (b'>' as u128) << (8 * (len + 2));
        len += 1;
    }
    tags
};

const LOW_BYTES: [u128; SHORT + 1] = {
    let mut masks = [u128::MAX; SHORT + 1];
    let mut len = 0;
    while len < SHORT {
        masks[len] = (1 << (8 * len)) - 1;
        len += 1;
    }
    masks
};

#[cfg(test)]
mod tests;
