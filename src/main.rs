//! `periodic-contact`: parse -> validate -> run. `anyhow` and exit codes live only here:
//! 0 success, 2 invalid input (clap errors too), 1 no solution, no convergence or I/O failure.

use clap::Parser;
use periodic_contact::cli::{args::Format, args::RawArgs, config::RunConfig, InvalidInput};
use std::io::Write;
use std::process::ExitCode;

fn run(config: RunConfig) -> anyhow::Result<()> {
    match config {
        RunConfig::Series { object, order, subs, format } => {
            let parts = object.derive(order, &subs)?;
            let text = match format {
                Format::Text => parts.iter().map(|d| d.text()).collect::<Vec<_>>().join("\n"),
                Format::Latex => parts.iter().map(|d| d.latex()).collect::<Vec<_>>().join("\n"),
                Format::Json => {
                    let v = match parts.as_slice() {
                        [one] => one.json(),
                        many => serde_json::json!({
                            "object": object.name(),
                            "parts": many.iter().map(|d| d.json()).collect::<Vec<_>>(),
                        }),
                    };
                    format!("{}\n", serde_json::to_string_pretty(&v)?)
                }
            };
            std::io::stdout().write_all(text.as_bytes())?;
        }
        RunConfig::Solve { scene, request, format } => {
            let v = periodic_contact::solve::solve_scene(&scene, request).map_err(|e| match e {
                periodic_contact::solve::SolveError::Invalid(i) => anyhow::Error::new(i),
                periodic_contact::solve::SolveError::Failed(m) => anyhow::anyhow!("no solution: {m}"),
            })?;
            let text = match format {
                Format::Json => format!("{}\n", serde_json::to_string_pretty(&v)?),
                _ => periodic_contact::solve::format::text(&v),
            };
            std::io::stdout().write_all(text.as_bytes())?;
        }
        RunConfig::Report { out, order } => {
            let files = periodic_contact::report::write_report(&out, order)?;
            for f in files.files {
                eprintln!("wrote {}", f.display());
            }
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let args = match RawArgs::try_parse() {
        Ok(a) => a,
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    let config = match RunConfig::from_args(args) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    match run(config) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(if e.downcast_ref::<InvalidInput>().is_some() { 2 } else { 1 })
        }
    }
}
