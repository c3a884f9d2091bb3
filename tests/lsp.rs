//! `postc lsp` driven as an editor drives it: the built binary on piped
//! stdio, JSON-RPC with Content-Length framing, every answer checked.

use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, ChildStdout, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::Duration;

use serde_json::{Value, json};

struct Client {
    child: Child,
    stdin: ChildStdin,
    messages: Receiver<Value>,
    next_id: i64,
}

fn read_message(r: &mut BufReader<ChildStdout>) -> Option<Value> {
    let mut length = None;
    loop {
        let mut line = String::new();
        if r.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(n) = line.strip_prefix("Content-Length: ") {
            length = n.parse::<usize>().ok();
        }
    }
    let mut body = vec![0; length?];
    r.read_exact(&mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

impl Client {
    fn start() -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_postc"))
            .arg("lsp")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("postc lsp starts");
        let stdin = child.stdin.take().unwrap();
        let mut stdout = BufReader::new(child.stdout.take().unwrap());
        let (tx, messages) = channel();
        std::thread::spawn(move || {
            while let Some(m) = read_message(&mut stdout) {
                if tx.send(m).is_err() {
                    break;
                }
            }
        });
        Client { child, stdin, messages, next_id: 1 }
    }

    fn send(&mut self, message: Value) {
        let body = serde_json::to_string(&message).unwrap();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{}", body.len(), body).unwrap();
        self.stdin.flush().unwrap();
    }

    fn recv(&self) -> Value {
        self.messages.recv_timeout(Duration::from_secs(30)).expect("the server answers within 30 s")
    }

    fn notify(&mut self, method: &str, params: Value) {
        self.send(json!({"jsonrpc": "2.0", "method": method, "params": params}));
    }

    /// Sends a request and returns its result (notifications in between
    /// must not come: the test reads each one where it is due).
    fn request(&mut self, method: &str, params: Value) -> Value {
        let id = self.next_id;
        self.next_id += 1;
        self.send(json!({"jsonrpc": "2.0", "id": id, "method": method, "params": params}));
        let answer = self.recv();
        assert_eq!(answer["id"], json!(id), "answer to {method}: {answer}");
        assert!(answer.get("error").is_none(), "{method} failed: {answer}");
        answer["result"].clone()
    }

    /// The next publishDiagnostics, for `uri`.
    fn diagnostics(&self, uri: &str) -> Vec<Value> {
        let m = self.recv();
        assert_eq!(m["method"], "textDocument/publishDiagnostics", "{m}");
        assert_eq!(m["params"]["uri"], uri, "{m}");
        m["params"]["diagnostics"].as_array().unwrap().clone()
    }

    fn open(&mut self, uri: &str, language: &str, text: &str) -> Vec<Value> {
        let doc = json!({"uri": uri, "languageId": language, "version": 1, "text": text});
        self.notify("textDocument/didOpen", json!({"textDocument": doc}));
        self.diagnostics(uri)
    }

    fn change(&mut self, uri: &str, version: i64, text: &str) -> Vec<Value> {
        let params = json!({"textDocument": {"uri": uri, "version": version}, "contentChanges": [{"text": text}]});
        self.notify("textDocument/didChange", params);
        self.diagnostics(uri)
    }

    fn at(&mut self, method: &str, uri: &str, line: u32, character: u32) -> Value {
        let params = json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}});
        self.request(method, params)
    }
}

fn range(line: u32, start: u32, end_line: u32, end: u32) -> Value {
    json!({"start": {"line": line, "character": start}, "end": {"line": end_line, "character": end}})
}

fn labels(completion: &Value) -> Vec<String> {
    let items = completion.as_array().or_else(|| completion["items"].as_array()).expect("completion items");
    items.iter().map(|i| i["label"].as_str().unwrap().to_owned()).collect()
}

fn find<'a>(diagnostics: &'a [Value], code: &str) -> &'a Value {
    diagnostics.iter().find(|d| d["code"] == code).unwrap_or_else(|| panic!("no {code} in {diagnostics:?}"))
}

/// Line 3 has a 2-byte `è` (1 UTF-16 unit) and a 4-byte `𝄞` (2 UTF-16
/// units, one character) before the unknown label `[QQ]`: postc says
/// column 19 (1-based, characters), LSP wants character 19 (0-based,
/// UTF-16 units).
const PP_BROKEN: &str = "UNITS = \"MM\"\nVAR X_POSITION = [X|Q|X|1.3]\nbegin HEADER\n\"(Pièce 𝄞) G0 [X] [QQ]\"\n";
const PP_FIXED: &str = "UNITS = \"MM\"\nVAR X_POSITION = [X|A|X|1.3]\nbegin HEADER\n\"(Pièce 𝄞) G0 [X]\"\nbegin FEED_MOVE\n\"G1 [X] [F]\"\n";
const PP_TYPO: &str =
    "UNITS = \"MM\"\nVAR X_POSITION = [X|A|X|1.3]\nbegin HEADER\n\"G0 [X]\"\nbegin FEED_MOVEE\n\"G1 [X]\"\n";

const JS: &str = "var xyzFormat = createFormat({decimals: 3});\nfunction onLinear(x, y, z, movement) {\n  return \"G1\" + xyzFormat.format(x);\n}\nfunction onOpen( {\n";
const VCPOST: &str = "Sub GOTO\n  Out \"G1 <X> <Y>\"\n  Helper\nEnd Sub\nSub Helper\n  If X > 1 Then\nEnd Sub\n";

#[test]
fn an_editor_session() {
    let mut c = Client::start();

    // initialize: the capabilities the server offers.
    let init = c.request("initialize", json!({"processId": null, "rootUri": null, "capabilities": {}}));
    let caps = &init["capabilities"];
    assert_eq!(caps["textDocumentSync"], 1, "full sync: {init}");
    assert_eq!(caps["hoverProvider"], true);
    assert_eq!(caps["definitionProvider"], true);
    assert_eq!(caps["codeActionProvider"], true);
    assert!(caps["completionProvider"]["triggerCharacters"].as_array().unwrap().contains(&json!("[")));
    assert_eq!(init["serverInfo"]["name"], "postc");
    c.notify("initialized", json!({}));

    // didOpen of a Vectric post with an error and a warning.
    let pp = "file:///work/posts/Pi%C3%A8ce%20test.pp";
    let d = c.open(pp, "vectric", PP_BROKEN);
    let pp004 = find(&d, "PP004");
    assert_eq!(pp004["severity"], 1);
    assert_eq!(pp004["source"], "postc");
    assert_eq!(pp004["range"], range(1, 20, 1, 21), "{pp004}");
    assert!(pp004["message"].as_str().unwrap().contains("`Q` is not A or C"), "{pp004}");
    let pp016 = find(&d, "PP016");
    assert_eq!(pp016["severity"], 2);
    assert_eq!(pp016["range"], range(3, 19, 3, 23), "{pp016}");
    assert_eq!(d.len(), 2, "{d:?}");

    // didChange fixing it: no diagnostics left.
    assert_eq!(c.change(pp, 2, PP_FIXED), Vec::<Value>::new());

    // hover on [X] (line 5: "G1 [X]", X at character 5).
    let hover = c.at("textDocument/hover", pp, 5, 5);
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("[X]") && text.contains("X_POSITION") && text.contains("X position"), "{hover}");
    assert_eq!(hover["range"], range(5, 5, 5, 6));
    // hover on a section name and on a global.
    let hover = c.at("textDocument/hover", pp, 4, 8);
    assert!(hover["contents"]["value"].as_str().unwrap().contains("FEED_MOVE"), "{hover}");
    let hover = c.at("textDocument/hover", pp, 0, 2);
    assert!(hover["contents"]["value"].as_str().unwrap().contains("INCHES"), "{hover}");
    // hover after the non-ASCII characters of line 3: the X of [X] is UTF-16 character 16 (character 15 in chars).
    let hover = c.at("textDocument/hover", pp, 3, 16);
    assert!(hover["contents"]["value"].as_str().unwrap().contains("X_POSITION"), "{hover}");

    // definition: from [X] to its VAR line.
    let def = c.at("textDocument/definition", pp, 5, 5);
    assert_eq!(def["uri"], pp);
    assert_eq!(def["range"], range(1, 4, 1, 14), "{def}");

    // completion after `begin ` and after `[`.
    let after_begin = labels(&c.at("textDocument/completion", pp, 4, 6));
    for s in ["HEADER", "FOOTER", "FEED_MOVE", "CW_ARC_MOVE", "TOOLCHANGE"] {
        assert!(after_begin.contains(&s.to_owned()), "{s} missing from {after_begin:?}");
    }
    // Typing the blank after `begin` asks too (trigger character " ").
    let typed = json!({"textDocument": {"uri": pp}, "position": {"line": 4, "character": 6},
                       "context": {"triggerKind": 2, "triggerCharacter": " "}});
    assert_eq!(labels(&c.request("textDocument/completion", typed)), after_begin);
    let after_bracket = labels(&c.at("textDocument/completion", pp, 5, 5));
    for l in ["X", "Y", "F", "S", "T", "TOOLNAME", "SAFEZ"] {
        assert!(after_bracket.contains(&l.to_owned()), "{l} missing from {after_bracket:?}");
    }
    assert!(!after_bracket.contains(&"HEADER".to_owned()));

    // A misspelt section: PP017, and a quick fix for it.
    let d = c.change(pp, 3, PP_TYPO);
    let pp017 = find(&d, "PP017").clone();
    assert_eq!(pp017["range"], range(4, 6, 4, 16), "{pp017}");
    let actions = c.request(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": pp}, "range": range(4, 0, 4, 16), "context": {"diagnostics": [pp017]}}),
    );
    let actions = actions.as_array().unwrap();
    assert_eq!(actions.len(), 1, "{actions:?}");
    let a = &actions[0];
    assert_eq!(a["title"], "Replace `FEED_MOVEE` with `FEED_MOVE`");
    assert_eq!(a["kind"], "quickfix");
    assert_eq!(a["diagnostics"][0]["code"], "PP017");
    assert_eq!(a["edit"]["changes"][pp], json!([{"range": range(4, 6, 4, 16), "newText": "FEED_MOVE"}]));
    // No action where nothing is misspelt.
    let none = c.request(
        "textDocument/codeAction",
        json!({"textDocument": {"uri": pp}, "range": range(2, 0, 2, 5), "context": {"diagnostics": []}}),
    );
    assert_eq!(none, json!([]));

    // A Vectric post whose POST_BASE (read from disk, next to it) has an
    // error: shown at the top of the document, naming the base's line.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("base.pp"),
        "UNITS = \"MM\"\nVAR X_POSITION = [X|Q|X|1.3]\nbegin HEADER\n\"G0 [X]\"\n",
    )
    .unwrap();
    let child = format!("file://{}/child.pp", dir.path().display());
    let d = c.open(&child, "vectric", "POST_BASE = \"base.pp\"\nbegin FOOTER\n\"M30\"\n");
    let base = find(&d, "PP004");
    assert_eq!(base["range"], range(0, 0, 0, 0), "{base}");
    assert!(base["message"].as_str().unwrap().contains("base.pp:2:21: `Q` is not A or C"), "{base}");

    // A CIMCO post: its syntax error, a hover on a host function, a
    // definition of a format.
    let js = "file:///work/posts/mill.js";
    let d = c.open(js, "javascript", JS);
    let js007 = find(&d, "JS007");
    assert_eq!(js007["severity"], 1);
    assert_eq!(js007["range"]["start"], json!({"line": 4, "character": 17}), "{js007}");
    let hover = c.at("textDocument/hover", js, 0, 20);
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("createFormat(") && text.contains("decimals"), "{hover}");
    let def = c.at("textDocument/definition", js, 2, 20);
    assert_eq!(def["range"], range(0, 4, 0, 13), "{def}");

    // A Fusion post: a hover on a host function gives Autodesk's
    // declaration and what postc's host does with it; completion offers
    // the host's names.
    let cps = "file:///work/posts/mill.cps";
    let _ = c.open(
        cps,
        "javascript",
        "function onOpen() {\n  var p = getParameter(\"job-description\");\n  include(\"common.cps\");\n}\n",
    );
    let hover = c.at("textDocument/hover", cps, 1, 12);
    let text = hover["contents"]["value"].as_str().unwrap();
    assert!(text.contains("getParameter(name: String): Value"), "{hover}");
    let hover = c.at("textDocument/hover", cps, 2, 4);
    assert!(hover["contents"]["value"].as_str().unwrap().contains("JS110"), "{hover}");
    assert!(labels(&c.at("textDocument/completion", cps, 1, 16)).contains(&"getParameter".to_owned()));

    // A VcPost post: the missing End If, a hover on a register, the
    // definition of a Sub.
    let vc = "file:///work/posts/mill.VcPost";
    let d = c.open(vc, "vcpost", VCPOST);
    let vc006 = find(&d, "VC006");
    assert_eq!(vc006["range"]["start"], json!({"line": 5, "character": 2}), "{vc006}");
    let hover = c.at("textDocument/hover", vc, 1, 12);
    assert!(hover["contents"]["value"].as_str().unwrap().contains("end point"), "{hover}");
    let def = c.at("textDocument/definition", vc, 2, 4);
    assert_eq!(def["range"], range(4, 4, 4, 10), "{def}");
    let regs = labels(&c.at("textDocument/completion", vc, 1, 11));
    // A blank typed in a VcPost line offers nothing.
    let typed = json!({"textDocument": {"uri": vc}, "position": {"line": 2, "character": 2},
                       "context": {"triggerKind": 2, "triggerCharacter": " "}});
    assert!(labels(&c.request("textDocument/completion", typed)).is_empty());
    assert!(regs.contains(&"X".to_owned()) && regs.contains(&"Minor".to_owned()), "{regs:?}");

    // Closing a document clears its diagnostics.
    c.notify("textDocument/didClose", json!({"textDocument": {"uri": vc}}));
    assert_eq!(c.diagnostics(vc), Vec::<Value>::new());

    // A request the server does not offer: MethodNotFound, and the server
    // goes on.
    c.send(json!({"jsonrpc": "2.0", "id": 999, "method": "textDocument/formatting", "params": {}}));
    let answer = c.recv();
    assert_eq!(answer["id"], 999);
    assert_eq!(answer["error"]["code"], -32601, "{answer}");
    let hover = c.at("textDocument/hover", js, 0, 20);
    assert!(hover["contents"]["value"].as_str().is_some());

    // shutdown, exit: the process ends with status 0.
    assert_eq!(c.request("shutdown", Value::Null), Value::Null);
    c.notify("exit", Value::Null);
    let status = c.child.wait().unwrap();
    assert!(status.success(), "{status}");
}

#[test]
fn the_lints_show_in_the_editor() {
    let mut c = Client::start();
    c.request("initialize", json!({"processId": null, "rootUri": null, "capabilities": {}}));
    c.notify("initialized", json!({}));
    let uri = "file:///work/posts/nofeed.pp";
    let d = c.open(uri, "vectric", "UNITS = \"MM\"\nbegin FEED_MOVE\n\"G1 [X]\"\n");
    let ln001 = find(&d, "LN001");
    assert_eq!(ln001["severity"], 2, "{ln001}");
    assert_eq!(ln001["range"]["start"]["line"], 1, "{ln001}");
    assert_eq!(c.change(uri, 2, "UNITS = \"MM\"\nbegin FEED_MOVE\n\"G1 [X] [F]\"\n"), Vec::<Value>::new());

    // The project's postc.toml applies in the editor as on the command line.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("postc.toml"), "[diagnostics]\nallow = [\"LN001\"]\ndeny = [\"PP027\"]\n").unwrap();
    let uri = format!("file://{}/nofeed.pp", dir.path().display());
    let d = c.open(&uri, "vectric", "begin FEED_MOVE\n\"G1 [X]\"\n");
    assert!(!d.iter().any(|d| d["code"] == "LN001"), "{d:?}");
    assert_eq!(find(&d, "PP027")["severity"], 1, "{d:?}");
}

/// A frame that does not read is answered with a JSON-RPC error (JSON-RPC
/// 2.0, section 5.1: -32700 parse error, -32600 invalid request, id null
/// when it cannot be read) and the server goes on with the next frame.
#[test]
fn a_bad_frame_is_answered_and_the_server_goes_on() {
    let mut c = Client::start();
    let raw = |c: &mut Client, bytes: &[u8]| {
        c.stdin.write_all(bytes).unwrap();
        c.stdin.flush().unwrap();
    };
    // Before initialize, and after it.
    raw(&mut c, b"Content-Length: 5\r\n\r\n{bad}");
    let answer = c.recv();
    assert_eq!(answer["error"]["code"], -32700, "{answer}");
    assert_eq!(answer["id"], Value::Null, "{answer}");
    c.request("initialize", json!({"processId": null, "rootUri": null, "capabilities": {}}));
    c.notify("initialized", json!({}));
    raw(&mut c, b"Content-Length: 5\r\n\r\n{bad}");
    assert_eq!(c.recv()["error"]["code"], -32700);
    // JSON that is no JSON-RPC message.
    raw(&mut c, b"Content-Length: 11\r\n\r\n{\"id\": [1]}");
    assert_eq!(c.recv()["error"]["code"], -32600);
    // A header without a length.
    raw(&mut c, b"Content-Type: x\r\n\r\n");
    assert_eq!(c.recv()["error"]["code"], -32700);
    // A length one short: the body's last byte comes before the next
    // header, which is found there (the mutation fuzzer's case).
    raw(&mut c, b"Content-Length: 10\r\n\r\n{\"id\": [1]}");
    assert_eq!(c.recv()["error"]["code"], -32700);
    // A length too long: the body holds the next frame's start, which is
    // read again.
    raw(&mut c, b"Content-Length: 38\r\n\r\n{\"id\"Content-Length: 11\r\n\r\n{\"id\": [1]}");
    assert_eq!(c.recv()["error"]["code"], -32700);
    assert_eq!(c.recv()["error"]["code"], -32600);
    // A header cut short, its line ending in the next frame's header: the
    // last header on the line is read (the mutation fuzzer's case, seed 7).
    raw(&mut c, b"Content-Length: 1cument/hover\"}}Content-Length: 11\r\n\r\n{\"id\": [1]}");
    assert_eq!(c.recv()["error"]["code"], -32600);
    // A frame with no body at all before the next frame: its length
    // takes the next frame, which starts its body: the frame is answered
    // as not JSON and the frames after it are read again (the mutation
    // fuzzer's case, seed 20261129).
    raw(
        &mut c,
        b"Content-Length: 40\r\n\r\nContent-Length: 11\r\n\r\n{\"id\": [1]}Content-Length: 11\r\n\r\n{\"id\": [2]}",
    );
    assert_eq!(c.recv()["error"]["code"], -32700);
    assert_eq!(c.recv()["error"]["code"], -32600);
    assert_eq!(c.recv()["error"]["code"], -32600);
    // The server still serves.
    let hover = c.at("textDocument/hover", "file:///nothing.pp", 0, 0);
    assert!(hover.is_null() || hover.is_object(), "{hover}");
    assert_eq!(c.request("shutdown", Value::Null), Value::Null);
    c.notify("exit", Value::Null);
    assert!(c.child.wait().unwrap().success());
}
