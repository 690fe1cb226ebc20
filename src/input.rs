//! From the bytes of a file to UTF-8 text, and from offsets in that text back to lines,
//! columns and byte offsets in the file.
#![forbid(unsafe_code)]

use std::borrow::Cow;

use crate::LoadOptions;
use crate::error::{Code, Error, Position};

/// How the file's bytes were encoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Utf8 { bom: bool },
    Utf16 { big_endian: bool },
}

/// The file as UTF-8 text (the byte-order mark removed).
pub struct Decoded<'a> {
    pub text: Cow<'a, str>,
    pub encoding: Encoding,
}

const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// Checks the size limit, detects the encoding, and validates the text: invalid UTF-8 and
/// NUL bytes are errors with their position.
pub fn decode<'a>(bytes: &'a [u8], options: &LoadOptions) -> Result<Decoded<'a>, Error> {
    if bytes.len() as u64 > options.max_input_bytes {
        return Err(too_big(options.max_input_bytes));
    }
    let decoded = match bytes {
        [0xFF, 0xFE, rest @ ..] => decode_utf16(rest, false)?,
        [0xFE, 0xFF, rest @ ..] => decode_utf16(rest, true)?,
        _ => decode_utf8(bytes)?,
    };
    if let Some(at) = decoded.text.find('\0') {
        let position = Locator::new(&decoded).locate(at);
        return Err(Error {
            code: Code::NulByte,
            position,
            message: "the file holds a NUL byte: it is not a text file (or it was truncated \
                      or padded)"
                .into(),
        });
    }
    Ok(decoded)
}

fn decode_utf8(bytes: &[u8]) -> Result<Decoded<'_>, Error> {
    let bom = bytes.starts_with(UTF8_BOM);
    let body = if bom { &bytes[UTF8_BOM.len()..] } else { bytes };
    if looks_like_utf16_without_bom(body) {
        return Err(Error {
            code: Code::UnsupportedEncoding,
            position: Position { line: 1, column: 1, byte_offset: 0 },
            message: "the file looks like UTF-16 without a byte-order mark; save it as UTF-8, \
                      or as UTF-16 with a byte-order mark"
                .into(),
        });
    }
    match std::str::from_utf8(body) {
        Ok(text) => Ok(Decoded { text: Cow::Borrowed(text), encoding: Encoding::Utf8 { bom } }),
        Err(e) => {
            let valid = std::str::from_utf8(&body[..e.valid_up_to()]).unwrap_or_default();
            let decoded = Decoded { text: Cow::Borrowed(valid), encoding: Encoding::Utf8 { bom } };
            Err(Error {
                code: Code::InvalidUtf8,
                position: Locator::new(&decoded).locate(valid.len()),
                message: "the file is not valid UTF-8 here: save it as UTF-8 (a file in a \
                          legacy code page must be converted)"
                    .into(),
            })
        }
    }
}

/// `<` followed or preceded by a zero byte: UTF-16 text that lost its byte-order mark.
fn looks_like_utf16_without_bom(bytes: &[u8]) -> bool {
    matches!(bytes, [b'<', 0, ..] | [0, b'<', ..])
}

fn decode_utf16(bytes: &[u8], big_endian: bool) -> Result<Decoded<'static>, Error> {
    let units = bytes.chunks_exact(2).map(|pair| {
        let pair = [pair[0], pair[1]];
        if big_endian { u16::from_be_bytes(pair) } else { u16::from_le_bytes(pair) }
    });
    let mut text = String::with_capacity(bytes.len() / 2);
    let mut valid = bytes.len() % 2 == 0;
    for unit in char::decode_utf16(units) {
        match unit {
            Ok(c) => text.push(c),
            Err(_) => {
                valid = false;
                break;
            }
        }
    }
    let decoded = Decoded { text: Cow::Owned(text), encoding: Encoding::Utf16 { big_endian } };
    if valid {
        return Ok(decoded);
    }
    Err(Error {
        code: Code::InvalidUtf8,
        position: Locator::new(&decoded).locate(decoded.text.len()),
        message: "the file is not valid UTF-16 here (an unpaired surrogate or an odd number of \
                  bytes)"
            .into(),
    })
}

/// The `limit-exceeded` error of an input larger than `max` bytes.
pub fn too_big(max: u64) -> Error {
    Error {
        code: Code::LimitExceeded,
        position: Position::default(),
        message: format!("the file is larger than the input size limit (max_input_bytes = {max})"),
    }
}

/// Turns offsets in the decoded text into positions in the file. Walks forward from the
/// last position it gave, so locating offsets in increasing order is linear overall.
pub struct Locator<'t> {
    text: &'t str,
    encoding: Encoding,
    offset: usize,
    line: u32,
    line_start: usize,
}

impl<'t> Locator<'t> {
    pub fn new(decoded: &'t Decoded<'_>) -> Locator<'t> {
        Locator {
            text: &decoded.text,
            encoding: decoded.encoding,
            offset: 0,
            line: 1,
            line_start: 0,
        }
    }

    pub fn locate(&mut self, offset: usize) -> Position {
        let offset = offset.min(self.text.len());
        if offset < self.offset {
            (self.offset, self.line, self.line_start) = (0, 1, 0);
        }
        for (i, b) in self.text.as_bytes()[self.offset..offset].iter().enumerate() {
            if *b == b'\n' {
                self.line += 1;
                self.line_start = self.offset + i + 1;
            }
        }
        self.offset = offset;
        let before = self.text.get(self.line_start..offset).unwrap_or_default();
        Position {
            line: self.line,
            column: 1 + saturate(before.chars().count()),
            byte_offset: self.file_offset(offset),
        }
    }

    /// The offset in the file of an offset in the decoded text.
    fn file_offset(&self, offset: usize) -> u64 {
        match self.encoding {
            Encoding::Utf8 { bom } => (offset + if bom { UTF8_BOM.len() } else { 0 }) as u64,
            Encoding::Utf16 { .. } => {
                let units: usize = self.text[..offset].chars().map(char::len_utf16).sum();
                2 + 2 * units as u64
            }
        }
    }
}

fn saturate(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX - 1)
}
