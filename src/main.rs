//! The `postc` binary; everything lives in the library's `cli` module.

fn main() -> std::process::ExitCode {
    postc::cli::main()
}
