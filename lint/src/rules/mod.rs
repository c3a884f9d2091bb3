//! The rules, one per file. Codes are `LN0xx`; docs/diagnostics.md lists
//! them with what each means and how many of the real Vectric posts it
//! fires on.

mod arc_words_coarse;
mod block_numbers_wrap;
mod comment_parentheses;
mod feed_never_printed;
mod global_never_assigned;
mod post_name;
mod product_support;
mod register_never_set;
mod section_never_reached;
mod spindle_never_printed;
mod tape_split_spindle;
mod toolchange_without_retract;
mod units_word;
mod unused;

use crate::Rule;

pub(crate) use spindle_never_printed::has_word;

/// Every rule, in code order.
pub const ALL: &[Rule] = &[
    feed_never_printed::RULE,
    spindle_never_printed::RULE,
    comment_parentheses::RULE,
    toolchange_without_retract::RULE,
    post_name::RULE,
    product_support::RULE,
    unused::VARIABLE,
    unused::FORMAT,
    unused::FUNCTION,
    arc_words_coarse::RULE,
    tape_split_spindle::RULE,
    block_numbers_wrap::RULE,
    register_never_set::RULE,
    section_never_reached::RULE,
    global_never_assigned::RULE,
    unused::SUB,
    units_word::RULE,
];
