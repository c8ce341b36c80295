//! ARCHITECTURE.md stays true to the tree: every crate under `crates/` is named (as
//! `crates/NAME`), and every source file under `crates/*/src` and `python/halfplane` is named by
//! its path relative to that directory, in backticks, in a section whose heading names the
//! directory (`## Code map: ... (`crates/halfplane/src`)`). The failure lists every file missing.

use std::fs;
use std::path::{Path, PathBuf};

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Every file under `dir`, as paths relative to it with `/` separators (caches left out).
fn files(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let path = entry.expect("a directory entry").path();
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if name == "__pycache__" || name.ends_with(".pyc") || name.starts_with('.') {
                continue;
            }
            if path.is_dir() {
                stack.push(path);
            } else {
                let relative = path.strip_prefix(dir).expect("under dir");
                let parts: Vec<&str> = relative.iter().filter_map(|p| p.to_str()).collect();
                out.push(parts.join("/"));
            }
        }
    }
    out.sort();
    out
}

/// The text of the sections (from a `## ` heading to the next) whose heading names `root`.
fn sections_naming(map: &str, root: &str) -> String {
    let tag = format!("`{root}`");
    map.split("\n## ")
        .filter(|section| section.lines().next().is_some_and(|h| h.contains(&tag)))
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn every_crate_and_source_file_is_named_in_the_architecture_map() {
    let root = workspace();
    let map = fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let mut missing = Vec::new();
    let mut crates: Vec<String> = fs::read_dir(root.join("crates"))
        .expect("crates/")
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir())
        .filter_map(|e| e.file_name().to_str().map(str::to_string))
        .collect();
    crates.sort();
    let mut roots = Vec::new();
    for name in &crates {
        if !map.contains(&format!("`crates/{name}`")) {
            missing.push(format!("crate crates/{name}"));
        }
        roots.push(format!("crates/{name}/src"));
    }
    roots.push("python/halfplane".to_string());
    let mut checked = 0;
    for r in &roots {
        let dir = root.join(r);
        if !dir.is_dir() {
            continue;
        }
        let text = sections_naming(&map, r);
        if text.is_empty() {
            missing.push(format!("a code-map section whose heading names `{r}`"));
            continue;
        }
        for file in files(&dir) {
            checked += 1;
            if !text.contains(&format!("`{file}`")) {
                missing.push(format!("{r}/{file}"));
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} files found: is the tree where expected?"
    );
    assert!(
        missing.is_empty(),
        "ARCHITECTURE.md does not name (by its path in backticks, in its code-map section):\n  {}",
        missing.join("\n  ")
    );
}
