//! `POST_BASE`: a post may name another post in its folder whose statements
//! apply first. This module reads the chain of bases (each one decoded,
//! registered in the source map and parsed), stopping with a warning when a
//! base cannot be read, when the chain loops back, or when it is deeper than
//! [`MAX_DEPTH`]. A base is read only when it is a regular file of at most
//! [`MAX_BASE_BYTES`]: a name such as `/dev/urandom` or `/dev/zero` would
//! otherwise be read without end. Bases are read through the source map's
//! [`SourceLoader`](postc_ir::SourceLoader) (the file system for the command
//! line, memory for tests and the language server): the frontend opens no
//! file itself.

use std::path::{Path, PathBuf};

use postc_ir::{Diagnostic, SourceLoader, SourceMap, Span};

use crate::ast::{ItemKind, PostFile, Value, VarBody};
use crate::decode::{Encoding, decode};
use crate::diagnostics::Code;
use crate::names::GlobalName;
use crate::parser::parse;

/// The most bases a chain may have.
pub const MAX_DEPTH: usize = 8;

/// The largest base file read (16 MiB): the largest post of the corpus is
/// under 100 KiB.
pub const MAX_BASE_BYTES: u64 = 16 << 20;

/// One parsed file of the chain.
pub struct Loaded {
    pub ast: PostFile,
    pub encoding: Encoding,
    pub path: PathBuf,
}

/// Decodes, registers and parses one file.
fn load(path: &Path, bytes: &[u8], sources: &mut SourceMap, diags: &mut Vec<Diagnostic>) -> Loaded {
    let (text, encoding) = decode(bytes);
    let file = sources.add(path.display().to_string(), text);
    let (ast, parse_diags) = parse(sources.text(file).unwrap_or(""), file);
    diags.extend(parse_diags);
    Loaded { ast, encoding, path: path.to_path_buf() }
}

/// The file named by the last `POST_BASE` of a post, and where it is named.
fn post_base(ast: &PostFile) -> Option<(String, Span)> {
    let mut found = None;
    for item in &ast.items {
        let (name, values) = match &item.kind {
            ItemKind::Global(g) => (&g.name, &g.values),
            ItemKind::Var(v) => match (&v.name, &v.body) {
                (Some(name), VarBody::Values(values)) => (name, values),
                _ => continue,
            },
            _ => continue,
        };
        if GlobalName::from_name(&name.value) != Some(GlobalName::PostBase) {
            continue;
        }
        if let [value] = values.as_slice() {
            let text = match &value.value {
                Value::Text(q) => q.plain(),
                Value::Word(w) => w.clone(),
                Value::Number(_) => continue,
            };
            if !text.trim().is_empty() {
                found = Some((text.trim().to_string(), value.span));
            }
        }
    }
    found
}

/// The base file: next to the post, matched without regard to letter case
/// when the exact name is not there (Windows posts name files loosely).
fn resolve(loader: &dyn SourceLoader, post: &Path, name: &str) -> PathBuf {
    let folder = post.parent().unwrap_or(Path::new(""));
    let exact = folder.join(name);
    if loader.exists(&exact) {
        return exact;
    }
    let (Some(file_name), Some(parent)) = (exact.file_name(), exact.parent()) else {
        return exact;
    };
    let wanted = file_name.to_string_lossy().into_owned();
    let parent = parent.to_path_buf();
    let lookup = if parent.as_os_str().is_empty() { Path::new(".") } else { parent.as_path() };
    let Ok(entries) = loader.read_dir(lookup) else {
        return exact;
    };
    let found = entries.into_iter().find(|e| e.to_string_lossy().eq_ignore_ascii_case(&wanted));
    found.map_or(exact, |e| parent.join(e))
}

/// The post and its bases, the deepest base first.
pub fn load_chain(path: &Path, bytes: &[u8], sources: &mut SourceMap, diags: &mut Vec<Diagnostic>) -> Vec<Loaded> {
    let mut chain = vec![load(path, bytes, sources, diags)];
    let mut seen = vec![sources.loader().canonicalize(path)];
    while let Some(current) = chain.last() {
        let Some((name, at)) = post_base(&current.ast) else {
            break;
        };
        let loader = sources.loader();
        let base = resolve(loader, &current.path, &name);
        let canonical = loader.canonicalize(&base);
        if seen.contains(&canonical) {
            diags.push(
                Code::BaseChain
                    .diag(format!("POST_BASE \"{name}\" leads back to a post already read; the chain stops here"))
                    .at(at, "loops back"),
            );
            break;
        }
        if chain.len() > MAX_DEPTH {
            diags.push(
                Code::BaseChain
                    .diag(format!("more than {MAX_DEPTH} POST_BASE files in a chain; the chain stops here"))
                    .at(at, "too deep"),
            );
            break;
        }
        match read_base(sources.loader(), &base) {
            Ok(bytes) => {
                seen.push(canonical);
                let loaded = load(&base, &bytes, sources, diags);
                chain.push(loaded);
            }
            Err(why) => {
                let label = if why == NO_SUCH_FILE { "base post not found" } else { "base post not read" };
                diags.push(
                    Code::MissingBase
                        .diag(format!("cannot read the POST_BASE file {}: {why}", base.display()))
                        .at(at, label)
                        .note(
                            "the post compiles without its base: sections, VARs and statements of the base are missing",
                        )
                        .help("put the base post in the same folder as this post"),
                );
                break;
            }
        }
    }
    chain.reverse();
    chain
}

const NO_SUCH_FILE: &str = "there is no such file";

/// The bytes of a base post, or why it is not read: only a regular file
/// (not a folder, device or pipe) of at most [`MAX_BASE_BYTES`] is read,
/// and never more than that many bytes, so the work stays bounded by the
/// size of real files whatever the name points at.
fn read_base(loader: &dyn SourceLoader, path: &Path) -> Result<Vec<u8>, String> {
    if !loader.exists(path) {
        return Err(NO_SUCH_FILE.into());
    }
    if !loader.is_file(path) {
        return Err("it is not a regular file (a folder, a device or a pipe), so it is not read".into());
    }
    let bytes = loader.read_at(path, 0, MAX_BASE_BYTES + 1).map_err(|error| {
        match error.kind() {
            std::io::ErrorKind::NotFound => NO_SUCH_FILE,
            std::io::ErrorKind::PermissionDenied => "permission denied",
            _ => "the file cannot be read",
        }
        .to_string()
    })?;
    if bytes.len() as u64 > MAX_BASE_BYTES {
        return Err(format!("it is larger than {} MiB, more than any post", MAX_BASE_BYTES >> 20));
    }
    Ok(bytes)
}
