//! Every command the README and docs/guide.md show is run here and its output compared (issue 30).
//!
//! The documents write a session as a fenced block of info string `console`: a line `$ COMMAND`
//! runs `COMMAND` with `sh -c` (pipes and redirections work), the binary first on `PATH`, in a
//! scratch folder per document (files written by one command are there for the next) holding a
//! link `scenes` to the shipped scenes; the lines after it, up to the next `$ ` or the block's end,
//! are its output (stdout, then stderr). In the expected text a line `...` matches any number of
//! lines and `[..]` any part of a line (the syntax of `trycmd`): timings and long outputs are
//! elided with them; trailing empty lines are not compared. A command that exits non-zero must
//! show its error; `# exit N` as the last expected line states the exit code. `cargo install --path P` and `pip install P` are not run
//! (minutes each): the test checks that P is the package that installs the binary
//! `periodic-contact`, respectively the Python module. A block of info string `sh` may hold only
//! the project's scripts (`scripts/report`, `scripts/test`: minutes, and the second runs this
//! test), each checked to be an executable file; any other command must be a `console` session.
//! Run: `cargo test -p periodic-contact-cli --test all doc_commands::`.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The workspace's root folder (the documents and `scenes/` are there).
const ROOT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");

/// One `$ command` of a document with its expected output lines.
#[derive(Debug)]
struct Session {
    line: usize,
    command: String,
    expected: Vec<String>,
}

/// The `$ ` commands of the `console` blocks of `markdown`, in order, and the lines (number,
/// text) of its `sh` blocks.
fn sessions(markdown: &str) -> (Vec<Session>, Vec<(usize, String)>) {
    let mut out: Vec<Session> = Vec::new();
    let mut sh = Vec::new();
    let mut block: Option<String> = None;
    for (i, line) in markdown.lines().enumerate() {
        if let Some(info) = line.strip_prefix("```") {
            block = if block.is_some() { None } else { Some(info.trim().to_string()) };
            continue;
        }
        match block.as_deref() {
            Some("console") => {}
            Some("sh") => {
                sh.push((i + 1, line.to_string()));
                continue;
            }
            _ => continue,
        }
        if let Some(cmd) = line.strip_prefix("$ ") {
            out.push(Session { line: i + 1, command: cmd.to_string(), expected: Vec::new() });
        } else if let Some(s) = out.last_mut() {
            s.expected.push(line.to_string());
        } else {
            panic!("line {}: output before any `$ ` command", i + 1);
        }
    }
    (out, sh)
}

/// Whether `actual` matches the pattern `pattern` (`[..]`: any text).
fn line_matches(pattern: &str, actual: &str) -> bool {
    let parts: Vec<&str> = pattern.split("[..]").collect();
    if parts.len() == 1 {
        return pattern == actual;
    }
    let (first, last) = (parts[0], parts[parts.len() - 1]);
    if !actual.starts_with(first) || !actual[first.len()..].ends_with(last) || actual.len() < first.len() + last.len() {
        return false;
    }
    let mut rest = &actual[first.len()..actual.len() - last.len()];
    for mid in &parts[1..parts.len() - 1] {
        match rest.find(mid) {
            Some(k) => rest = &rest[k + mid.len()..],
            None => return false,
        }
    }
    true
}

/// Whether the lines `actual` match `expected` (`...`: any number of lines).
fn lines_match(expected: &[String], actual: &[&str]) -> bool {
    match expected.split_first() {
        None => actual.is_empty(),
        Some((e, rest)) if e == "..." => (0..=actual.len()).any(|k| lines_match(rest, &actual[k..])),
        Some((e, rest)) => actual.split_first().is_some_and(|(a, more)| line_matches(e, a) && lines_match(rest, more)),
    }
}

/// `cargo install --path P`: P's manifest is the package whose binary is `periodic-contact`.
fn check_install(command: &str) -> Result<(), String> {
    let words: Vec<&str> = command.split_whitespace().collect();
    if words.starts_with(&["pip", "install"]) {
        let p = Path::new(ROOT).join(words[2]).join("pyproject.toml");
        let text = std::fs::read_to_string(&p).map_err(|e| format!("{}: {e}", p.display()))?;
        return text
            .contains("name = \"periodic-contact\"")
            .then_some(())
            .ok_or(format!("{}: no such project", p.display()));
    }
    let path = words.iter().position(|w| *w == "--path").and_then(|i| words.get(i + 1)).ok_or("no --path")?;
    let dir = Path::new(ROOT).join(path);
    let manifest = std::fs::read_to_string(dir.join("Cargo.toml")).map_err(|e| format!("{path}: {e}"))?;
    let names_the_binary = manifest.contains("name = \"periodic-contact\"") && dir.join("src/main.rs").is_file()
        || manifest.contains("[[bin]]\nname = \"periodic-contact\"");
    names_the_binary.then_some(()).ok_or(format!("{path}: installs no binary `periodic-contact`"))
}

/// Runs the `console` sessions of one document; returns the failures.
fn run_document(doc: &str) -> Vec<String> {
    let text = std::fs::read_to_string(Path::new(ROOT).join(doc)).unwrap();
    let (list, sh) = sessions(&text);
    assert!(!list.is_empty(), "{doc} shows no console session");
    let mut failures = Vec::new();
    for (n, line) in sh {
        let command = line.split('#').next().unwrap_or_default().trim();
        let script = Path::new(ROOT).join(command);
        #[cfg(unix)]
        let runnable = {
            use std::os::unix::fs::PermissionsExt;
            command.starts_with("scripts/")
                && !command.contains(' ')
                && script.metadata().is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
        };
        #[cfg(not(unix))]
        let runnable = command.starts_with("scripts/") && script.is_file();
        if !command.is_empty() && !runnable {
            failures.push(format!(
                "{doc}:{n}: `{line}` in an sh block: only scripts/* (write commands as console sessions)"
            ));
        }
    }
    let dir: PathBuf =
        std::env::temp_dir().join(format!("doc_commands_{}_{}", std::process::id(), doc.replace('/', "_")));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink(Path::new(ROOT).join("scenes"), dir.join("scenes")).unwrap();
    let bin = Path::new(env!("CARGO_BIN_EXE_periodic-contact")).parent().unwrap().to_path_buf();
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    for s in list {
        let where_ = format!("{doc}:{}: $ {}", s.line, s.command);
        if s.command.starts_with("cargo install") || s.command.starts_with("pip install") {
            if let Err(e) = check_install(&s.command) {
                failures.push(format!("{where_}\n  {e}"));
            }
            continue;
        }
        let out = Command::new("sh").arg("-c").arg(&s.command).current_dir(&dir).env("PATH", &path).output().unwrap();
        let mut expected = s.expected.clone();
        while expected.last().is_some_and(|l| l.is_empty()) {
            expected.pop();
        }
        let want_code = match expected.last().and_then(|l| l.strip_prefix("# exit ")) {
            Some(c) => {
                let c = c.trim().parse::<i32>().unwrap();
                expected.pop();
                c
            }
            None => 0,
        };
        let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
        // the progress note appears only when a run outlasts its 2 s on a loaded machine
        let mut actual: Vec<&str> = text.lines().filter(|l| !l.ends_with("(running for more than 2 s)")).collect();
        while actual.last().is_some_and(|l| l.is_empty()) {
            actual.pop();
        }
        let code = out.status.code().unwrap_or(-1);
        if code != want_code || !lines_match(&expected, &actual) {
            failures.push(format!(
                "{where_}\n  exit {code} (want {want_code})\n  expected:\n    {}\n  actual:\n    {}",
                expected.join("\n    "),
                actual.join("\n    ")
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    failures
}

#[test]
fn readme_commands_print_what_the_readme_shows() {
    let f = run_document("README.md");
    assert!(f.is_empty(), "{}", f.join("\n\n"));
}

#[test]
fn guide_commands_print_what_the_guide_shows() {
    let f = run_document("docs/guide.md");
    assert!(f.is_empty(), "{}", f.join("\n\n"));
}

#[test]
fn the_matcher_elides_only_what_it_is_told() {
    let e = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert!(lines_match(&e(&["a", "...", "d"]), &["a", "b", "c", "d"]));
    assert!(lines_match(&e(&["a", "...", "d"]), &["a", "d"]));
    assert!(!lines_match(&e(&["a", "d"]), &["a", "b", "d"]));
    assert!(line_matches("took [..] s", "took 1.25 s"));
    assert!(!line_matches("took [..] s", "took 1.25 ms!"));
    assert!(line_matches("x [..] y [..] z", "x 1 y 2 z"));
    assert!(!line_matches("x [..] y", "x y"));
    assert!(check_install("cargo install --path crates/cli").is_ok());
    assert!(check_install("cargo install --path .").is_err());
    assert!(check_install("cargo install --path series").is_err());
    assert!(check_install("pip install ./python").is_ok());
}
