//! Runs that cannot finish are refused before they start (`march` and `sweep`, naming the field,
//! the estimate and the limit), `--no-size-limit` lifts the limit, long runs report progress on
//! stderr when it is not a terminal, and a sweep that fails or is interrupted part-way removes its
//! `.part` file and says so.

mod common;
use common::{example, scratch, stderr, REFERENCE_CASE};
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

/// The longest a refusal may take: it happens before any solving (measured well under a second;
/// the margin is for a loaded machine). Before the limits these runs took hours.
const REFUSAL_SECONDS: u64 = 30;

fn command(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_halfplane"));
    c.args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    c
}

/// Waits for `child` at most `seconds`; kills it (and fails) if it is still running.
fn wait_at_most(mut child: Child, seconds: u64, what: &str) -> Output {
    let start = Instant::now();
    loop {
        if child.try_wait().expect("wait").is_some() {
            return child.wait_with_output().expect("output");
        }
        if start.elapsed() > Duration::from_secs(seconds) {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} still running after {seconds} s: it was not refused");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

/// Runs the command, which must end within [`REFUSAL_SECONDS`].
fn run_briefly(args: &[&str]) -> Output {
    let child = command(args).spawn().expect("run halfplane");
    wait_at_most(child, REFUSAL_SECONDS, &args.join(" "))
}

fn assert_refused(o: &Output, parts: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    for part in parts {
        assert!(err.contains(part), "missing {part:?} in: {err}");
    }
    assert!(err.contains("--no-size-limit"), "no way out named: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn a_march_on_a_million_cells_is_refused_at_once() {
    let start = Instant::now();
    let o = run_briefly(&["march", &example("march-cycle.toml"), "--cells", "1000000"]);
    // 1e12 cells² x 300 increments x 5e-10 s = 1.5e5 s = 41.7 hours > 8 hours.
    assert_refused(
        &o,
        &[
            "--cells 1000000 with 300 increments",
            "41.7 hours",
            "limit of 8.0 hours",
            "cells² x increments = 3.0e14",
        ],
    );
    assert!(o.stdout.is_empty());
    eprintln!("refused in {:.3} s", start.elapsed().as_secs_f64());
}

#[test]
fn stress_fatigue_and_crack_refuse_the_march_they_would_need() {
    // Each marches the case's history first; before this check `fatigue --cells 1000000` ran for
    // hours with no output. examples/crack.toml has 140 increments: 1e12 x 140 x 5e-10 s = 19.4
    // hours; examples/fatigue.toml has 140 as well.
    for (command, case) in [
        ("fatigue", "fatigue.toml"),
        ("crack", "crack.toml"),
        ("stress", "fatigue.toml"),
    ] {
        let case = example(case);
        let mut args = vec![command, case.as_str(), "--cells", "1000000"];
        if command == "stress" {
            args.extend(["--grid", "0,1,2,0,1,2"]);
        }
        let o = run_briefly(&args);
        assert_refused(&o, &["--cells 1000000 with", "limit of 8.0 hours"]);
        assert!(o.stdout.is_empty(), "{command}");
    }
}

#[cfg(feature = "plot")] // draws figures
#[test]
fn figures_refuse_the_march_they_would_need() {
    // Before, `plot stress-map --cells 1000000` marched for hours with no output.
    let dir = scratch("limits-figures");
    let out = dir.join("f.svg");
    let (fatigue, cycle) = (example("fatigue.toml"), example("march-cycle.toml"));
    for args in [
        vec!["plot", "stress-map", fatigue.as_str()],
        vec!["plot", "fatigue-map", fatigue.as_str()],
        vec!["plot", "surface-profiles", fatigue.as_str()],
        vec!["plot", "march-fields", cycle.as_str()],
        vec!["plot", "march-zones", cycle.as_str()],
    ] {
        let mut args = args;
        args.extend([
            "-o",
            out.to_str().expect("utf-8 path"),
            "--cells",
            "1000000",
        ]);
        let o = run_briefly(&args);
        assert_refused(&o, &["--cells 1000000 with", "limit of 8.0 hours"]);
        assert!(!out.exists(), "{args:?} drew a figure");
    }
}

#[test]
fn fatigue_says_it_is_running_when_stderr_is_not_a_terminal() {
    // Before, a long fatigue run printed nothing until its table; now a line per interval.
    let o = command(&["fatigue", &example("fatigue.toml"), "--csv"])
        .env("HALFPLANE_PROGRESS_SECONDS", "0.1")
        .output()
        .expect("run halfplane");
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        err.contains("fatigue: running, "),
        "no progress line in: {err}"
    );
}

#[test]
fn a_figure_that_marches_says_it_is_running() {
    // Before, `plot march-zones` (and the other figures that march) printed nothing until the
    // figure was written; now a line per interval, as the commands that march.
    let dir = scratch("limits-plot-progress");
    let out = dir.join("zones.svg");
    let o = command(&[
        "plot",
        "march-zones",
        &example("march-cycle.toml"),
        // 1600 cells: about 1.8 s in the test build, many intervals of 0.1 s.
        "--cells",
        "1600",
        "-o",
        out.to_str().expect("utf-8 path"),
    ])
    .env("HALFPLANE_PROGRESS_SECONDS", "0.1")
    .output()
    .expect("run halfplane");
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(
        err.contains("plot: running, "),
        "no progress line in: {err}"
    );
    assert!(out.exists(), "no figure written");
}

#[test]
fn the_cells_of_the_case_file_are_named_when_they_make_the_march_too_long() {
    let dir = scratch("limits-case-cells");
    let case = dir.join("case.toml");
    let text = std::fs::read_to_string(example("march-cycle.toml"))
        .unwrap()
        .replace("cells = 400", "cells = 500000");
    std::fs::write(&case, text).unwrap();
    let o = run_briefly(&["march", case.to_str().unwrap()]);
    assert_refused(
        &o,
        &["solver.cells = 500000 with 300 increments", "10.4 hours"],
    );
}

/// A harmonic history of 999,980 increments (8333 cycles of 120 steps and a ramp of 20) on 1300
/// cells: the march is estimated at 1300² x 999,980 x 5e-10 s = 845 s, under the time limit, but
/// `--fields` would write 80 bytes per cell and increment, 104 GB.
fn long_history(dir: &Path) -> String {
    let case = dir.join("long.toml");
    std::fs::write(
        &case,
        format!(
            "{REFERENCE_CASE}[history]\nkind = \"harmonic\"\ncycles = 8333\nsteps_per_cycle = 120\n\
             ramp_steps = 20\nnormal = {{ mean = 1200.0, amplitude = 200.0, phase = 0.0 }}\n\
             shear = {{ mean = 0.0, amplitude = 300.0, phase = 90.0 }}\n[solver]\ncells = 1300\n"
        ),
    )
    .unwrap();
    case.to_str().unwrap().to_string()
}

#[test]
fn march_fields_that_would_fill_the_disk_are_refused() {
    let dir = scratch("limits-fields");
    let case = long_history(&dir);
    let fields = dir.join("fields");
    let o = run_briefly(&["march", &case, "--fields", fields.to_str().unwrap()]);
    assert_refused(
        &o,
        &[
            "--fields with solver.cells = 1300 and 999980 increments",
            "104.0 GB",
            "limit of 100.0 GB",
        ],
    );
    assert!(!fields.exists(), "nothing written");
}

/// The stderr lines of a running child, as they come.
type Lines = std::sync::mpsc::Receiver<String>;

/// Spawns `args` with progress lines every `every` seconds, and returns once a stderr line
/// containing `marker` has been read (the run has started working), with the child, the lines
/// so far and the rest to come.
fn start_until(args: &[&str], every: &str, marker: &str) -> (Child, Vec<String>, Lines) {
    let mut child = command(args)
        .env("HALFPLANE_PROGRESS_SECONDS", every)
        .spawn()
        .expect("run halfplane");
    let err = child.stderr.take().expect("stderr");
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        for line in BufReader::new(err).lines() {
            if tx.send(line.unwrap_or_default()).is_err() {
                break;
            }
        }
    });
    let mut lines = Vec::new();
    let deadline = Instant::now() + Duration::from_secs(120);
    while Instant::now() < deadline {
        match rx.recv_timeout(Duration::from_millis(100)) {
            Ok(line) => {
                let found = line.contains(marker);
                lines.push(line);
                if found {
                    // The reader thread keeps draining stderr, so the child never blocks on it.
                    return (child, lines, rx);
                }
            }
            Err(std::sync::mpsc::RecvTimeoutError::Timeout) => {}
            Err(_) => break,
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    panic!("no {marker:?} on stderr: {lines:?}");
}

fn interrupt(child: &Child) {
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill");
    assert!(killed.success());
}

fn wait_status(mut child: Child, seconds: u64) -> ExitStatus {
    let start = Instant::now();
    loop {
        if let Some(s) = child.try_wait().expect("wait") {
            return s;
        }
        if start.elapsed() > Duration::from_secs(seconds) {
            let _ = child.kill();
            panic!("still running {seconds} s after Ctrl-C");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn no_size_limit_lets_a_refused_march_start() {
    let dir = scratch("limits-override");
    let case = long_history(&dir);
    let fields = dir.join("fields");
    let (mut child, lines, _) = start_until(
        &[
            "march",
            &case,
            "--fields",
            fields.to_str().unwrap(),
            "--no-size-limit",
        ],
        "0",
        "march: ",
    );
    let _ = child.kill();
    let _ = child.wait();
    assert!(
        lines.iter().any(|l| l.contains("/999980 increments")),
        "{lines:?}"
    );
}

#[test]
fn a_march_reports_progress_on_stderr_when_it_is_not_a_terminal() {
    let o = command(&["march", &example("march-cycle.toml"), "--csv"])
        .env("HALFPLANE_PROGRESS_SECONDS", "0")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let lines: Vec<&str> = err.lines().collect();
    assert!(lines.len() >= 2, "{err}");
    for line in &lines {
        assert!(
            line.starts_with("march: ") && line.contains("/300 increments"),
            "{line}"
        );
    }
    let last = lines.last().unwrap();
    assert!(last.contains("300/300 increments (100%)"), "{last}");
    // The report on stdout is untouched by the progress lines.
    assert!(String::from_utf8_lossy(&o.stdout).starts_with("step,"));
}

#[test]
fn a_short_march_prints_no_progress_at_the_default_interval() {
    let o = command(&[
        "march",
        &example("march-cycle.toml"),
        "--cells",
        "50",
        "--csv",
    ])
    .env_remove("HALFPLANE_PROGRESS_SECONDS")
    .output()
    .unwrap();
    assert!(o.status.success());
    assert_eq!(stderr(&o), "");
}

fn spec(dir: &Path, sweep: &str) -> String {
    let path = dir.join("spec.toml");
    std::fs::write(&path, format!("{REFERENCE_CASE}{sweep}")).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn sweeps_too_large_to_write_are_refused_at_once() {
    let dir = scratch("limits-sweep");
    let out = dir.join("out.csv");
    let out = out.to_str().unwrap();
    for (sweep, field, estimate) in [
        (
            "[sweep]\nmode = \"random\"\nsamples = 1000000000000\nseed = 1\n[sweep.vary]\n\"friction.coefficient\" = { from = 0.3, to = 0.9 }\n",
            "sweep.samples = 1000000000000",
            "220.0 TB",
        ),
        (
            "[sweep]\nmode = \"latin-hypercube\"\nsamples = 1000000000000\nseed = 1\n[sweep.vary]\n\"friction.coefficient\" = { from = 0.3, to = 0.9 }\n",
            "sweep.samples = 1000000000000",
            "220.0 TB",
        ),
        (
            "[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"friction.coefficient\" = { from = 0.3, to = 0.9, count = 1000000 }\n\"cycle.point1.normal\" = { from = 900.0, to = 1100.0, count = 1000000 }\n",
            "the grid's 1000000 x 1000000 rows",
            "240.0 TB",
        ),
    ] {
        let path = spec(&dir, sweep);
        let o = run_briefly(&["sweep", &path, "-o", out]);
        assert_refused(&o, &[field, estimate, "limit of 100.0 GB"]);
        assert!(!Path::new(out).exists() && !Path::new(&format!("{out}.part")).exists());
    }
    // The same in Parquet: 8 bytes a number.
    let path = spec(
        &dir,
        "[sweep]\nmode = \"random\"\nsamples = 1000000000000\nseed = 1\n[sweep.vary]\n\"friction.coefficient\" = { from = 0.3, to = 0.9 }\n",
    );
    let parquet = dir.join("out.parquet");
    let o = run_briefly(&["sweep", &path, "-o", parquet.to_str().unwrap()]);
    assert_refused(&o, &["sweep.samples = 1000000000000", "88.0 TB"]);
}

#[test]
fn a_march_sweep_too_long_to_run_is_refused_and_names_its_largest_case() {
    let dir = scratch("limits-march-sweep");
    // Two rows, each bounded by its largest case: 400000² x 300 increments x 5e-10 s = 24000 s.
    let path = spec(
        &dir,
        "[history]\nkind = \"cycle\"\ncycles = 3\nsteps_per_half = 45\nramp_steps = 15\n[solver]\ncells = 400\n\
         [sweep]\nmode = \"grid\"\nanalysis = \"march\"\n[sweep.vary]\n\"solver.cells\" = [100, 400000]\n",
    );
    let out = dir.join("out.csv");
    let o = run_briefly(&["sweep", &path, "-o", out.to_str().unwrap()]);
    assert_refused(
        &o,
        &["the grid's 2 rows", "13.3 hours", "limit of 8.0 hours"],
    );
}

#[test]
fn a_wear_sweep_is_estimated_by_its_bound_on_marched_cycles() {
    let dir = scratch("limits-wear-sweep");
    // The partial-slip example (400 cells, a ramp of 10 and cycles of 40 increments, 1e6 cycles,
    // 7 checkpoints, the default bound 0.01), 2000 rows. The cycles a row marches are not known
    // before it runs: the estimate takes min(1e6, 100 / 0.01 + 7) = 10007 marched cycles, each
    // 400² x 40 x 5e-10 s = 3.2 ms, plus the ramp and the case: 32.02 s a row, 17.8 hours in all
    // (the run itself marches 78 cycles a row).
    let base = std::fs::read_to_string(example("wear-partial-slip.toml")).unwrap();
    let path = dir.join("spec.toml");
    std::fs::write(
        &path,
        format!("{base}[sweep]\nmode = \"grid\"\nanalysis = \"wear\"\n[sweep.vary]\n\"wear.coefficient\" = {{ from = 1e-8, to = 1e-7, count = 2000 }}\n"),
    )
    .unwrap();
    let out = dir.join("out.csv");
    let o = run_briefly(&["sweep", path.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_refused(
        &o,
        &[
            "the grid's 2000 rows",
            "17.8 hours",
            "100 / max_depth_increment cycles",
        ],
    );
}

/// A steady grid of 20,000 rows: about 4 MB of CSV, more than the writer's 1 MB buffer, so
/// writes fail part-way when the output is a full disk.
const MID_SIZE_GRID: &str = "[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"cycle.point1.normal\" = { from = 900.0, to = 1100.0, count = 20000 }\n";

#[test]
fn a_sweep_that_fails_part_way_removes_its_part_file_and_says_so() {
    let dir = scratch("limits-full");
    let path = spec(&dir, MID_SIZE_GRID);
    let out = dir.join("out.csv");
    let part = dir.join("out.csv.part");
    // The .part file is a link to /dev/full: every write that reaches it fails with ENOSPC.
    std::os::unix::fs::symlink("/dev/full", &part).unwrap();
    let o = run_briefly(&["sweep", &path, "-o", out.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("removed the incomplete output") && err.contains("out.csv.part"),
        "{err}"
    );
    assert!(err.contains("No space left on device"), "{err}");
    assert!(part.symlink_metadata().is_err(), "the .part file is left");
    assert!(!out.exists());
}

#[test]
fn an_interrupted_sweep_removes_its_part_file_and_says_so() {
    let dir = scratch("limits-ctrl-c");
    // 10^8 rows: 22 GB and about 1.4 hours of one core, under the limits; interrupted once it is
    // writing.
    let path = spec(
        &dir,
        "[sweep]\nmode = \"random\"\nsamples = 100000000\nseed = 1\n[sweep.vary]\n\"friction.coefficient\" = { from = 0.3, to = 0.9 }\n",
    );
    let out = dir.join("out.csv");
    let part = dir.join("out.csv.part");
    let (child, lines, rest) = start_until(
        &["sweep", &path, "-o", out.to_str().unwrap()],
        "0.2",
        "sweep: ",
    );
    assert!(part.exists(), "{lines:?}");
    interrupt(&child);
    let status = wait_status(child, 30);
    assert_eq!(status.code(), Some(2), "{status:?}");
    assert!(!part.exists(), "the .part file is left");
    assert!(!out.exists());
    let rest: Vec<String> = rest.iter().collect();
    let said = format!(
        "interrupted: removed the incomplete output {}",
        part.display()
    );
    assert!(rest.contains(&said), "{rest:?}");
}

#[test]
fn a_sweep_reports_progress_on_stderr_when_it_is_not_a_terminal() {
    let dir = scratch("limits-sweep-progress");
    let path = spec(&dir, MID_SIZE_GRID);
    let out = dir.join("out.csv");
    let o = command(&["sweep", &path, "-o", out.to_str().unwrap()])
        .env("HALFPLANE_PROGRESS_SECONDS", "0")
        .output()
        .unwrap();
    let err = stderr(&o);
    assert!(o.status.success(), "{err}");
    let progress: Vec<&str> = err.lines().filter(|l| l.starts_with("sweep: ")).collect();
    assert!(!progress.is_empty(), "{err}");
    assert!(
        progress.last().unwrap().contains("20000/20000 rows (100%)"),
        "{err}"
    );
    assert!(err.contains("wrote 20000 rows"), "{err}");
}

#[test]
fn an_empty_list_of_values_is_named_as_written() {
    let dir = scratch("limits-empty-vary");
    let out = dir.join("out.csv");
    let path = spec(
        &dir,
        "[sweep]\nmode = \"grid\"\n[sweep.vary]\n\"profile.radius\" = []\n",
    );
    let o = run_briefly(&["sweep", &path, "-o", out.to_str().unwrap()]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("sweep.vary.\"profile.radius\" = [] is an empty list"),
        "{err}"
    );
    assert!(!err.contains("= 0:"), "{err}");
    let path = spec(&dir, "[sweep]\nmode = \"grid\"\nvary = []\n");
    let o = run_briefly(&["sweep", &path, "-o", out.to_str().unwrap()]);
    let err = stderr(&o);
    assert!(
        err.contains("invalid sweep.vary = []: must be a table"),
        "{err}"
    );
}
