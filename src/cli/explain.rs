//! `postc explain CODE`: one diagnostic code's documentation, from the
//! registry (`postc_ir::codes`), as `rustc --explain` prints an error code.
//!
//! `postc explain TRACE.jsonl LINE` explains a line of a posted program
//! from its trace instead (`trace.rs`). The argument is a code when it has
//! a code's shape (two letters and three digits, `PP027`) and no LINE
//! follows; with a LINE it is a trace.

use std::path::Path;

use postc_ir::{SourceMap, codes};

use super::{Failed, fail, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// A diagnostic code (PP027), or the trace `postc post --trace` wrote.
    #[arg(value_name = "CODE|TRACE.jsonl")]
    target: String,
    /// With a trace: the NC line to explain, from 1.
    #[arg(value_name = "LINE")]
    line: Option<u64>,
    /// With a trace: which NC file, when the post split its output into parts (a path or its end).
    #[arg(short, long, value_name = "NC")]
    output: Option<String>,
}

pub fn run(args: Args) -> Result<(), Failed> {
    if let Some(line) = args.line {
        let mut sources = SourceMap::new();
        return match super::trace::explain(Path::new(&args.target), line, args.output.as_deref(), &mut sources) {
            Ok(text) => {
                report::out(&text);
                Ok(())
            }
            Err(d) => Err(fail(&mut sources, d)),
        };
    }
    let target = args.target.trim();
    if Path::new(target).is_file() && !codes::is_code_shaped(target) {
        eprintln!(
            "postc: `{target}` is a file: to explain a line of a posted program, give the line too (`postc explain TRACE.jsonl LINE`)"
        );
        return Err(Failed);
    }
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
