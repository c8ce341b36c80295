//! The README's example outputs are what the binary prints, byte for byte.
//!
//! Convention: a fenced ```` ```text ```` block is an example output when the fenced block just
//! before it (only prose between, no heading) is a ```` ```sh ```` block whose first line is a
//! runnable command: `cargo run [--release] -p halfplane-cli -- ARGS` or `halfplane ARGS`,
//! optionally followed by `| head -n N` (the block is then the first N lines) and a `# comment`.
//! The command runs from the repository root and must succeed; its stdout must equal the block.
//! Every other block (usage synopses, case files, commands without an output block) is skipped.
//! To show an output in the README, put its command in a `sh` block right above it.

mod common;
use common::stderr;
use std::path::Path;
use std::process::Command;

/// A command shown in the README and the output block below it.
#[derive(Debug)]
struct Example {
    /// README line of the command.
    line: usize,
    args: Vec<String>,
    /// Only this many leading lines are shown (`| head -n N`).
    head: Option<usize>,
    expected: String,
}

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
    let args = [
        "cargo run --release -p halfplane-cli -- ",
        "cargo run -p halfplane-cli -- ",
        "halfplane ",
    ]
    .iter()
    .find_map(|p| line.strip_prefix(p))?;
    Some((args.split_whitespace().map(String::from).collect(), head))
}

fn examples(readme: &str) -> Vec<Example> {
    let blocks = blocks(readme);
    blocks
        .windows(2)
        .filter(|w| w[0].lang == "sh" && w[1].lang == "text" && !w[1].after_heading)
        .filter_map(|w| {
            let (args, head) = command(w[0].text.lines().next()?)?;
            Some(Example {
                line: w[0].line + 1,
                args,
                head,
                expected: w[1].text.clone(),
            })
        })
        .collect()
}

#[test]
fn the_convention_finds_commands_and_skips_the_rest() {
    let readme = "# t\n```sh\ncargo run --release -p halfplane-cli -- steady a.toml   # note\ncargo test\n```\nprose\n```text\nout\n```\n```text\nusage\n```\n```sh\nhalfplane march b.toml --csv | head -n 2\n```\n```text\nx\ny\n```\n```sh\ncargo test\n```\n```text\nz\n```\n```sh\nhalfplane evolve c.toml\n```\n## heading\n```text\nw\n```\n";
    let found = examples(readme);
    assert_eq!(found.len(), 2, "{found:?}");
    assert_eq!(found[0].args, ["steady", "a.toml"]);
    assert_eq!(found[0].expected, "out\n");
    assert_eq!(found[1].args, ["march", "b.toml", "--csv"]);
    assert_eq!(found[1].head, Some(2));
    assert_eq!(found[1].expected, "x\ny\n");
}

#[test]
fn every_readme_output_block_is_what_its_command_prints() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let found = examples(&readme);
    // The README shows steady, evolve (table and CSV) and march (summary and CSV) outputs.
    assert!(found.len() >= 5, "only {} output blocks found", found.len());
    std::thread::scope(|s| {
        for e in &found {
            let root = &root;
            s.spawn(move || {
                let o = Command::new(env!("CARGO_BIN_EXE_halfplane"))
                    .args(&e.args)
                    .current_dir(root)
                    .output()
                    .expect("run halfplane");
                assert!(o.status.success(), "README line {}: {}", e.line, stderr(&o));
                let mut out = String::from_utf8(o.stdout).expect("UTF-8 output");
                if let Some(n) = e.head {
                    out = out.split_inclusive('\n').take(n).collect();
                }
                assert!(
                    out == e.expected,
                    "README line {} ({}): the block below it differs from the output:\n{out}",
                    e.line,
                    e.args.join(" ")
                );
            });
        }
    });
}
