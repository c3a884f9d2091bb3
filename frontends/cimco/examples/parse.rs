//! Parses a CIMCO post and prints the tree dump and every diagnostic:
//! `cargo run -p postc-front-cimco --example parse -- post.js [--js]`
//! (`--js` prints the tree back as JavaScript instead of the dump).

use postc_report::Render as _;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.iter().find(|a| !a.starts_with("--")) else {
        eprintln!("usage: parse POST.js [--js]");
        std::process::exit(2);
    };
    let text = match std::fs::read(path) {
        Ok(bytes) => String::from_utf8_lossy(&bytes).into_owned(),
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(2);
        }
    };
    let mut sources = postc_report::source_map();
    let file = sources.add(path.clone(), text.clone());
    let (program, diagnostics) = postc_front_cimco::parse(&text, file);
    if args.iter().any(|a| a == "--js") {
        print!("{}", postc_front_cimco::print::to_js(&program));
    } else {
        print!("{}", postc_front_cimco::dump::dump(&program, &text));
    }
    eprint!("{}", sources.render(&diagnostics, false));
    if diagnostics.iter().any(|d| d.is_error()) {
        std::process::exit(1);
    }
}
