//! Sub signatures: the typed view of keyword comments that the probe-cycle
//! table, `postc probe-table` and the composites driver need (which Sub is
//! the #Init Sub, which parameters a #Cycle Sub takes and which of them are
//! mandatory, the tips of an #Option Sub).
//!
//! They are also kept in the compiled post, one line each in
//! `PostInfo::notes`, so that the runtime reads them without the syntax
//! tree:
//!
//! ```text
//! vcpost.sub WallThick #Cycle !X !Y !Width !Depth !Angle !Correction Offset MaxSafe
//! vcpost.sub OpMessage #Option
//! vcpost.tip OpMessage #C1 Operator message
//! ```
//!
//! [`to_notes`] writes these lines and [`from_post`] reads them back.

use postc_ir::{Post, Span};
use serde::{Deserialize, Serialize};

use crate::ast::{CommentKind, Item, Program, SubKeyword, TipSlot};
use crate::keywords::MAX_PARAMS;

/// What the keyword comments of one Sub say.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SubSignature {
    /// The Sub's name, as written.
    pub name: String,
    /// Its keyword (`None` when it has only tips).
    pub keyword: Option<SubKeyword>,
    /// Parameters in table order: name and whether it is mandatory.
    pub params: Vec<(String, bool)>,
    /// Tips of an option Sub's input fields.
    pub tips: Vec<(TipSlot, String)>,
    /// The Sub's header line.
    pub span: Span,
}

/// Prefix of a signature note.
pub const SUB_NOTE: &str = "vcpost.sub ";
/// Prefix of a tip note.
pub const TIP_NOTE: &str = "vcpost.tip ";

/// The signatures of every Sub that has a keyword or a tip, in file order.
/// A Sub's keyword is its first one; its parameters are those of all its
/// keyword lines, duplicates and invalid or reserved names left out, at
/// most 16.
pub fn signatures(program: &Program) -> Vec<SubSignature> {
    let mut out = Vec::new();
    for item in &program.items {
        let Item::Proc(p) = item else { continue };
        let mut sig = SubSignature {
            name: p.name.text.clone(),
            keyword: None,
            params: Vec::new(),
            tips: Vec::new(),
            span: p.header,
        };
        for kc in &p.keyword_comments {
            match &kc.kind {
                CommentKind::Keyword(k) => {
                    sig.keyword.get_or_insert(*k);
                    for param in &kc.params {
                        let usable =
                            crate::token::is_valid_name(&param.name) && !crate::token::is_reserved(&param.name);
                        let fresh = !sig.params.iter().any(|(n, _)| n.eq_ignore_ascii_case(&param.name));
                        if usable && fresh && sig.params.len() < MAX_PARAMS {
                            sig.params.push((param.name.clone(), param.mandatory));
                        }
                    }
                }
                CommentKind::Tip(slot, text) => sig.tips.push((*slot, text.clone())),
                CommentKind::Unknown(_) => {}
            }
        }
        if sig.keyword.is_some() || !sig.tips.is_empty() {
            out.push(sig);
        }
    }
    out
}

/// The signatures of Subs with a cycle keyword (what the probe table lists).
pub fn probe_cycles(program: &Program) -> Vec<SubSignature> {
    signatures(program).into_iter().filter(|s| s.keyword.is_some()).collect()
}

/// Signatures as `PostInfo::notes` lines.
pub fn to_notes(signatures: &[SubSignature]) -> Vec<String> {
    let mut notes = Vec::new();
    for s in signatures {
        let mut line =
            format!("{SUB_NOTE}{} {}", s.name, s.keyword.map_or("-".to_string(), |k| format!("#{}", k.as_str())));
        for (name, mandatory) in &s.params {
            line.push(' ');
            if *mandatory {
                line.push('!');
            }
            line.push_str(name);
        }
        notes.push(line);
        for (slot, text) in &s.tips {
            notes.push(format!("{TIP_NOTE}{} #{} {}", s.name, slot.as_str(), text).trim_end().to_string());
        }
    }
    notes
}

/// Reads signatures back from a compiled post's notes; spans come from the
/// post's functions.
pub fn from_post(post: &Post) -> Vec<SubSignature> {
    let mut out: Vec<SubSignature> = Vec::new();
    for note in &post.info.notes {
        if let Some(rest) = note.strip_prefix(SUB_NOTE) {
            let mut words = rest.split_whitespace();
            let (Some(name), Some(keyword)) = (words.next(), words.next()) else { continue };
            let span = post
                .functions
                .iter()
                .find(|f| f.name.eq_ignore_ascii_case(name))
                .and_then(|f| f.span)
                .unwrap_or_default();
            out.push(SubSignature {
                name: name.to_string(),
                keyword: keyword.strip_prefix('#').and_then(SubKeyword::from_word),
                params: words
                    .map(|w| w.strip_prefix('!').map_or((w.to_string(), false), |n| (n.to_string(), true)))
                    .collect(),
                tips: Vec::new(),
                span,
            });
        } else if let Some(rest) = note.strip_prefix(TIP_NOTE) {
            let mut parts = rest.splitn(3, ' ');
            let (Some(name), Some(slot)) = (parts.next(), parts.next()) else { continue };
            let Some(slot) = slot.strip_prefix('#').and_then(TipSlot::from_word) else { continue };
            let text = parts.next().unwrap_or("").to_string();
            if let Some(sig) = out.iter_mut().rev().find(|s| s.name == name) {
                sig.tips.push((slot, text));
            }
        }
    }
    out
}
