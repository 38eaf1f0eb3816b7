//! The module graph, drawn from the code: every `crate::<module>` reference of every file under
//! `src/` (comments left out), folded to top-level modules. Asserts that imports only point down
//! the layers (model -> numerics -> params -> asymptotics -> sliding / adhesion -> verification ->
//! solve -> report -> cli -> api -> main), that the two solver folders do not use each other, and that the
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
    ("sliding", 5),
    ("adhesion", 5),
    ("verification", 6),
    ("solve", 7),
    ("report", 8),
    ("cli", 9),
    ("api", 10),
    ("main", 11),
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
         asymptotics; sliding, adhesion; verification; solve; report; cli; api; main. Every arrow points to a\n\
         lower layer.\n\n```mermaid\ngraph TD\n",
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

#[test]
fn the_series_crate_has_no_file_cycle() {
    // Files of series/src and the files each names through `crate::<file>`.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("series/src");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let name = |p: &Path| {
        let rel = p.strip_prefix(&root).unwrap();
        rel.components().next().unwrap().as_os_str().to_string_lossy().trim_end_matches(".rs").to_string()
    };
    let names: BTreeSet<String> = files.iter().map(|f| name(f)).collect();
    let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for f in &files {
        let m = name(f);
        let text = code(&std::fs::read_to_string(f).unwrap());
        let e = g.entry(m.clone()).or_default();
        for r in references(&text, "crate::") {
            if r != m && names.contains(&r) {
                e.insert(r);
            }
        }
    }
    for (a, deps) in &g {
        for b in deps {
            assert!(!g.get(b).is_some_and(|d| d.contains(a)), "series files {a} and {b} use each other");
        }
    }
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
