//! `postc lsp`: the language server on stdio (`docs/editors.md`).
//!
//! The server itself (`postc_lsp::serve`) talks over an in-memory
//! connection; this module carries its messages to and from stdin and
//! stdout with the base protocol's `Content-Length` framing. A frame that
//! does not read (a bad header, a body that is not JSON, JSON that is not
//! a JSON-RPC message) is answered with a JSON-RPC error (-32700 parse
//! error, -32600 invalid request) and the server goes on with the next
//! frame, as the JSON-RPC 2.0 specification asks.

use std::io::{self, BufRead, Read, Write};
use std::sync::{Arc, Mutex};

use lsp_server::{Connection, Message};

use super::Failed;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Accepted for editors that pass it (VS Code clients do); stdio is the only transport.
    #[arg(long)]
    stdio: bool,
}

pub fn run(_args: Args) -> Result<(), Failed> {
    serve_stdio().map_err(|e| {
        eprintln!("postc lsp: {e}");
        Failed
    })
}

/// JSON-RPC's parse error: the body is not JSON.
const PARSE_ERROR: i32 = -32700;
/// JSON-RPC's invalid request: JSON, but not a request, response or notification.
const INVALID_REQUEST: i32 = -32600;

/// A frame read from the client.
enum Frame {
    Message(Message),
    /// What is wrong with a frame, and the id of the request it held when
    /// that could be read.
    Bad {
        code: i32,
        message: String,
        id: serde_json::Value,
    },
    End,
}

/// The server on stdin/stdout until the client says `exit` or closes
/// stdin, reading the files documents name from disk.
fn serve_stdio() -> Result<(), Box<dyn std::error::Error + Send + Sync>> {
    let (server, client) = Connection::memory();
    let stdout = Arc::new(Mutex::new(io::stdout()));
    let writer = {
        let stdout = Arc::clone(&stdout);
        let receiver = client.receiver;
        std::thread::Builder::new().name("postc-lsp-writer".into()).spawn(move || -> io::Result<()> {
            for message in receiver {
                let mut out = stdout.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                message.write(&mut *out)?;
            }
            Ok(())
        })?
    };
    let sender = client.sender;
    let reader = std::thread::Builder::new().name("postc-lsp-reader".into()).spawn(move || {
        let stdin = io::stdin();
        let mut input = Resync { back: Vec::new(), inner: stdin.lock() };
        loop {
            match read_frame(&mut input) {
                Frame::End => break,
                Frame::Message(message) => {
                    let exit = matches!(&message, Message::Notification(n) if n.method == "exit");
                    if sender.send(message).is_err() || exit {
                        break;
                    }
                }
                Frame::Bad { code, message, id } => {
                    let answer = serde_json::json!({
                        "jsonrpc": "2.0",
                        "id": id,
                        "error": { "code": code, "message": message },
                    });
                    let mut out = stdout.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
                    if write_frame(&mut *out, &answer.to_string()).is_err() {
                        break;
                    }
                }
            }
        }
    })?;
    let served = postc_lsp::serve(&server, Arc::new(postc_report::FsLoader));
    drop(server);
    // The writer ends when the server's sender is gone; the reader ends
    // at `exit` or at the end of stdin (it is not waited for: after
    // `shutdown` a client may keep stdin open).
    let written = writer.join().map_err(|_| "the writer thread panicked")?;
    drop(reader);
    served?;
    written?;
    Ok(())
}

/// The client's bytes, with room to read again what a frame's body held
/// of the frames after it (a `Content-Length` longer than its body).
struct Resync<R> {
    /// Bytes to read again, last first.
    back: Vec<u8>,
    inner: R,
}

impl<R: BufRead> Resync<R> {
    /// Reads up to and including `\n`, as [`BufRead::read_until`].
    fn read_line(&mut self, line: &mut Vec<u8>) -> io::Result<usize> {
        let mut n = 0;
        while let Some(b) = self.back.pop() {
            line.push(b);
            n += 1;
            if b == b'\n' {
                return Ok(n);
            }
        }
        Ok(n + self.inner.read_until(b'\n', line)?)
    }

    /// Reads `length` bytes, or fewer when the input ends.
    fn read_body(&mut self, length: usize) -> io::Result<Vec<u8>> {
        let mut body = Vec::with_capacity(length.min(1 << 20));
        while body.len() < length
            && let Some(b) = self.back.pop()
        {
            body.push(b);
        }
        let rest = (length - body.len()) as u64;
        self.inner.by_ref().take(rest).read_to_end(&mut body)?;
        Ok(body)
    }

    /// Makes `bytes` the next ones read.
    fn unread(&mut self, bytes: &[u8]) {
        self.back.extend(bytes.iter().rev());
    }
}

/// Where a frame header starts inside `body`: the whole `Content-Length:`,
/// or at the end of the body the start of it (a length that took the first
/// bytes of the next frame). At the body's first byte too: a frame sent
/// with no body has the next frame for one. Reading again from there ends:
/// the frame's own header is read.
fn header_inside(body: &[u8]) -> Option<usize> {
    const HEADER: &[u8] = b"content-length:";
    (0..body.len()).find(|&i| {
        let n = body[i..].len().min(HEADER.len());
        body[i..i + n].eq_ignore_ascii_case(&HEADER[..n])
    })
}

/// Reads one frame: headers up to an empty line, then `Content-Length`
/// bytes of JSON. A body that is not JSON and holds the start of another
/// frame (its length was too long) gives those bytes back to be read again.
fn read_frame<R: BufRead>(input: &mut Resync<R>) -> Frame {
    let mut length: Option<Result<usize, String>> = None;
    let mut headers = false;
    let mut line = Vec::new();
    loop {
        line.clear();
        match input.read_line(&mut line) {
            Ok(0) | Err(_) => return Frame::End,
            Ok(_) => {}
        }
        let text = String::from_utf8_lossy(&line);
        let text = text.trim_end_matches(['\r', '\n']);
        if text.is_empty() {
            // A blank line before any header is noise between frames.
            if !headers {
                continue;
            }
            break;
        }
        headers = true;
        // A frame whose length was short leaves the rest of its body
        // before the next header (`}Content-Length: 45`), and a frame cut
        // inside its header leaves that header's start before it
        // (`Content-Length: 1...Content-Length: 45`): the last header on
        // the line is the frame's, and the frames after it read again.
        let text = match text.to_ascii_lowercase().rfind("content-length:") {
            Some(at) => &text[at..],
            None => text,
        };
        if let Some((name, value)) = text.split_once(':')
            && name.trim().eq_ignore_ascii_case("content-length")
        {
            length = Some(
                value.trim().parse::<usize>().map_err(|_| format!("bad Content-Length header `{}`", value.trim())),
            );
        } else if length.is_none() && !text.contains(':') {
            length = Some(Err(format!("a header line must be `Name: value`, not `{}`", text.trim())));
        }
    }
    let length = match length {
        Some(Ok(n)) => n,
        Some(Err(message)) => return bad(PARSE_ERROR, message),
        None => return bad(PARSE_ERROR, "the frame has no Content-Length header".into()),
    };
    let Ok(body) = input.read_body(length) else { return Frame::End };
    let value: serde_json::Value = match serde_json::from_slice(&body) {
        Ok(v) => v,
        Err(e) => {
            if let Some(at) = header_inside(&body) {
                input.unread(&body[at..]);
            } else if body.len() < length {
                return Frame::End;
            }
            return bad(PARSE_ERROR, format!("the message is not JSON: {e}"));
        }
    };
    let id = value.get("id").cloned().unwrap_or(serde_json::Value::Null);
    match serde_json::from_value::<Message>(value) {
        Ok(message) => Frame::Message(message),
        Err(e) => Frame::Bad {
            code: INVALID_REQUEST,
            message: format!("the message is not a JSON-RPC request, response or notification: {e}"),
            id,
        },
    }
}

fn bad(code: i32, message: String) -> Frame {
    Frame::Bad { code, message, id: serde_json::Value::Null }
}

fn write_frame(out: &mut impl Write, body: &str) -> io::Result<()> {
    write!(out, "Content-Length: {}\r\n\r\n{body}", body.len())?;
    out.flush()
}
