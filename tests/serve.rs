//! `postc serve`, the post workbench (docs/workbench.md): each test starts
//! the real binary on a free port (`--port 0`, the URL read from its
//! standard output) and speaks raw HTTP to it; the browser test drives the
//! page with Playwright and Debian's Chromium (`web/e2e/workbench.mjs`).

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use serde_json::{Value, json};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A running `postc serve`, stopped when dropped.
struct Server {
    child: Child,
    /// `127.0.0.1:PORT`.
    host: String,
}

impl Server {
    fn start(args: &[&Path]) -> Server {
        Server::start_in(args, &std::env::temp_dir())
    }

    /// With `tmp` as the system's temporary folder (`TMPDIR`).
    fn start_in(args: &[&Path], tmp: &Path) -> Server {
        let mut child = Command::new(env!("CARGO_BIN_EXE_postc"))
            .current_dir(root())
            .arg("serve")
            .args(args)
            .args(["--port", "0"])
            .env("TMPDIR", tmp)
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).unwrap();
        let url = line.trim().strip_prefix("postc serve: ").unwrap_or_else(|| panic!("no URL printed: {line:?}"));
        let host = url.trim_start_matches("http://").trim_end_matches('/').to_string();
        Server { child, host }
    }

    fn url(&self) -> String {
        format!("http://{}/", self.host)
    }

    /// Sends raw request bytes; the status and the body.
    fn raw(&self, request: &[u8]) -> (u16, Vec<u8>, String) {
        let mut stream = TcpStream::connect(&self.host).unwrap();
        stream.write_all(request).unwrap();
        let mut response = Vec::new();
        let _ = stream.read_to_end(&mut response);
        let split = response.windows(4).position(|w| w == b"\r\n\r\n").expect("a response head");
        let head = String::from_utf8_lossy(&response[..split]).into_owned();
        let status = head.split(' ').nth(1).and_then(|s| s.parse().ok()).unwrap_or(0);
        let body = &response[split + 4..];
        let body = if head.to_ascii_lowercase().contains("transfer-encoding: chunked") {
            dechunk(body)
        } else {
            body.to_vec()
        };
        (status, body, head)
    }

    /// POSTs JSON to `/api/{endpoint}` with extra header lines.
    fn api_with(&self, endpoint: &str, body: &Value, headers: &str) -> (u16, Value) {
        let body = serde_json::to_vec(body).unwrap();
        let mut request = format!(
            "POST /api/{endpoint} HTTP/1.1\r\nHost: {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n{headers}\r\n",
            self.host,
            body.len()
        )
        .into_bytes();
        request.extend_from_slice(&body);
        let (status, body, _) = self.raw(&request);
        (status, serde_json::from_slice(&body).unwrap_or(Value::Null))
    }

    /// POSTs JSON as the workbench's own page does (its Origin).
    fn api(&self, endpoint: &str, body: &Value) -> (u16, Value) {
        self.api_with(endpoint, body, &format!("Origin: http://{}\r\n", self.host))
    }
}

/// A chunked body's bytes.
fn dechunk(mut body: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    while let Some(end) = body.windows(2).position(|w| w == b"\r\n") {
        let size = usize::from_str_radix(String::from_utf8_lossy(&body[..end]).trim(), 16).unwrap_or(0);
        if size == 0 {
            break;
        }
        let start = end + 2;
        out.extend_from_slice(&body[start..(start + size).min(body.len())]);
        body = &body[(start + size + 2).min(body.len())..];
    }
    out
}

impl Drop for Server {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// A folder with a copy of a corpus post (saving must not touch the corpus).
fn workspace(post: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let source = root().join("corpus/posts").join(post);
    let copy = dir.path().join(source.file_name().unwrap());
    std::fs::copy(&source, &copy).unwrap();
    (dir, copy)
}

fn seed_job() -> PathBuf {
    root().join("corpus/toolpaths/seed_job.ron")
}

#[test]
fn serves_the_page_and_its_script_gzip() {
    let server = Server::start(&[]);
    let host = &server.host;
    let (status, body, _) =
        server.raw(format!("GET / HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n").as_bytes());
    assert_eq!(status, 200);
    assert!(String::from_utf8_lossy(&body).contains("app.js"), "the page loads the script");
    let (status, body, head) =
        server.raw(format!("GET /app.js HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n").as_bytes());
    assert_eq!(status, 200);
    assert!(head.to_ascii_lowercase().contains("content-encoding: gzip"), "{head}");
    assert_eq!(&body[..2], &[0x1f, 0x8b], "a gzip stream");
}

#[test]
fn posts_the_editor_text_with_trace_findings_and_backplot() {
    let (_dir, post) = workspace("vectric/gcode_mm.pp");
    let server = Server::start(&[&post, &seed_job()]);
    let (status, opened) = server.api("open", &json!({ "path": post }));
    assert_eq!(status, 200, "{opened}");
    let text = opened["text"].as_str().unwrap().to_string();
    let request = json!({
        "path": post, "text": text,
        "toolpath": { "kind": "file", "path": seed_job() },
    });
    let (status, out) = server.api("post", &request);
    assert_eq!(status, 200, "{out}");
    let program = out["program"].as_str().unwrap();
    // What `postc post` writes for the same post and toolpath.
    let cli = Command::new(env!("CARGO_BIN_EXE_postc")).arg("post").arg(&post).arg(seed_job()).output().unwrap();
    assert!(cli.status.success());
    let cli_text = String::from_utf8_lossy(&cli.stdout);
    let strip_date = |s: &str| s.lines().filter(|l| !l.contains("made by postc")).collect::<Vec<_>>().join("\n");
    assert_eq!(strip_date(program), strip_date(&cli_text));
    // Every line of the program has its post line, and each is a line of the post.
    let post_lines = out["trace"]["post"].as_array().unwrap();
    assert_eq!(post_lines.len(), program.lines().count());
    let lines_of_post = text.lines().count() as u64;
    assert!(post_lines.iter().all(|l| (1..=lines_of_post).contains(&l.as_u64().unwrap())), "{post_lines:?}");
    // The first G1 line was written by a FEED_MOVE line of the post.
    let g1 = program.lines().position(|l| l.starts_with("G1")).unwrap();
    let writer = text.lines().nth(post_lines[g1].as_u64().unwrap() as usize - 1).unwrap();
    assert!(writer.contains("G1") || writer.contains("[F]") || writer.contains("[X]"), "{writer}");
    assert!(out["svg"].as_str().unwrap().starts_with("<svg"));
    assert_eq!(out["verify"]["errors"], 0, "{}", out["verify"]);
    assert!(out["diagnostics"].as_array().unwrap().is_empty(), "{}", out["diagnostics"]);

    // Hover: the language server's text for a label.
    let at = text.find("[X]").unwrap() + 1;
    let (_, hover) = server.api("hover", &json!({ "path": post, "text": text, "offset": at }));
    assert!(hover["markdown"].as_str().unwrap().contains("X_POSITION"), "{hover}");
    // Conversion, as `postc convert --to fusion` writes it.
    let (_, converted) = server.api("convert", &json!({ "path": post, "text": text, "to": "fusion" }));
    let cli =
        Command::new(env!("CARGO_BIN_EXE_postc")).arg("convert").arg(&post).args(["--to", "fusion"]).output().unwrap();
    assert_eq!(converted["text"].as_str().unwrap(), String::from_utf8_lossy(&cli.stdout));

    // A misspelt section is reported with its code and place.
    let broken = text.replacen("begin HEADER", "begin HEADR", 1);
    let (_, out) = server.api("post", &json!({ "path": post, "text": broken, "toolpath": request["toolpath"] }));
    let d = &out["diagnostics"][0];
    assert_eq!(d["code"], "PP017", "{out}");
    let from = d["from"].as_u64().unwrap() as usize;
    assert_eq!(&broken[from..d["to"].as_u64().unwrap() as usize], "HEADR");
    // Its quick fix.
    let (_, fixes) = server.api("fixes", &json!({ "path": post, "text": broken, "from": from, "to": from }));
    assert_eq!(fixes[0]["insert"], "HEADER", "{fixes}");
}

#[test]
fn posts_a_dropped_toolpath() {
    let (_dir, post) = workspace("vectric/gcode_mm.pp");
    let server = Server::start(&[&post]);
    let job = std::fs::read_to_string(seed_job()).unwrap();
    // Only the name is kept, in the workbench's own folder.
    let (status, kept) = server.api("drop", &json!({ "name": "../../elsewhere/dropped.ron", "text": job }));
    assert_eq!(status, 200, "{kept}");
    let path = kept["path"].as_str().unwrap();
    assert!(path.ends_with("/dropped.ron") && !path.contains(".."), "{path}");
    let text = std::fs::read_to_string(&post).unwrap();
    let (status, out) =
        server.api("post", &json!({ "path": post, "text": text, "toolpath": { "kind": "file", "path": path } }));
    assert_eq!(status, 200, "{out}");
    assert_eq!(out["verify"]["errors"], 0, "{out}");
    assert!(out["program"].as_str().unwrap().contains("G2"), "{out}");
    // What is not a toolpath is refused.
    assert_eq!(server.api("drop", &json!({ "name": "notes.txt", "text": "hello" })).0, 422);
}

/// Interrupted, the workbench leaves no folder of dropped files behind
/// (docs/outputs.md: temporary files and folders are removed on SIGINT).
#[cfg(unix)]
#[test]
fn an_interrupt_removes_the_folder_of_dropped_files() {
    let tmp = tempfile::tempdir().unwrap();
    let mut server = Server::start_in(&[], tmp.path());
    let made: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().flatten().map(|e| e.file_name()).collect();
    assert_eq!(made.len(), 1, "the folder of dropped files: {made:?}");
    let killed = Command::new("kill").args(["-INT", &server.child.id().to_string()]).status().unwrap();
    assert!(killed.success());
    let status = server.child.wait().unwrap();
    assert_eq!(status.code(), Some(130), "{status:?}");
    let left: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().flatten().map(|e| e.file_name()).collect();
    assert!(left.is_empty(), "left behind: {left:?}");
}

#[test]
fn refuses_other_origins_and_hosts() {
    let server = Server::start(&[]);
    let (status, body) = server.api_with("toolpaths", &json!({}), "Origin: http://evil.example\r\n");
    assert_eq!(status, 403, "{body}");
    // DNS rebinding: the page's name is not this server's.
    let body = b"{}";
    let request = format!(
        "POST /api/toolpaths HTTP/1.1\r\nHost: evil.example:{}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{}",
        server.host.rsplit(':').next().unwrap(),
        body.len(),
        String::from_utf8_lossy(body)
    );
    let (status, _, _) = server.raw(request.as_bytes());
    assert_eq!(status, 403);
    let (status, _, _) = server.raw(b"GET / HTTP/1.1\r\nHost: attacker.test\r\nConnection: close\r\n\r\n");
    assert_eq!(status, 403);
    // Without an Origin (curl, the tests) and with its own, it answers.
    assert_eq!(server.api_with("toolpaths", &json!({}), "").0, 200);
    assert_eq!(server.api("toolpaths", &json!({})).0, 200);
}

#[test]
fn refuses_paths_outside_its_folders() {
    let (dir, post) = workspace("vectric/gcode_mm.pp");
    let server = Server::start(&[&post, &seed_job()]);
    let outside = tempfile::tempdir().unwrap();
    let secret = outside.path().join("secret.pp");
    std::fs::write(&secret, "x").unwrap();
    // Reading, by a plain path and by `..` out of an allowed folder.
    assert_eq!(server.api("open", &json!({ "path": secret })).0, 403);
    let escape =
        dir.path().join("..").join(outside.path().strip_prefix("/tmp").unwrap_or(outside.path())).join("secret.pp");
    assert_eq!(server.api("open", &json!({ "path": escape })).0, 403);
    assert_eq!(server.api("open", &json!({ "path": "/etc/passwd" })).0, 403);
    // A link inside an allowed folder to a file outside it.
    #[cfg(unix)]
    {
        let link = dir.path().join("link.pp");
        std::os::unix::fs::symlink(&secret, &link).unwrap();
        assert_eq!(server.api("open", &json!({ "path": link })).0, 403);
    }
    // A toolpath outside.
    let text = std::fs::read_to_string(&post).unwrap();
    let (status, _) = server.api(
        "post",
        &json!({ "path": post, "text": text, "toolpath": { "kind": "file", "path": outside.path().join("t.ron") } }),
    );
    assert_eq!(status, 403);
    // Saving: outside, and in the corpus (readable, not writable).
    assert_eq!(server.api("save", &json!({ "path": secret, "text": "y" })).0, 403);
    assert_eq!(std::fs::read_to_string(&secret).unwrap(), "x");
    let corpus_post = root().join("corpus/posts/vectric/gcode_mm.pp");
    assert_eq!(server.api("open", &json!({ "path": corpus_post })).0, 200);
    assert_eq!(server.api("save", &json!({ "path": corpus_post, "text": "y" })).0, 403);
    // Inside: allowed.
    assert_eq!(server.api("save", &json!({ "path": post, "text": text })).0, 200);
}

#[test]
fn refuses_bodies_over_the_limit() {
    let server = Server::start(&[]);
    // The head alone says the size: refused before the body is sent.
    let request = format!(
        "POST /api/check HTTP/1.1\r\nHost: {}\r\nContent-Type: application/json\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
        server.host,
        (32u64 << 20) + 1
    );
    let (status, body, _) = server.raw(request.as_bytes());
    assert_eq!(status, 413, "{}", String::from_utf8_lossy(&body));
    // A chunked body that grows past it.
    let mut request = format!(
        "POST /api/check HTTP/1.1\r\nHost: {}\r\nTransfer-Encoding: chunked\r\nConnection: close\r\n\r\n",
        server.host
    )
    .into_bytes();
    let chunk = vec![b' '; 1 << 20];
    for _ in 0..33 {
        request.extend_from_slice(format!("{:x}\r\n", chunk.len()).as_bytes());
        request.extend_from_slice(&chunk);
        request.extend_from_slice(b"\r\n");
    }
    request.extend_from_slice(b"0\r\n\r\n");
    let (status, _, _) = server.raw(&request);
    assert_eq!(status, 413);
}

#[test]
fn saves_in_the_files_encoding_and_line_endings() {
    let dir = tempfile::tempdir().unwrap();
    let post = dir.path().join("latin.pp");
    let original = std::fs::read(root().join("corpus/posts/vectric/gcode_mm.pp")).unwrap();
    // Windows line endings and a Latin-1 `°` in a comment.
    let mut bytes = b"+ Fr\xe4se 90\xb0\r\n".to_vec();
    bytes.extend(String::from_utf8(original).unwrap().replace('\n', "\r\n").into_bytes());
    std::fs::write(&post, &bytes).unwrap();
    let server = Server::start(&[&post]);
    let (status, opened) = server.api("open", &json!({ "path": post }));
    assert_eq!(status, 200);
    assert_eq!(opened["encoding"], "latin-1");
    assert_eq!(opened["crlf"], true);
    let text = opened["text"].as_str().unwrap();
    assert!(text.starts_with("+ Fräse 90°\n"), "{:?}", &text[..20]);
    let (status, _) = server.api("save", &json!({ "path": post, "text": text }));
    assert_eq!(status, 200);
    assert_eq!(std::fs::read(&post).unwrap(), bytes, "saved as it was read");
    let edited = text.replacen("Fräse", "Fräser", 1);
    server.api("save", &json!({ "path": post, "text": edited }));
    assert!(std::fs::read(&post).unwrap().starts_with(b"+ Fr\xe4ser 90\xb0\r\n"));
    // A character Latin-1 cannot hold: refused, the file unchanged.
    let (status, body) = server.api("save", &json!({ "path": post, "text": "€\n" }));
    assert_eq!(status, 422, "{body}");
    assert!(std::fs::read(&post).unwrap().starts_with(b"+ Fr\xe4ser"));
}

/// Node.js, Chromium and web/node_modules for the browser tests: their
/// paths, or None when one is missing (a failure under `CI=true`).
fn browser_tools(test: &str) -> Option<(PathBuf, PathBuf)> {
    let node = crate::support::cimco::node_command().arg("--version").output().is_ok_and(|o| o.status.success());
    if !node {
        super::support::referee_missing(test, "node");
        return None;
    }
    let chromium = std::env::var_os("CHROMIUM").map_or_else(|| PathBuf::from("/usr/bin/chromium"), PathBuf::from);
    if !chromium.exists() {
        super::support::referee_missing(test, "chromium");
        return None;
    }
    let web = root().join("web");
    if !web.join("node_modules/playwright-core").is_dir() || !web.join("node_modules/esbuild").is_dir() {
        super::support::referee_missing(test, "web/node_modules (npm ci in web/)");
        return None;
    }
    Some((chromium, web))
}

/// The target folder of this build (test artifacts go in it).
fn target_dir() -> PathBuf {
    let exe = PathBuf::from(env!("CARGO_BIN_EXE_postc"));
    exe.parent().and_then(Path::parent).map_or_else(|| root().join("target"), Path::to_path_buf)
}

#[test]
fn browser_workbench_end_to_end() {
    let Some((chromium, web)) = browser_tools("browser_workbench_end_to_end") else { return };
    // A 200-line post: the corpus's G-code post after comment lines.
    let dir = tempfile::tempdir().unwrap();
    let source = std::fs::read_to_string(root().join("corpus/posts/vectric/gcode_mm.pp")).unwrap();
    let padding: String =
        (source.lines().count()..200).map(|i| format!("+ workbench latency padding line {i}\n")).collect();
    let post = dir.path().join("gcode_mm.pp");
    std::fs::write(&post, padding + source.as_str()).unwrap();
    let server = Server::start(&[&post, &seed_job()]);
    let shots = target_dir().join("workbench");
    let out = crate::support::cimco::node_command()
        .arg(web.join("e2e/workbench.mjs"))
        .arg(server.url())
        .arg(&shots)
        .env("CHROMIUM", &chromium)
        .output()
        .unwrap();
    let said = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    // The measured latency and the steps, for the test's output.
    println!("{said}");
    assert!(out.status.success(), "the browser test failed (screenshots in {}):\n{said}", shots.display());
    assert!(said.contains("LATENCY {"), "{said}");
    let saved = std::fs::read_to_string(&post).unwrap();
    assert!(saved.starts_with("+ saved by the workbench test\n"), "the save reached the file");
    for step in ["01-open", "03-error-underlined", "04-fixed", "05-trace", "06-converted", "07-saved"] {
        assert!(shots.join(format!("{step}.png")).is_file(), "screenshot {step}");
    }
}

#[test]
fn web_dist_is_what_web_src_builds() {
    let Some((_, web)) = browser_tools("web_dist_is_what_web_src_builds") else { return };
    let out = crate::support::cimco::node_command().arg(web.join("check.mjs")).output().unwrap();
    assert!(out.status.success(), "{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
}
