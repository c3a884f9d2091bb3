//! `postc serve`: the post workbench, a local web application served by
//! postc itself (docs/workbench.md).
//!
//! This module owns the HTTP side: binding (127.0.0.1 unless `--bind`
//! says otherwise), the request checks every request passes before it is
//! answered — its `Host` and `Origin` must be the server's own (DNS
//! rebinding and other sites' pages are refused with 403), its body at
//! most [`BODY_LIMIT`] bytes (413) — and the routing of `/api/*` to
//! [`api`] and of everything else to the embedded front end ([`assets`]).
//! Which files a request may name is [`Roots`]' business.
//!
//! A small pool of threads takes requests from one `tiny_http` server; each
//! request is answered on the thread that took it.

mod api;
mod assets;
mod roots;

use std::io::{Read, Write};
use std::net::{IpAddr, Ipv4Addr, SocketAddr};
use std::path::PathBuf;
use std::sync::Arc;

use postc_ir::{Diagnostic, codes};

use super::{Failed, fail};
pub use roots::Roots;

/// The largest request body the API reads, in bytes (a post, or a dropped
/// toolpath): 32 MiB. A larger one is refused with 413 before it is read.
pub const BODY_LIMIT: u64 = 32 << 20;

/// Threads answering requests.
const WORKERS: usize = 4;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The post to open (its folder is one the workbench may read and save in).
    post: Option<PathBuf>,
    /// The toolpath to post it over (its folder is one the workbench may read).
    toolpath: Option<PathBuf>,
    /// The port to listen on; 0 picks a free one. The URL is printed on standard output.
    #[arg(long, default_value_t = 8765)]
    port: u16,
    /// The address to listen on. Anything but a loopback address lets other machines reach the workbench.
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    bind: IpAddr,
    /// The corpus folder whose posts and toolpaths the pickers offer (read only); by default `corpus` in the current folder, or in the source tree postc was built from.
    #[arg(long, value_name = "DIR")]
    corpus: Option<PathBuf>,
}

/// What every request shares.
pub struct State {
    pub roots: Roots,
    /// The post and toolpath given on the command line.
    pub post: Option<PathBuf>,
    pub toolpath: Option<PathBuf>,
    /// `Host` values that name this server (`127.0.0.1:PORT`, `localhost:PORT`).
    hosts: Vec<String>,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    for (what, path) in [("post", &args.post), ("toolpath", &args.toolpath)] {
        if let Some(p) = path
            && !p.is_file()
        {
            return Err(fail(
                &mut sources,
                Diagnostic::error(codes::IO001, format!("the {what}: {}", super::missing(p))),
            ));
        }
    }
    let corpus = args.corpus.clone().or_else(default_corpus);
    let dropped = super::outputs::TempDir::new("postc-serve-").map_err(|e| {
        fail(&mut sources, Diagnostic::error(codes::IO003, format!("cannot make a folder for dropped files: {e}")))
    })?;
    let roots = Roots::new(args.post.as_deref(), args.toolpath.as_deref(), corpus.as_deref(), dropped.path());
    let server = tiny_http::Server::http(SocketAddr::new(args.bind, args.port)).map_err(|e| {
        fail(
            &mut sources,
            Diagnostic::error(codes::IO003, format!("cannot listen on {}:{}: {e}", args.bind, args.port))
                .help("choose another port with `--port N` (0 picks a free one)"),
        )
    })?;
    let port = server.server_addr().to_ip().map_or(args.port, |a| a.port());
    let mut hosts = vec![format!("{}:{port}", host_name(args.bind))];
    if args.bind.is_loopback() || args.bind.is_unspecified() {
        hosts.push(format!("localhost:{port}"));
    } else {
        eprintln!(
            "postc serve: warning: listening on {}, which other machines may reach; the workbench reads and writes your files",
            args.bind
        );
    }
    let state = Arc::new(State { roots, post: args.post, toolpath: args.toolpath, hosts });
    println!("postc serve: http://{}/", state.hosts[0]);
    let _ = std::io::stdout().flush();
    let server = Arc::new(server);
    let workers: Vec<_> = (0..WORKERS)
        .map(|_| {
            let server = Arc::clone(&server);
            let state = Arc::clone(&state);
            std::thread::spawn(move || {
                while let Ok(request) = server.recv() {
                    answer(&state, request);
                }
            })
        })
        .collect();
    for w in workers {
        let _ = w.join();
    }
    drop(dropped);
    Ok(())
}

/// `corpus` in the current folder, else in the source tree of this build.
fn default_corpus() -> Option<PathBuf> {
    [PathBuf::from("corpus"), PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/corpus"))]
        .into_iter()
        .find(|p| p.join("toolpaths").is_dir())
}

/// An address as a URL's host.
fn host_name(ip: IpAddr) -> String {
    match ip {
        IpAddr::V4(v4) if v4 == Ipv4Addr::UNSPECIFIED => "127.0.0.1".to_string(),
        IpAddr::V4(v4) => v4.to_string(),
        IpAddr::V6(v6) => format!("[{v6}]"),
    }
}

/// A response: status, content type, body, and whether the body is gzip.
pub struct Reply {
    pub status: u16,
    pub content_type: &'static str,
    pub body: Vec<u8>,
    pub gzip: bool,
}

impl Reply {
    pub fn json(status: u16, value: &serde_json::Value) -> Reply {
        Reply {
            status,
            content_type: "application/json; charset=utf-8",
            body: serde_json::to_vec(value).unwrap_or_default(),
            gzip: false,
        }
    }

    /// An error: `{"error": message}`.
    pub fn error(status: u16, message: impl Into<String>) -> Reply {
        Reply::json(status, &serde_json::json!({ "error": message.into() }))
    }
}

/// Checks and answers one request.
fn answer(state: &State, mut request: tiny_http::Request) {
    let reply = match refusal(state, &request) {
        Some(r) => r,
        None => route(state, &mut request),
    };
    let mut response = tiny_http::Response::from_data(reply.body).with_status_code(reply.status);
    let mut headers = vec![
        ("Content-Type", reply.content_type),
        ("Cache-Control", "no-store"),
        ("X-Content-Type-Options", "nosniff"),
        ("X-Frame-Options", "DENY"),
        (
            "Content-Security-Policy",
            "default-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; frame-ancestors 'none'",
        ),
    ];
    if reply.gzip {
        headers.push(("Content-Encoding", "gzip"));
    }
    for (name, value) in headers {
        if let Ok(h) = tiny_http::Header::from_bytes(name.as_bytes(), value.as_bytes()) {
            response.add_header(h);
        }
    }
    let _ = request.respond(response);
}

/// Why a request is refused before it is read: 403 for a `Host` that is
/// not this server's (DNS rebinding) or an `Origin` of another site, 413
/// for a body over [`BODY_LIMIT`].
fn refusal(state: &State, request: &tiny_http::Request) -> Option<Reply> {
    let header = |name: &str| {
        request
            .headers()
            .iter()
            .find(|h| h.field.as_str().as_str().eq_ignore_ascii_case(name))
            .map(|h| h.value.as_str())
    };
    match header("Host") {
        Some(host) if state.hosts.iter().any(|h| h.eq_ignore_ascii_case(host)) => {}
        Some(host) => return Some(Reply::error(403, format!("the Host `{host}` is not this server's"))),
        None => return Some(Reply::error(403, "the request has no Host header")),
    }
    if let Some(origin) = header("Origin")
        && !state.hosts.iter().any(|h| origin.eq_ignore_ascii_case(&format!("http://{h}")))
    {
        return Some(Reply::error(
            403,
            format!("requests from `{origin}` are refused: only this server's own page may call it"),
        ));
    }
    if request.body_length().is_some_and(|n| n as u64 > BODY_LIMIT) {
        return Some(Reply::error(413, format!("the request body is over {} MiB", BODY_LIMIT >> 20)));
    }
    None
}

fn route(state: &State, request: &mut tiny_http::Request) -> Reply {
    let url = request.url().split(['?', '#']).next().unwrap_or("/").to_string();
    let method = request.method().clone();
    match (method, url.strip_prefix("/api/")) {
        (tiny_http::Method::Post, Some(endpoint)) => {
            let mut body = Vec::new();
            // A chunked body has no length to check first: read one byte past the limit.
            if let Err(e) = request.as_reader().take(BODY_LIMIT + 1).read_to_end(&mut body) {
                return Reply::error(400, format!("cannot read the request: {e}"));
            }
            if body.len() as u64 > BODY_LIMIT {
                return Reply::error(413, format!("the request body is over {} MiB", BODY_LIMIT >> 20));
            }
            let value: serde_json::Value = match serde_json::from_slice(&body) {
                Ok(v) => v,
                Err(e) => return Reply::error(400, format!("the request is not JSON: {e}")),
            };
            api::handle(state, endpoint, value)
        }
        (_, Some(_)) => Reply::error(405, "the API takes POST requests with a JSON body"),
        (tiny_http::Method::Get | tiny_http::Method::Head, None) => assets::get(&url),
        _ => Reply::error(405, "only GET"),
    }
}
