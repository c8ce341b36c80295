//! End-to-end tests of `halfplane plot`: every figure from a bundled example, and bad requests.
//! (The README's figure commands are run by tests/readme.rs.)
#![cfg(feature = "plot")]

mod common;
use common::*;
use std::path::PathBuf;

/// A scratch directory of this test process, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let dir =
            std::env::temp_dir().join(format!("halfplane-cli-plot-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("output directory");
        Self(dir)
    }

    fn out(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Width and height from a PNG's header.
fn png_size(bytes: &[u8]) -> (u32, u32) {
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "not a PNG");
    let word = |i: usize| u32::from_be_bytes(bytes[i..i + 4].try_into().unwrap());
    (word(16), word(20))
}

#[test]
fn every_figure_is_written_with_its_series() {
    let cases: [(&str, &str, &[&str], &[&str]); 5] = [
        (
            "load-space",
            "hertz.toml",
            &[],
            &[
                "trajectory",
                "friction lines ±fP",
                "point 1",
                "left edge S = Q + πaσ/4",
                "normal load P (N/mm)",
            ],
        ),
        (
            "slip-map",
            "hertz.toml",
            &["--ratios", "1,1.2"],
            &[
                "f = 0.3",
                "f = 0.6",
                "P2/P1 = 1.2, Δσ/P1 = 0.02",
                "ΔQ/(f P0)",
            ],
        ),
        (
            "evolution",
            "march-cycle.toml",
            &["--march", "--cells", "100"],
            &[
                "contact edge",
                "stick boundary (exact)",
                "stick boundary (asymptotic)",
                "stick boundary (time marching)",
                "right edge: a and n",
            ],
        ),
        (
            "march-fields",
            "march-cycle.toml",
            &["--steps", "100,150", "--cells", "100"],
            &[
                "q, step 100",
                "slip, step 150",
                "±f p, step 100",
                "traction q (MPa)",
            ],
        ),
        (
            "march-zones",
            "march-history.toml",
            &["--cells", "100"],
            &["contact edges ±a", "stick", "increment"],
        ),
    ];
    let scratch = Scratch::new("figures");
    for (figure, case, extra, needles) in cases {
        let path = scratch.out(&format!("{figure}.svg"));
        let case_path = example(case);
        let mut args = vec![
            "plot",
            figure,
            case_path.as_str(),
            "-o",
            path.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert!(o.status.success(), "{figure}: {}", stderr(&o));
        let svg = std::fs::read_to_string(&path).unwrap();
        for n in needles {
            assert!(svg.contains(n), "{figure}: {n:?} not in the SVG");
        }
    }
    let png = scratch.out("map.png");
    let o = run(&[
        "plot",
        "load-space",
        &example("hertz.toml"),
        "-o",
        png.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(png_size(&std::fs::read(&png).unwrap()).0, 1280);
}

#[test]
fn bad_plot_requests_are_clear_errors() {
    let (hertz, history) = (example("hertz.toml"), example("march-history.toml"));
    let scratch = Scratch::new("bad");
    let (gif, svg) = (scratch.out("x.gif"), scratch.out("y.svg"));
    let (gif, svg) = (gif.to_str().unwrap(), svg.to_str().unwrap());
    let cases: [(&[&str], &[&str]); 6] = [
        (
            &["plot", "pie-chart", &hertz, "-o", svg],
            &[
                "unrecognized subcommand 'pie-chart'",
                "load-space",
                "march-zones",
            ],
        ),
        (
            &["plot", "load-space", &hertz, "-o", "/nonexistent-dir/x.svg"],
            &["cannot write /nonexistent-dir/x.svg"],
        ),
        (
            &["plot", "load-space", &hertz, "-o", gif],
            &[".svg or .png"],
        ),
        (
            &[
                "plot",
                "march-fields",
                &history,
                "--steps",
                "999",
                "-o",
                svg,
            ],
            &["increments 1 to 50"],
        ),
        (&["plot", "march-zones", &hertz, "-o", svg], &["[history]"]),
        (&["plot", "evolution", &history, "-o", svg], &["[cycle]"]),
    ];
    for (args, needles) in cases {
        let o = run(args);
        let err = stderr(&o);
        assert!(!o.status.success(), "{args:?} should fail");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        for n in needles {
            assert!(
                err.contains(n),
                "{args:?}: error does not mention {n:?}: {err}"
            );
        }
    }
}

#[test]
fn the_crack_figure_draws_the_ranges_the_threshold_and_the_crack() {
    // The crack example: ΔK against length on log-log axes (ticks at 1, 2, 5 x 10^k, labelled
    // plainly) beside the sxx map with the crack; the numbers are the crack command's.
    let scratch = Scratch::new("crack");
    let path = scratch.out("crack.svg");
    let case = example("crack.toml");
    let o = run(&[
        "plot",
        "crack",
        &case,
        "-o",
        path.to_str().unwrap(),
        "--cells",
        "200",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&path).unwrap();
    for n in [
        "ΔK effective",
        "ΔK_I",
        "ΔK_II",
        "threshold ΔK_th(l) (El Haddad)",
        "crack length l (mm)",
        "stress intensity range ΔK (MPa √mm)",
        "crack, l = 0.3 mm",
        "\n0.002\n",
        "\n0.01\n",
        "\n0.1\n",
        "σxx (MPa)",
    ] {
        assert!(svg.contains(n), "{n:?} not in the SVG");
    }
    // Without [crack]: the crack command's error.
    let hertz = example("hertz.toml");
    let o = run(&["plot", "crack", &hertz, "-o", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn the_wear_figure_draws_the_checkpoints_and_the_chosen_quantity() {
    // The partial-slip example on a coarse grid (100 cells, to keep the test quick): four
    // panels side by side in the width of three 640-pixel panels.
    let scratch = Scratch::new("wear");
    let case = example("wear-partial-slip.toml");
    let png = scratch.out("wear.png");
    let png = png.to_str().unwrap();
    let o = run(&["plot", "wear", &case, "-o", png, "--cells", "100"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let bytes = std::fs::read(png).unwrap();
    let (width, height) = png_size(&bytes);
    assert_eq!(width, 1920);
    assert!((400..1000).contains(&height), "height {height}");
    assert!(
        bytes.len() > 50_000,
        "{} bytes: too few for four panels",
        bytes.len()
    );
    // One curve per checkpoint (1 to 1e6, seven), the stick zone on the pressure, the chosen
    // column with its unit against cycles on a log axis (ticks 1, 10, ..., 1000000).
    let svg = scratch.out("wear.svg");
    let svg = svg.to_str().unwrap();
    let o = run(&[
        "plot",
        "wear",
        &case,
        "-o",
        svg,
        "--cells",
        "100",
        "--quantity",
        "peak_pressure",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(svg).unwrap();
    for n in [
        "cycle 1\n",
        "cycle 1000\n",
        "cycle 1000000\n",
        "stick zone |x| ≤ ",
        "wear depth, both bodies",
        "depth h (mm)",
        "pressure p (MPa)",
        "fretting loops, colours as the depth&apos;s",
        "shear load Q (N/mm)",
        "relative displacement δ (mm), datum 7.611 mm",
        "peak_pressure at the checkpoints",
        "peak_pressure (MPa)",
        "\n10\n",
        "\n100000\n",
        "\n1000000\n",
    ] {
        assert!(text.contains(n), "{n:?} not in the SVG");
    }
    // A quantity that is not a checkpoint column: exit 2, naming the option and the columns.
    let o = run(&["plot", "wear", &case, "-o", svg, "--quantity", "depth"]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    for n in [
        "--quantity",
        "'depth'",
        "wear_volume",
        "max_depth",
        "energy_per_cycle",
        "dissipated_energy",
        "contact_left",
        "peak_pressure",
        "stick_right",
        "slip_amplitude_max",
    ] {
        assert!(err.contains(n), "error does not mention {n:?}: {err}");
    }
    // Gross sliding has no stick zone: refused before the run, naming what can be drawn.
    let sliding = example("wear-sliding.toml");
    let o = run(&[
        "plot",
        "wear",
        &sliding,
        "-o",
        svg,
        "--quantity",
        "stick_left",
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    for n in ["--quantity stick_left", "no stick zone", "max_depth"] {
        assert!(err.contains(n), "error does not mention {n:?}: {err}");
    }
}
