//! The command line of periodic-contact, a client of the library: raw arguments ([`args`], clap)
//! become the library's validated requests ([`config`]); `main.rs` runs them and renders the
//! answers (text, JSON, LaTeX, SymPy, Mathematica), with the exit codes 0 (answer), 2 (invalid
//! input), 1 (no solution, not physical, no convergence, I/O). Tests: `tests/` of this crate (every
//! subcommand through the binary).

// The doc comments of `args` are clap's --help text: `[output] digits` names a TOML table of the
// scene, not an intra-doc link, and must print without escapes.
#[allow(rustdoc::broken_intra_doc_links)]
pub mod args;
pub mod config;
