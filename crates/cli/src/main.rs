//! `periodic-contact`: parse -> validate (the library's requests) -> run (the library) -> render. `anyhow` and exit codes live only here:
//! 0 success, 2 invalid input (clap errors too), 1 no solution, no convergence or I/O failure.

use clap::Parser;
use periodic_contact::api::{derive_valid, json_text, Derivation};
use periodic_contact::error::{Error, ErrorKind};
use periodic_contact::model::ModelError;
use periodic_contact_cli::{args::Format, args::RawArgs, config::RunConfig};
use std::io::Write;
use std::process::ExitCode;

fn run(config: RunConfig) -> anyhow::Result<()> {
    match config {
        RunConfig::Series { valid, format } => {
            use periodic_contact::asymptotics::print::{render, SeriesFormat};
            let d = derive_valid(*valid)?;
            let text = match (&d, format) {
                (Derivation::Exact { object, parts, .. }, _) => {
                    let format = match format {
                        Format::Text => SeriesFormat::Text,
                        Format::Json => SeriesFormat::Json,
                        Format::Latex => SeriesFormat::Latex,
                        Format::Sympy => SeriesFormat::Sympy,
                        Format::Mathematica => SeriesFormat::Mathematica,
                    };
                    render(object, parts, format) + &d.pade_text()
                }
                (_, Format::Json) => json_text(&d.json()),
                _ => d.text(),
            };
            std::io::stdout().write_all(text.as_bytes())?;
        }
        RunConfig::Solve { scene, choice, format } => {
            let what = format!(
                "solving with {} ({} digits requested; {})",
                choice.request.method.name(),
                choice.request.digits,
                choice.reason
            );
            let v = with_progress(&what, || periodic_contact::api::solve_with_choice(&scene, choice))?.json;
            let text = match format {
                Format::Json => json_text(&v),
                _ => periodic_contact::solve::format::text(&v),
            };
            std::io::stdout().write_all(text.as_bytes())?;
        }
        RunConfig::SceneTemplate { text } => std::io::stdout().write_all(text.as_bytes())?,
        RunConfig::Completions { shell } => {
            use clap::CommandFactory;
            clap_complete::generate(shell, &mut RawArgs::command(), "periodic-contact", &mut std::io::stdout());
        }
        RunConfig::Man => {
            use clap::CommandFactory;
            clap_mangen::Man::new(RawArgs::command()).render(&mut std::io::stdout())?;
        }
        RunConfig::Report { out, scenes, order, fast, jobs } => {
            use periodic_contact_report::{section::Profile, write_report, ReportError, ReportOptions};
            let opts = ReportOptions {
                out: out.clone(),
                scenes,
                order,
                profile: if fast { Profile::Fast } else { Profile::Full },
                progress: true,
                jobs,
            };
            let files = write_report(&opts).map_err(|e| match e {
                ReportError::Scene { path, error } => anyhow::Error::new(ModelError::new(
                    format!("{path}: {}", error.parameter),
                    error.value,
                    error.expected,
                )),
                other => anyhow::Error::new(other),
            })?;
            eprintln!(
                "wrote {} files into {} (report.md, timings.md, charts as SVG + CSV)",
                files.files.len(),
                out.display()
            );
        }
        RunConfig::Calibrate { out } => {
            let pb = indicatif::ProgressBar::new(10);
            let table = periodic_contact_report::calibration::calibrate(&periodic_contact_report::machine(), |m| {
                pb.set_message(m.to_string());
                pb.inc(1);
            })
            .map_err(|e| anyhow::anyhow!("calibration failed: {e}"))?;
            pb.finish_and_clear();
            if let Some(dir) = out.parent().filter(|d| !d.as_os_str().is_empty()) {
                std::fs::create_dir_all(dir)?;
            }
            periodic_contact_report::write_whole(&out, table.to_csv().as_bytes())?;
            eprintln!("wrote {} ({} rows); review and commit it, then rebuild", out.display(), table.rows.len());
        }
    }
    Ok(())
}

/// Seconds a run may take before progress is shown.
const PROGRESS_AFTER: std::time::Duration = std::time::Duration::from_secs(2);

/// Runs `work`; if it is still running after [`PROGRESS_AFTER`], shows `what` on stderr: a
/// spinner with the elapsed time when stderr is a terminal, else one plain line.
fn with_progress<T>(what: &str, work: impl FnOnce() -> T) -> T {
    use std::io::IsTerminal;
    let (done, wait) = std::sync::mpsc::channel::<()>();
    let what = what.to_string();
    let shower = std::thread::spawn(move || {
        if wait.recv_timeout(PROGRESS_AFTER).is_ok() {
            return;
        }
        if !std::io::stderr().is_terminal() {
            eprintln!("{what} (running for more than {} s)", PROGRESS_AFTER.as_secs());
            return;
        }
        let pb = indicatif::ProgressBar::new_spinner();
        pb.set_style(
            indicatif::ProgressStyle::with_template("{spinner} [{elapsed_precise}] {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
        );
        pb.set_message(what);
        pb.enable_steady_tick(std::time::Duration::from_millis(120));
        let _ = wait.recv();
        pb.finish_and_clear();
    });
    let out = work();
    let _ = done.send(());
    let _ = shower.join();
    out
}

/// Exit status after Ctrl-C (SIGINT): 128 + 2, as a shell reports a process ended by it.
const INTERRUPTED: i32 = 130;

/// Ctrl-C (SIGINT) stops the run (issue 34): a watcher thread waits for the signal, removes this
/// process's temporary files from `dirs` (the report's output directory, the calibration file's;
/// every file is written whole under a temporary name and renamed, so a finished file is never
/// partial and the previous one stays until its successor is complete) and exits with status 130.
/// Nothing is printed to stdout before a solve or a series is complete, so an interrupted one
/// leaves no partial output either. Test: `crates/cli/tests/all/interrupt.rs`.
fn exit_on_interrupt(dirs: Vec<std::path::PathBuf>) -> std::io::Result<()> {
    let mut signals = signal_hook::iterator::Signals::new([signal_hook::consts::SIGINT])?;
    std::thread::spawn(move || {
        if signals.forever().next().is_some() {
            let removed: usize = dirs.iter().map(|d| periodic_contact_report::remove_partial_files(d)).sum();
            eprintln!(
                "interrupted (Ctrl-C): stopped; {removed} temporary file(s) removed, finished files left as they were"
            );
            std::process::exit(INTERRUPTED);
        }
    });
    Ok(())
}

/// The one mapping from errors to exit codes: 2 for invalid input, 1 for everything else (no
/// solution, not physical, no convergence, I/O).
fn exit_code(e: &anyhow::Error) -> u8 {
    let input = match e.downcast_ref::<Error>() {
        Some(err) => err.kind() == ErrorKind::Input,
        None => e.downcast_ref::<ModelError>().is_some(),
    };
    if input {
        2
    } else {
        1
    }
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
            let e = anyhow::Error::new(e);
            eprintln!("error: {e:#}");
            return ExitCode::from(exit_code(&e));
        }
    };
    if let Err(e) = exit_on_interrupt(config.output_dirs()) {
        eprintln!("error: cannot install the Ctrl-C handler: {e}");
        return ExitCode::from(1);
    }
    match run(config) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::from(exit_code(&e))
        }
    }
}
