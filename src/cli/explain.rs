//! `postc explain CODE`: one diagnostic code's documentation, from the
//! registry (`postc_ir::codes`), as `rustc --explain` prints an error code.
//!
//! The argument is a code when it has a code's shape (two letters and three
//! digits, `PP027`); other arguments are kept for other forms of the
//! command (a trace file and a line of the program it traces).

use postc_ir::codes;

use super::{Failed, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A diagnostic code, such as PP027.
    #[arg(value_name = "CODE")]
    target: String,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let target = args.target.trim();
    let upper = target.to_ascii_uppercase();
    let looks_like_code = codes::is_code_shaped(&upper) && !std::path::Path::new(target).exists();
    if looks_like_code && let Some(code) = codes::lookup(&upper) {
        report::out(&code.explain());
        return Ok(());
    }
    if looks_like_code {
        let near = codes::similar(&upper);
        if near.is_empty() {
            eprintln!("postc: `{target}` is not a diagnostic code postc reports (docs/diagnostics.md lists them)");
        } else {
            eprintln!("postc: `{target}` is not a diagnostic code postc reports; did you mean {}?", near.join(", "));
        }
    } else {
        let near = codes::similar(&upper);
        let hint = if near.is_empty() { String::new() } else { format!("; did you mean {}?", near.join(", ")) };
        eprintln!(
            "postc: `{target}` is not a diagnostic code: a code is two letters and three digits, such as PP027{hint}"
        );
    }
    Err(Failed)
}
