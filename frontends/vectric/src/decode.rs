//! Text encodings of post files: decoding the bytes of a `.pp` file to text
//! (UTF-8, or Windows-1252 when the bytes are not valid UTF-8) and encoding
//! literal output text back to the file's own bytes, so that what a post
//! prints is byte for byte what its file holds.

use std::borrow::Cow;

/// The encoding a post file was read in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    #[default]
    Utf8,
    Windows1252,
}

/// Decodes a post file. Valid UTF-8 stays UTF-8 (a byte-order mark is kept
/// in the text, the parser skips it); anything else is Windows-1252, which
/// maps every byte to one character and back.
pub fn decode(bytes: &[u8]) -> (String, Encoding) {
    match std::str::from_utf8(bytes) {
        Ok(text) => (text.to_string(), Encoding::Utf8),
        Err(_) => {
            let (text, _) = encoding_rs::WINDOWS_1252.decode_without_bom_handling(bytes);
            (text.into_owned(), Encoding::Windows1252)
        }
    }
}

impl Encoding {
    /// The bytes `text` stands for in this encoding. Characters the encoding
    /// cannot hold (none, for text that was decoded with it) become `?`.
    pub fn encode<'a>(self, text: &'a str) -> Cow<'a, [u8]> {
        match self {
            Encoding::Utf8 => Cow::Borrowed(text.as_bytes()),
            Encoding::Windows1252 => {
                if text.is_ascii() {
                    return Cow::Borrowed(text.as_bytes());
                }
                let mut out = Vec::with_capacity(text.len());
                for c in text.chars() {
                    let mut buf = [0u8; 4];
                    let (bytes, _, unmappable) = encoding_rs::WINDOWS_1252.encode(c.encode_utf8(&mut buf));
                    if unmappable {
                        out.push(b'?');
                    } else {
                        out.extend_from_slice(&bytes);
                    }
                }
                Cow::Owned(out)
            }
        }
    }
}
