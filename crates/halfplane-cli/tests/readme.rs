//! Every shell command in the README runs as written from the repository root, and its example
//! outputs are what the binary prints, byte for byte.
//!
//! Each line of a ```` ```sh ```` block is either run or skipped for a stated reason ([`skip`]);
//! a line that is neither fails the test, so a new README command is run as soon as it is added.
//! A runnable line is `cargo run [--release] -p halfplane-cli [--no-default-features] -- ARGS`
//! or `halfplane ARGS`, optionally followed by `| head -n N` and a `# comment`. The `cargo run`
//! wrapper is not itself run: the test runs the binary cargo built for it (the debug one, with
//! every feature), because `--release` would compile the whole workspace a second time (minutes)
//! for the same source. Every run command must succeed; one that names an output (`-o`) must
//! write it under `target/` (the README's examples leave the repository as it was); a `plot`
//! command must write a PNG the size of the committed `docs/` picture of the same name, and every
//! committed picture must have such a command.
//!
//! Example outputs: a fenced ```` ```text ```` block is the output of the first command of the
//! `sh` block just before it (only prose between, no heading); with `| head -n N` it is the first
//! N lines. Every other block (usage synopses, case files) is not a command and is skipped.
//!
//! The README draws figures, so this needs the `plot` feature (a default one).
#![cfg(feature = "plot")]

mod common;
use common::stderr;
use std::path::Path;
use std::process::Command;

/// One fenced block: its language, first line number and contents.
struct Block {
    lang: String,
    line: usize,
    text: String,
    /// A heading lies between the previous block and this one.
    after_heading: bool,
}

fn blocks(readme: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut open: Option<Block> = None;
    let mut heading = false;
    for (i, l) in readme.lines().enumerate() {
        match (&mut open, l.strip_prefix("```")) {
            (None, Some(lang)) => {
                open = Some(Block {
                    lang: lang.trim().to_string(),
                    line: i + 1,
                    text: String::new(),
                    after_heading: heading,
                });
                heading = false;
            }
            (Some(_), Some("")) => out.push(open.take().unwrap()),
            (Some(b), _) => {
                b.text.push_str(l);
                b.text.push('\n');
            }
            (None, None) => heading |= l.starts_with('#'),
        }
    }
    out
}

/// Why a README shell line is not run, or None when it must be run.
fn skip(line: &str) -> Option<&'static str> {
    const SKIPPED: [(&str, &str); 3] = [
        (
            "./scripts/test",
            "the whole test suite, of which this test is a part",
        ),
        (
            "pip install ",
            "builds the Python package in release mode (minutes); ./scripts/test installs the \
             same package with its extras and runs its tests",
        ),
        (
            "{ head -n 1 out/part-",
            "joins the shard files the Slurm job array writes (tests/sweep.rs checks that shards \
             joined in order are the sweep)",
        ),
    ];
    SKIPPED
        .iter()
        .find(|(prefix, _)| line.starts_with(prefix))
        .map(|(_, why)| *why)
}

/// Why a whole block is not run (a script for another machine), or None.
fn skip_block(text: &str) -> Option<&'static str> {
    text.starts_with("#!/bin/bash\n#SBATCH").then_some(
        "a Slurm job script: it needs sbatch and the user's own spec.toml (the sharding it uses \
         is tested in tests/sweep.rs)",
    )
}

/// The arguments of a runnable `halfplane` command line, and its `| head -n N`.
fn command(line: &str) -> Option<(Vec<String>, Option<usize>)> {
    let line = line.split(" #").next()?.trim();
    let (line, head) = match line.split_once('|') {
        Some((cmd, pipe)) => {
            let n = pipe.trim().strip_prefix("head -n")?.trim().parse().ok()?;
            (cmd.trim(), Some(n))
        }
        None => (line, None),
    };
    let args = match line.strip_prefix("cargo run ") {
        Some(rest) => {
            let (flags, args) = rest.split_once(" -- ")?;
            let known = ["--release", "-p", "halfplane-cli", "--no-default-features"];
            flags
                .split_whitespace()
                .all(|f| known.contains(&f))
                .then_some(args)?
        }
        None => line.strip_prefix("halfplane ")?,
    };
    Some((args.split_whitespace().map(String::from).collect(), head))
}

/// A README command to run.
#[derive(Debug)]
struct Example {
    /// README line of the command.
    line: usize,
    args: Vec<String>,
    /// Only this many leading lines are shown (`| head -n N`).
    head: Option<usize>,
    /// The output block below it, for the first command of a block.
    expected: Option<String>,
}

/// The commands to run, one list per block, and the skipped lines with the reason.
type Found = (Vec<Vec<Example>>, Vec<(usize, &'static str)>);

/// The README's commands, one list per `sh` block (a block's commands run in order: a later one
/// may read what an earlier one wrote), and the lines skipped with their reasons.
fn examples(readme: &str) -> Result<Found, String> {
    let blocks = blocks(readme);
    let (mut runs, mut skipped) = (Vec::new(), Vec::new());
    for (k, b) in blocks.iter().enumerate().filter(|(_, b)| b.lang == "sh") {
        if let Some(why) = skip_block(&b.text) {
            skipped.push((b.line + 1, why));
            continue;
        }
        let output = blocks
            .get(k + 1)
            .filter(|n| n.lang == "text" && !n.after_heading)
            .map(|n| n.text.clone());
        let mut block = Vec::new();
        for (i, l) in b.text.lines().enumerate() {
            let line = b.line + 1 + i;
            if l.trim().is_empty() {
                continue;
            }
            if let Some(why) = skip(l) {
                skipped.push((line, why));
                continue;
            }
            let (args, head) = command(l).ok_or_else(|| {
                format!("README line {line}: {l:?} is neither a halfplane command nor skipped")
            })?;
            let expected = if block.is_empty() {
                output.clone()
            } else {
                None
            };
            block.push(Example {
                line,
                args,
                head,
                expected,
            });
        }
        runs.push(block);
    }
    Ok((runs, skipped))
}

#[test]
fn the_convention_runs_commands_skips_with_reasons_and_rejects_the_rest() {
    let readme = "# t\n```sh\ncargo run --release -p halfplane-cli --no-default-features -- steady a.toml   # note\n./scripts/test\n```\nprose\n```text\nout\n```\n```text\nusage\n```\n```sh\nhalfplane march b.toml --csv | head -n 2\nhalfplane plot x b.toml -o target/x.png\n```\n```text\nx\ny\n```\n```sh\nhalfplane evolve c.toml\n```\n## heading\n```text\nw\n```\n";
    let (runs, skipped) = examples(readme).unwrap();
    assert_eq!(runs.len(), 3);
    assert_eq!(runs[0][0].args, ["steady", "a.toml"]);
    assert_eq!(runs[0][0].expected.as_deref(), Some("out\n"));
    assert_eq!(skipped.len(), 1);
    assert_eq!(skipped[0].0, 4);
    assert_eq!(runs[1][0].args, ["march", "b.toml", "--csv"]);
    assert_eq!(runs[1][0].head, Some(2));
    assert_eq!(runs[1][0].expected.as_deref(), Some("x\ny\n"));
    assert_eq!(runs[1][1].expected, None);
    assert_eq!(runs[2][0].expected, None, "a heading separates the output");
    let unknown = "```sh\ncargo test\n```\n";
    assert!(examples(unknown).unwrap_err().contains("line 2"));
    let other_flags = "```sh\ncargo run --features x -p halfplane-cli -- steady a.toml\n```\n";
    assert!(examples(other_flags).is_err());
}

/// Width and height from a PNG's header.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    let word = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (word(16), word(20))
}

/// The file a command writes (`-o FILE`), if any.
fn output(args: &[String]) -> Option<&str> {
    let at = args.iter().position(|a| a == "-o" || a == "--output")?;
    args.get(at + 1).map(String::as_str)
}

/// Runs one README command from the repository root and checks what it printed and wrote.
fn check(root: &Path, e: &Example) {
    let shown = e.args.join(" ");
    if let Some(out) = output(&e.args) {
        assert!(
            out.starts_with("target/"),
            "README line {}: {shown} writes {out}, outside target/: examples must leave the \
             repository as it was",
            e.line
        );
    }
    let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
        .args(&e.args)
        .current_dir(root)
        .output()
        .expect("run halfplane");
    assert!(
        o.status.success(),
        "README line {} ({shown}): {}",
        e.line,
        stderr(&o)
    );
    if let Some(expected) = &e.expected {
        let mut out = String::from_utf8(o.stdout).expect("UTF-8 output");
        if let Some(n) = e.head {
            out = out.split_inclusive('\n').take(n).collect();
        }
        assert!(
            &out == expected,
            "README line {} ({shown}): the block below it differs from the output:\n{out}",
            e.line
        );
    }
    if e.args[0] == "plot" {
        let written = output(&e.args).expect("a plot command names its output");
        let name = Path::new(written).file_name().unwrap();
        let committed = root.join("docs").join(name);
        let ours = png_size(&std::fs::read(root.join(written)).unwrap());
        let theirs = png_size(&std::fs::read(&committed).unwrap());
        assert_eq!(
            ours,
            theirs,
            "README line {}: {} differs in size from the committed picture; refresh it with -o {}",
            e.line,
            written,
            committed.display()
        );
    }
}

/// Every command the README shows runs as written (see the module's doc for what is checked).
/// Pixels are not compared: they depend on font rasterisation; the size includes the legend
/// strip, so it also changes when a legend moves between a corner and below the panels.
#[test]
fn every_readme_command_runs_as_written_and_prints_its_output_block() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let (runs, skipped) = examples(&readme).unwrap_or_else(|e| panic!("{e}"));
    // The README shows steady, evolve (table and CSV), march (summary and CSV) and match outputs.
    let outputs = runs.iter().flatten().filter(|e| e.expected.is_some());
    assert!(outputs.count() >= 6, "too few output blocks found");
    assert!(skipped.len() <= 5, "skipped: {skipped:?}");
    let mut drawn: Vec<String> = runs
        .iter()
        .flatten()
        .filter(|e| e.args[0] == "plot")
        .filter_map(|e| output(&e.args))
        .map(|o| {
            format!(
                "docs/{}",
                Path::new(o).file_name().unwrap().to_str().unwrap()
            )
        })
        .collect();
    drawn.sort();
    let mut committed: Vec<String> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .map(|n| format!("docs/{n}"))
        .collect();
    committed.sort();
    assert_eq!(drawn, committed, "README plot commands against docs/*.png");
    std::fs::create_dir_all(root.join("target")).unwrap();
    std::thread::scope(|s| {
        for block in &runs {
            let root = &root;
            s.spawn(move || block.iter().for_each(|e| check(root, e)));
        }
    });
}
