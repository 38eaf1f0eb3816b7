//! The module graph, drawn from the code: every `crate::<module>` reference of every file under
//! `src/` (comments left out), folded to top-level modules. Asserts that imports only point down
//! the layers (model -> numerics -> params -> asymptotics -> growing_contact -> sliding / adhesion /
//! loading_law -> verification -> solve, series_request -> api; the report and the command line
//! are crates of their own on top), that the three problems' folders do not use each other, that
//! no two files of any folder of any crate name each other, and that the
//! committed picture `docs/module-graph.md` is the graph of the code as it is (regenerate with
//! `UPDATE_MODULE_GRAPH=1 cargo test --test architecture`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Layer of each top-level module of `src/`: a module may use only modules of a lower layer.
const LAYERS: [(&str, u32); 14] = [
    ("model", 0),
    ("error", 1),
    ("scene", 1),
    ("numerics", 2),
    ("params", 3),
    ("asymptotics", 4),
    ("growing_contact", 5),
    ("sliding", 6),
    ("adhesion", 6),
    ("loading_law", 6),
    ("verification", 7),
    ("solve", 8),
    ("series_request", 8),
    ("api", 9),
];

fn layer(m: &str) -> Option<u32> {
    LAYERS.iter().find(|(n, _)| *n == m).map(|(_, l)| *l)
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The code of a file without comments (line comments and doc comments).
fn code(text: &str) -> String {
    text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

/// Top-level modules a file names: `crate::x` anywhere, `use crate::{x, y::z}` groups, and
/// `periodic_contact::x` in main.rs.
fn references(code: &str, prefix: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let ident = |s: &str| -> String { s.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect() };
    let mut rest = code;
    while let Some(i) = rest.find(prefix) {
        let after = &rest[i + prefix.len()..];
        if let Some(group) = after.strip_prefix('{') {
            // The matching brace of the group.
            let mut depth = 0i32;
            let mut end = group.len();
            for (j, ch) in group.char_indices() {
                match ch {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        end = j;
                        break;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            // Top-level items of the group: split at commas outside nested braces.
            let mut depth = 0;
            let mut start = 0;
            let g = &group[..end];
            for (j, ch) in g.char_indices() {
                match ch {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.insert(ident(g[start..j].trim()));
                        start = j + 1;
                    }
                    _ => {}
                }
            }
            out.insert(ident(g[start..].trim()));
        } else {
            out.insert(ident(after));
        }
        rest = after;
    }
    out.retain(|m| !m.is_empty());
    out
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in files {
        let rel = f.strip_prefix(&root).unwrap();
        let first = rel.components().next().unwrap().as_os_str().to_string_lossy().into_owned();
        let module = first.trim_end_matches(".rs").to_string();
        if module == "lib" {
            continue;
        }
        let text = code(&std::fs::read_to_string(&f).unwrap());
        let prefix = if module == "main" { "periodic_contact::" } else { "crate::" };
        let entry = g.entry(module.clone()).or_default();
        for r in references(&text, prefix) {
            if r != module && layer(&r).is_some() {
                entry.insert(r);
            }
        }
    }
    g
}

fn mermaid(g: &BTreeMap<String, BTreeSet<String>>) -> String {
    let mut s = String::from(
        "# Module graph of `src/`\n\nDrawn from the code by `tests/architecture.rs` (which fails when this file is out of date;\n\
         regenerate with `UPDATE_MODULE_GRAPH=1 cargo test --test architecture`). An arrow `a --> b` means\n\
         a file of `a` names `crate::b`. Layers, lowest first: model; error, scene; numerics; params;\n\
         asymptotics; growing_contact; sliding, adhesion, loading_law; verification; solve, series_request; api.\n\
         Every arrow points to a lower layer. The report (`crates/report`) and the command line\n\
         (`crates/cli`) are crates on top of the library.\n\n```mermaid\ngraph TD\n",
    );
    for (m, deps) in g {
        for d in deps {
            s.push_str(&format!("    {m} --> {d}\n"));
        }
    }
    s.push_str("```\n");
    s
}

#[test]
fn imports_point_down_the_layers() {
    let g = graph();
    let mut bad = Vec::new();
    for (m, deps) in &g {
        let lm = layer(m).unwrap_or_else(|| panic!("module {m} has no layer in LAYERS"));
        for d in deps {
            let ld = layer(d).unwrap();
            if ld >= lm {
                bad.push(format!("{m} (layer {lm}) -> {d} (layer {ld})"));
            }
        }
    }
    assert!(bad.is_empty(), "imports running up or sideways:\n{}", bad.join("\n"));
}

#[test]
fn committed_picture_is_the_graph_of_the_code() {
    let want = mermaid(&graph());
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/module-graph.md");
    if std::env::var_os("UPDATE_MODULE_GRAPH").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &want).unwrap();
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    assert_eq!(have, want, "docs/module-graph.md is out of date: UPDATE_MODULE_GRAPH=1 cargo test --test architecture");
}

/// The module path of a file under `root` (`loading_law/jacobian.rs` -> `[loading_law, jacobian]`;
/// `mod.rs`, `lib.rs` and `main.rs` name their folder).
fn module_path(root: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(root).unwrap();
    let mut parts: Vec<String> = rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    let last = parts.pop().unwrap();
    let stem = last.trim_end_matches(".rs");
    if !matches!(stem, "mod" | "lib" | "main") {
        parts.push(stem.to_string());
    }
    parts
}

/// Every path a piece of code names: `crate::a::b`, `super::super::c`, `self::d`, with `use`
/// groups expanded one level (`use super::{a::X, b}` names `super::a` and `super::b`).
fn paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    let bytes: Vec<char> = code.chars().collect();
    let is_id = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == ':';
    let mut i = 0;
    while i < bytes.len() {
        let starts = ["crate::", "super::", "self::"].iter().find(|p| code_at(&bytes, i, p));
        let boundary = i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == '_' || bytes[i - 1] == ':');
        if let (Some(_), true) = (starts, boundary) {
            let mut j = i;
            while j < bytes.len() && is_id(bytes[j]) {
                j += 1;
            }
            let head: String = bytes[i..j].iter().collect();
            if j < bytes.len() && bytes[j] == '{' && head.ends_with("::") {
                // A group: its items, one level.
                let mut depth = 0;
                let mut k = j + 1;
                let mut start = k;
                while k < bytes.len() {
                    match bytes[k] {
                        '{' => depth += 1,
                        '}' if depth == 0 => break,
                        '}' => depth -= 1,
                        ',' if depth == 0 => {
                            let item: String = bytes[start..k].iter().collect();
                            out.push(format!("{head}{}", item.trim()));
                            start = k + 1;
                        }
                        _ => {}
                    }
                    k += 1;
                }
                let item: String = bytes[start..k.min(bytes.len())].iter().collect();
                out.push(format!("{head}{}", item.trim()));
                i = k;
            } else {
                out.push(head.trim_end_matches(':').to_string());
                i = j;
            }
        } else {
            i += 1;
        }
    }
    out
}

fn code_at(chars: &[char], i: usize, pat: &str) -> bool {
    pat.chars().enumerate().all(|(k, c)| chars.get(i + k) == Some(&c))
}

/// The files of a crate (`root` = its `src/`) and, per file, the other files it names: a path is
/// resolved from the crate root (`crate::`) or the file's module (`super::`, `self::`; inside an
/// inline `mod tests { ... }` one `super` more), to the deepest module that is a file. A folder
/// module's `pub use` of its own children (its public face) is not counted.
fn file_graph(root: &Path) -> BTreeMap<Vec<String>, BTreeSet<Vec<String>>> {
    let mut files = Vec::new();
    rust_files(root, &mut files);
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(root, f)).collect();
    let mut g = BTreeMap::new();
    for f in &files {
        let me = module_path(root, f);
        let text = code(&std::fs::read_to_string(f).unwrap());
        // The code before the first inline module (tests) and after it.
        let split = text.find("mod tests {").unwrap_or(text.len());
        let mut deps = BTreeSet::new();
        for (part, extra) in [(&text[..split], 0usize), (&text[split..], 1)] {
            for p in paths(part) {
                let is_face = p.starts_with("self::") || (extra == 0 && part.contains(&format!("pub use {p}")));
                let mut segs: Vec<&str> = p.split("::").filter(|s| !s.is_empty()).collect();
                let mut base: Vec<String> = match segs.first() {
                    Some(&"crate") => {
                        segs.remove(0);
                        Vec::new()
                    }
                    _ => me.clone(),
                };
                let mut ups = 0usize;
                while segs.first() == Some(&"super") {
                    segs.remove(0);
                    ups += 1;
                }
                if segs.first() == Some(&"self") {
                    segs.remove(0);
                }
                let ups = if ups > 0 { ups.saturating_sub(extra) } else { 0 };
                for _ in 0..ups {
                    base.pop();
                }
                let mut target = base.clone();
                let mut best = base.clone();
                for s in segs {
                    target.push(s.to_string());
                    if modules.contains(&target) {
                        best = target.clone();
                    }
                }
                // A folder's `pub use child::...` (its public face) and a child's own names.
                let child_of_me = best.len() > me.len() && best.starts_with(&me);
                if best != me && modules.contains(&best) && !(is_face && child_of_me) {
                    deps.insert(best);
                }
            }
        }
        g.insert(me, deps);
    }
    g
}

/// Pairs of files that name each other.
fn mutual_pairs(root: &Path) -> Vec<String> {
    let g = file_graph(root);
    let mut bad = Vec::new();
    for (a, deps) in &g {
        for b in deps {
            if a < b && g.get(b).is_some_and(|d| d.contains(a)) {
                bad.push(format!("{} <-> {}", a.join("/"), b.join("/")));
            }
        }
    }
    bad
}

/// No two files of any folder name each other (a split that leaves two files importing each
/// other is worse than the long file), in every crate of the workspace.
#[test]
fn no_two_files_use_each_other() {
    let here = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut bad = Vec::new();
    for krate in ["src", "series/src", "crates/report/src", "crates/cli/src"] {
        for pair in mutual_pairs(&here.join(krate)) {
            bad.push(format!("{krate}: {pair}"));
        }
    }
    assert!(bad.is_empty(), "files that use each other:\n{}", bad.join("\n"));
}

#[test]
fn the_file_graph_sees_super_and_crate_paths() {
    let p = paths("use super::{increment::{a, b}, kernel::Side};\nlet x = crate::model::Exact::new(); self::f();");
    assert_eq!(p, ["super::increment::{a, b}", "super::kernel::Side", "crate::model::Exact::new", "self::f"]);
}

#[test]
fn the_reference_parser_reads_groups() {
    let r = references("use crate::{model::{A, B}, numerics::x};\nlet y = crate::params::sliding::f();", "crate::");
    assert_eq!(r.into_iter().collect::<Vec<_>>(), ["model", "numerics", "params"]);
}

/// theta, l_s, a0, the osculating k and beta are each computed in one function per number type
/// (`src/params/`): their formulas appear nowhere else in non-test code.
#[test]
fn derived_parameters_have_one_definition() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let patterns = [
        ("theta = atan(kappa)/pi", ".atan() / PI"),
        ("theta = atan(kappa)/pi", "atan_ref()) /"),
        ("theta = atan(kappa)/pi", "kappa.atan() / pi"),
        ("l_s = a0/sqrt(1 - 4 theta^2)", "4.0 * theta * theta"),
        ("l_s = a0/sqrt(1 - 4 theta^2)", "4.0 * th * th"),
        ("a0 = sqrt(2 P2/(pi E* k))", "2.0 * p2 / (PI"),
        ("k = 2 pi^2 D/L^2", "PI * PI * d"),
        ("beta = (1 - 2 nu)/(2 (1 - nu))", "0.4 / 1.4"),
    ];
    let mut found = Vec::new();
    for f in files {
        let rel = f.strip_prefix(&root).unwrap().to_string_lossy().into_owned();
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        if rel.starts_with("params") || name == "tests.rs" || name == "against_series.rs" {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        let production = code(text.split("#[cfg(test)]").next().unwrap_or(""));
        for (what, p) in patterns {
            if production.contains(p) {
                found.push(format!("{rel}: `{p}` ({what}: use crate::params)"));
            }
        }
    }
    assert!(found.is_empty(), "derived parameters computed outside params:\n{}", found.join("\n"));
}

/// Every ignored test in the workspace is in a tier: `#[ignore = "long tier ..."]` ones are named
/// in the LONG list of `scripts/test` (so `scripts/test --long`, which CI runs, runs it: slow tests
/// move to the long tier, never away), `#[ignore = "measurement tier ..."]` ones in its MEASURE
/// list (`scripts/test --measure`), and the rest need a tool (`"needs ..."`: SymPy, Chromium) that
/// `scripts/test` runs them with; every name in the two lists is such a test.
#[test]
fn every_ignored_test_is_in_a_tier() {
    let top = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["src", "tests", "series", "crates", "python/src"] {
        if top.join(dir).is_dir() {
            rust_files(&top.join(dir), &mut files);
        }
    }
    // every ignored test is in a tier scripts/test runs, or needs a tool scripts/test runs it with
    let (mut long, mut measure, mut unplaced) = (BTreeSet::new(), BTreeSet::new(), Vec::new());
    for f in files.iter().filter(|f| !f.components().any(|c| c.as_os_str() == "target")) {
        let text = std::fs::read_to_string(f).unwrap();
        let mut pending: Option<&str> = None;
        for line in text.lines().map(str::trim) {
            if let Some(reason) = line.strip_prefix("#[ignore") {
                pending = Some(reason);
            } else if let Some(reason) = pending
                && let Some(rest) = line.strip_prefix("fn ").or_else(|| line.strip_prefix("pub fn "))
            {
                let name = rest.split('(').next().unwrap().to_string();
                if reason.starts_with(" = \"long tier") {
                    long.insert(name);
                } else if reason.starts_with(" = \"measurement tier") {
                    measure.insert(name);
                } else if !reason.starts_with(" = \"needs ") {
                    unplaced.push(format!("{}: {name}", f.display()));
                }
                pending = None;
            }
        }
    }
    assert!(
        unplaced.is_empty(),
        "ignored tests in no tier (mark them \"long tier\" or \"measurement tier\"): {unplaced:?}"
    );
    let script = std::fs::read_to_string(top.join("scripts/test")).unwrap();
    for (tier, marked) in [("LONG", &long), ("MEASURE", &measure)] {
        let list = script
            .split(&format!("{tier}=("))
            .nth(1)
            .and_then(|s| s.split(')').next())
            .unwrap_or_else(|| panic!("{tier}=( ... ) in scripts/test"));
        let listed: BTreeSet<String> = list
            .lines()
            .filter_map(|l| l.trim().strip_prefix('"')?.strip_suffix('"').map(str::to_string))
            .flat_map(|entry| {
                entry.split_whitespace().skip(2).map(|n| n.rsplit("::").next().unwrap().to_string()).collect::<Vec<_>>()
            })
            .collect();
        assert!(!marked.is_empty() && !listed.is_empty(), "{tier}");
        let missing: Vec<_> = marked.difference(&listed).collect();
        let stale: Vec<_> = listed.difference(marked).collect();
        assert!(missing.is_empty(), "{tier}-tier tests not in scripts/test {tier}: {missing:?}");
        assert!(stale.is_empty(), "scripts/test {tier} names no such marked test: {stale:?}");
    }
}
