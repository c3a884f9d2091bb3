//! How a post file is stored (UTF-8 or one byte per character, a BOM,
//! CR LF line endings), so that a command that rewrites it (`check --fix`,
//! the workbench's Save) reads it as text whose lines end with `\n` and
//! writes it back the same way: the bytes it does not change stay as they
//! were.

/// How a file's text is stored, to write it back the same way.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stored {
    pub utf8: bool,
    pub bom: bool,
    pub crlf: bool,
}

const BOM: &[u8] = b"\xEF\xBB\xBF";

/// A file's text as the editor shows it (lines end with `\n`), and how it is stored.
pub fn decode(bytes: &[u8]) -> (String, Stored) {
    let (bom, body) = match bytes.strip_prefix(BOM) {
        Some(rest) => (true, rest),
        None => (false, bytes),
    };
    let crlf = body.windows(2).any(|w| w == b"\r\n");
    let (text, utf8) = match std::str::from_utf8(body) {
        Ok(t) => (t.to_string(), true),
        // Byte for character, as `postc check --fix` reads such a file.
        Err(_) => (body.iter().map(|&b| char::from(b)).collect(), false),
    };
    let text = if crlf { text.replace("\r\n", "\n") } else { text };
    (text, Stored { utf8, bom, crlf })
}

/// The editor's text stored as `how`; a character the file's encoding
/// cannot hold is an error naming its line.
pub fn encode(text: &str, how: Stored) -> Result<Vec<u8>, String> {
    let text = if how.crlf { text.replace("\r\n", "\n").replace('\n', "\r\n") } else { text.to_string() };
    let mut out = Vec::with_capacity(text.len() + 3);
    if how.bom {
        out.extend_from_slice(BOM);
    }
    if how.utf8 {
        out.extend_from_slice(text.as_bytes());
        return Ok(out);
    }
    for (i, c) in text.char_indices() {
        match u8::try_from(u32::from(c)) {
            Ok(b) => out.push(b),
            Err(_) => {
                let line = text[..i].matches('\n').count() + 1;
                return Err(format!(
                    "line {line}: `{c}` cannot be written in this file's encoding (one byte per character); nothing was saved"
                ));
            }
        }
    }
    Ok(out)
}
