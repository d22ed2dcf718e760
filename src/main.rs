//! The `chatter` binary: a thin wrapper over [`chatter::cli`].
fn main() -> std::process::ExitCode {
    chatter::cli::main()
}
