//! Sub signatures: the typed view of keyword comments that the probe-cycle
//! table, `postc probe-table` and the composites driver need (which Sub is
//! the #Init Sub, which parameters a #Cycle Sub takes and which of them are
//! mandatory, the tips of an #Option Sub).
//!
//! They are also kept in the compiled post, typed, in `PostInfo::subs`
//! ([`postc_ir::SubSignature`]), so that the runtime and the applications
//! read them without the syntax tree: [`to_ir`] writes them and
//! [`from_post`] reads them back.

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

/// Signatures as the IR keeps them.
pub fn to_ir(signatures: &[SubSignature]) -> Vec<postc_ir::SubSignature> {
    signatures
        .iter()
        .map(|s| postc_ir::SubSignature {
            name: s.name.clone(),
            keyword: s.keyword.map(|k| k.as_str().to_string()),
            params: s
                .params
                .iter()
                .map(|(name, required)| postc_ir::SubParam { name: name.clone(), required: *required })
                .collect(),
            tips: s
                .tips
                .iter()
                .map(|(slot, text)| postc_ir::SubTip { slot: slot.as_str().to_string(), text: text.clone() })
                .collect(),
        })
        .collect()
}

/// Reads signatures back from a compiled post; spans come from the post's
/// functions. A keyword or tip slot the post's IR names but VcPost does
/// not know (a hand-written RON post) is left out.
pub fn from_post(post: &Post) -> Vec<SubSignature> {
    post.info
        .subs
        .iter()
        .map(|s| SubSignature {
            name: s.name.clone(),
            keyword: s.keyword.as_deref().and_then(SubKeyword::from_word),
            params: s.params.iter().map(|p| (p.name.clone(), p.required)).collect(),
            tips: s.tips.iter().filter_map(|t| Some((TipSlot::from_word(&t.slot)?, t.text.clone()))).collect(),
            span: post
                .functions
                .iter()
                .find(|f| f.name.eq_ignore_ascii_case(&s.name))
                .and_then(|f| f.span)
                .unwrap_or_default(),
        })
        .collect()
}
