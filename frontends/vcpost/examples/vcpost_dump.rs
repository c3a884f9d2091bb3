//! Compiles a `.VcPost` file and prints its diagnostics, Sub signatures and
//! (with `--ir`) the lowered IR as RON:
//! `cargo run -p postc-front-vcpost --example vcpost_dump -- FILE [--ir]`.

use postc_report::Render as _;
use std::path::Path;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.iter().find(|a| !a.starts_with("--")) else {
        eprintln!("usage: vcpost_dump FILE [--ir]");
        std::process::exit(2);
    };
    let bytes = match std::fs::read(path) {
        Ok(b) => b,
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(2);
        }
    };
    let mut sources = postc_report::source_map();
    let (post, diagnostics) = postc_front_vcpost::compile(Path::new(path), &bytes, &mut sources);
    print!("{}", sources.render(&diagnostics, false));
    for sub in &post.info.subs {
        println!("{sub:?}");
    }
    if args.iter().any(|a| a == "--ir") {
        println!("{post:#?}");
    }
}
