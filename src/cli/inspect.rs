//! `postc inspect`: prints a post's IR as RON, with a summary of which
//! functions run as native IR and which as scripts.

use std::path::PathBuf;

use postc_ir::Body;

use super::{DialectArg, Failed, load_post, report};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The post to show.
    post: PathBuf,
    /// The post's dialect, when its extension does not say.
    #[arg(long, value_enum)]
    dialect: Option<DialectArg>,
}

pub fn run(args: Args) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    let post = load_post(Some(&args.post), args.dialect, &mut sources)?;
    let config = ron::ser::PrettyConfig::new().struct_names(false).compact_arrays(true);
    let text = ron::ser::to_string_pretty(&post, config).unwrap_or_else(|e| format!("// cannot print the IR: {e}"));
    report::out(&format!("// {} ({:?} dialect)\n", post.info.name, post.info.dialect));
    for f in &post.functions {
        let how = match (&f.body, &f.why_script) {
            (Body::Native(_), _) => "native".to_string(),
            (Body::Script(_), None) => "script".to_string(),
            (Body::Script(_), Some(why)) => {
                let at = why
                    .span
                    .and_then(|s| sources.line_column(s.file, s.start).map(|(l, c)| (sources.name(s.file), l, c)))
                    .map_or_else(String::new, |(file, l, c)| format!(" ({file}:{l}:{c})"));
                format!("script: {}{at}", why.what)
            }
        };
        report::out(&format!("// function {}: {how}\n", f.name));
    }
    report::out(&(text + "\n"));
    Ok(())
}
