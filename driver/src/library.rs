//! The post library's names: what a compiled post says about itself (its
//! own name, dialect, units and output extension, read from the IR its
//! frontend made, not from its text) and how a name given as `postc post
//! --post NAME` picks one post out of a library (docs/posts.md).
//!
//! A name matches a post when the two are equal ignoring case and runs of
//! blanks, or when the name is the post's name without its trailing file
//! pattern (`LinuxCNC (mm)` for `LinuxCNC (mm) (*.ngc)`). No match is
//! answered with the names a typing mistake away, or that hold the name
//! given (`grbl` for `grbl (mm) (*.nc)`); two posts that match
//! are an ambiguity the caller reports with both paths.

use postc_ir::units::Units;
use postc_ir::{Dialect, Post};

/// What a post says about itself, as `postc posts` lists it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Described {
    /// The post's own name (Vectric `POST_NAME`, CIMCO `PostInfo.title`,
    /// Fusion `description`, VcPost `Postc.Name` or its header); the
    /// file's stem when the post names itself nowhere.
    pub name: String,
    pub dialect: Dialect,
    /// The units it writes; `None` when it writes the toolpath's own.
    pub units: Option<Units>,
    /// The extension of the files it writes, without the dot.
    pub extension: String,
}

impl Described {
    /// A compiled post's description.
    pub fn of(post: &Post) -> Described {
        Described {
            name: post.info.name.clone(),
            dialect: post.info.dialect,
            units: post.output_units(),
            extension: post.info.file_extension.trim_start_matches('.').to_string(),
        }
    }

    /// A compiled post's description, given the file it was compiled from:
    /// a VcPost post that sets no `Postc.Name` is named by its header, the
    /// first line of the comments that open the file (VcPost has no name
    /// statement of its own; Vericut names a post by its file).
    pub fn of_file(post: &Post, path: &std::path::Path, text: &[u8]) -> Described {
        let mut d = Described::of(post);
        let stem = path.file_stem().map(|s| s.to_string_lossy());
        if post.info.dialect == Dialect::VcPost
            && stem.is_some_and(|s| s == post.info.name)
            && let Some(header) = vcpost_header(&String::from_utf8_lossy(text))
        {
            d.name = header;
        }
        d
    }
}

/// The first line of the comments that open a VcPost file, without its
/// decoration (rules of `=`, `-`, `*`) and a final period; none when the
/// file opens with code or its opening comments hold no word.
fn vcpost_header(text: &str) -> Option<String> {
    let lexed = postc_front_vcpost::lexer::lex(text, postc_ir::FileId::default());
    let code_starts = lexed.tokens.iter().find(|(t, _)| !matches!(t, postc_front_vcpost::token::Token::Newline));
    let code_starts = code_starts.map_or(usize::MAX, |(_, span)| span.start);
    lexed
        .comments
        .iter()
        .take_while(|c| c.whole_line && c.span.start < code_starts)
        .map(|c| c.text.trim_matches(|ch: char| ch.is_whitespace() || matches!(ch, '=' | '-' | '*' | '\'')))
        .find(|t| t.chars().any(char::is_alphanumeric))
        .map(|t| t.strip_suffix('.').unwrap_or(t).trim_end().to_string())
}

/// The dialect as `--dialect` and `postc posts` name it.
pub fn dialect_name(d: Dialect) -> &'static str {
    match d {
        Dialect::Vectric => "vectric",
        Dialect::Cimco => "cimco",
        Dialect::VcPost => "vcpost",
        Dialect::Ron => "ron",
        Dialect::Fusion => "fusion",
    }
}

/// The units as `postc posts` names them.
pub fn units_name(u: Option<Units>) -> &'static str {
    match u {
        Some(Units::Mm) => "mm",
        Some(Units::Inch) => "inch",
        None => "toolpath's",
    }
}

/// What a name finds among a library's names.
#[derive(Debug, PartialEq, Eq)]
pub enum Lookup {
    /// The index of the one post it names.
    One(usize),
    /// Every post it names, when there are several.
    Ambiguous(Vec<usize>),
    /// No post; the indexes of at most three names a typing mistake away
    /// (nearest first), then of names that hold the name given.
    NotFound(Vec<usize>),
}

/// A name as names are compared: lower case, blanks trimmed and each run
/// of blanks one space.
fn normal(name: &str) -> String {
    name.split_whitespace().collect::<Vec<_>>().join(" ").to_lowercase()
}

/// A post's name without a trailing file pattern in parentheses
/// (`(*.ngc)`), as Vectric names end.
fn without_pattern(normal: &str) -> Option<&str> {
    let open = normal.rfind('(')?;
    let inner = normal[open..].strip_prefix("(*")?.strip_suffix(')')?;
    (!inner.contains(['(', ')'])).then(|| normal[..open].trim_end())
}

/// Finds the post that `wanted` names among `names` (docs/posts.md).
pub fn lookup<S: AsRef<str>>(wanted: &str, names: &[S]) -> Lookup {
    let wanted = normal(wanted);
    let normals: Vec<String> = names.iter().map(|n| normal(n.as_ref())).collect();
    let mut hits: Vec<usize> = (0..names.len()).filter(|&i| normals[i] == wanted).collect();
    if hits.is_empty() {
        hits = (0..names.len()).filter(|&i| without_pattern(&normals[i]) == Some(wanted.as_str())).collect();
    }
    match hits.len() {
        1 => return Lookup::One(hits[0]),
        0 => {}
        _ => return Lookup::Ambiguous(hits),
    }
    // A typing mistake: at most a third of the name's characters (at least
    // two) edited, against the whole name, the name without its pattern, or
    // one word of three letters or more of it (`grbel` for `grbl (mm)`).
    let limit = (wanted.chars().count() / 3).max(2);
    let mut near: Vec<(usize, usize)> = normals
        .iter()
        .enumerate()
        .filter_map(|(i, n)| {
            let words = n.split(' ').filter(|w| w.chars().count() >= 3);
            let d = std::iter::once(n.as_str())
                .chain(without_pattern(n))
                .chain(words)
                .map(|part| strsim::levenshtein(&wanted, part))
                .min()?;
            (d <= limit).then_some((d, i))
        })
        .collect();
    near.sort_unstable();
    // A part of a name (`grbl` for `grbl (mm) (*.nc)`) suggests the names
    // that hold it, after the near ones.
    let mut suggested: Vec<usize> = near.into_iter().map(|(_, i)| i).collect();
    if !wanted.is_empty() {
        let holding: Vec<usize> =
            (0..names.len()).filter(|&i| normals[i].contains(&wanted) && !suggested.contains(&i)).collect();
        suggested.extend(holding);
    }
    suggested.truncate(3);
    Lookup::NotFound(suggested)
}
