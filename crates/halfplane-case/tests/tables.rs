//! Tables given in the case itself (`data = """..."""`) against the same tables as files: the
//! same reader, so the same values exactly; and the errors of both forms.

use halfplane::steady::{analyse, SteadyOptions};
use halfplane_case::case::{self, Case};
use std::path::{Path, PathBuf};

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// The example `name` as written, and with its `file = "..."` line replaced by the file's text
/// as `data = """..."""`.
fn both_forms(name: &str) -> (Case, Case) {
    let dir = examples();
    let text = std::fs::read_to_string(dir.join(name)).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("file = "))
        .expect("the example names a table file");
    let file = line.split('"').nth(1).unwrap();
    let csv = std::fs::read_to_string(dir.join(file)).unwrap();
    let inline = text.replace(line, &format!("data = \"\"\"\n{csv}\"\"\""));
    assert!(!inline.contains("file = "), "{inline}");
    let from_file = case::load(&dir.join(name)).unwrap();
    // An empty directory: the inline form reads no file.
    let from_data = case::parse(&inline, Path::new("/nonexistent")).unwrap();
    (from_file, from_data)
}

#[test]
fn a_profile_table_given_as_data_is_the_file_exactly() {
    let (file, data) = both_forms("tabulated.toml");
    assert_eq!(file.contact, data.contact);
    let cycle = file.cycle().unwrap();
    let options = SteadyOptions::default();
    let (a, b) = (
        analyse(&file.contact, &cycle, &options).unwrap(),
        analyse(&data.contact, &cycle, &options).unwrap(),
    );
    assert_eq!(format!("{a:?}"), format!("{b:?}"));
}

#[test]
fn a_history_given_as_data_is_the_file_exactly() {
    let (file, data) = both_forms("march-history.toml");
    let (a, b) = (file.history().unwrap(), data.history().unwrap());
    assert_eq!(a, b);
    let csv = std::fs::read_to_string(examples().join("march-history.csv")).unwrap();
    let rows = csv.lines().filter(|l| !l.starts_with('#')).count() - 1;
    assert_eq!(a.loads().len(), rows);
}

const HEAD: &str =
    "[material]\nyoungs_modulus = 2e5\npoisson_ratio = 0.3\n[friction]\ncoefficient = 0.6\n";

fn error(text: &str) -> String {
    let e = case::parse(text, &examples()).unwrap_err();
    format!("{e:#}")
}

#[test]
fn file_and_data_together_are_an_error_naming_both() {
    let text = format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\nfile = \"tabulated-profile.csv\"\ndata = \"x,g\\n0,0\\n1,1\\n\"\n"
    );
    let e = error(&text);
    assert!(
        e.contains("profile.file") && e.contains("profile.data"),
        "{e}"
    );
    let text = format!(
        "{HEAD}[profile]\nkind = \"hertz\"\nradius = 50.0\n[history]\nfile = \"march-history.csv\"\ndata = \"normal,shear,bulk\\n1,0,0\\n\"\n"
    );
    let e = error(&text);
    assert!(
        e.contains("history.file") && e.contains("history.data"),
        "{e}"
    );
}

#[test]
fn errors_in_data_name_the_field_the_line_the_column_and_the_value() {
    let profile = |data: &str| {
        error(&format!(
            "{HEAD}[profile]\nkind = \"tabulated\"\ndata = \"\"\"\n{data}\"\"\"\n"
        ))
    };
    let e = profile("x,g\n0,0\n# a comment\n0.5,zero\n");
    assert!(
        e.contains("profile.data, line 4: g = \"zero\" is not a number"),
        "{e}"
    );
    let e = profile("x,g\n0,0\n0.5\n");
    assert!(
        e.contains("profile.data, line 3: expected 2 columns"),
        "{e}"
    );
    let e = profile("x,h\n0,0\n");
    assert!(e.contains("profile.data, line 1: header is \"x,h\""), "{e}");
    // The library's check of the table (x must increase), at the line it came from.
    let e = profile("x,g\n0,0\n\n1,1\n0.5,2\n");
    assert!(e.contains("profile.data, line 5"), "{e}");
    let history = format!(
        "{HEAD}[profile]\nkind = \"hertz\"\nradius = 50.0\n[history]\ndata = \"\"\"\nnormal,shear,bulk\n100,0,0\n-5,0,0\n\"\"\"\n"
    );
    let e = error(&history);
    assert!(e.contains("history.data, line 3: normal = -5"), "{e}");
    let e = error(&format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\nkinks = [0.3]\n"
    ));
    assert!(
        e.contains("profile.file") && e.contains("profile.data"),
        "{e}"
    );
}

#[test]
fn data_takes_what_a_file_takes_a_byte_order_mark_and_crlf_line_ends() {
    let text = format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\ndata = \"\\ufeffx,g\\r\\n0,0\\r\\n1,0.01\\r\\n2,0.04\\r\\n\"\n"
    );
    let crlf = case::parse(&text, Path::new(".")).unwrap();
    let plain = format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\ndata = \"x,g\\n0,0\\n1,0.01\\n2,0.04\\n\"\n"
    );
    assert_eq!(
        crlf.contact,
        case::parse(&plain, Path::new(".")).unwrap().contact
    );
}

#[test]
fn a_quote_in_a_comment_does_not_swallow_the_rows_after_it() {
    let table = "x,g\n# the \"flat, to 0.3\n  # indented, \"too\n0,0\n1,0.01\n2,0.04\n";
    let text = format!("{HEAD}[profile]\nkind = \"tabulated\"\ndata = \"\"\"\n{table}\"\"\"\n");
    let commented = case::parse(&text, Path::new(".")).unwrap();
    let plain = format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\ndata = \"x,g\\n0,0\\n1,0.01\\n2,0.04\\n\"\n"
    );
    assert_eq!(
        commented.contact,
        case::parse(&plain, Path::new(".")).unwrap().contact
    );
    // The lines after the comments keep their numbers.
    let bad = table.replace("2,0.04", "2,\"0.04\"");
    let e = error(&format!(
        "{HEAD}[profile]\nkind = \"tabulated\"\ndata = '''\n{bad}'''\n"
    ));
    assert!(
        e.contains("profile.data, line 6: g = \"\"0.04\"\" is not a number"),
        "{e}"
    );
}

#[test]
fn errors_in_a_file_name_the_file_the_line_the_column_and_the_value() {
    let dir = std::env::temp_dir().join(format!("halfplane-case-tables-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("h.csv"),
        "normal,shear,bulk\r\n100,0,0\r\n\r\n200,x,0\r\n",
    )
    .unwrap();
    let text =
        format!("{HEAD}[profile]\nkind = \"hertz\"\nradius = 50.0\n[history]\nfile = \"h.csv\"\n");
    let e = format!("{:#}", case::parse(&text, &dir).unwrap_err());
    std::fs::remove_dir_all(&dir).unwrap();
    let path = dir.join("h.csv");
    let want = format!(
        "history.file {}, line 4: shear = \"x\" is not a number",
        path.display()
    );
    assert!(e.contains(&want), "{e}");
}

#[test]
fn a_bad_value_is_found_at_its_line_whatever_comes_before_it() {
    // Every mix of line ends and skipped lines before a bad row: its line is counted by hand.
    let fillers = ["", "   ", "# note, \"quoted", "\u{feff}", "1,0.5"];
    for end in ["\n", "\r\n"] {
        for (i, a) in fillers.iter().enumerate() {
            for b in &fillers[i..] {
                let mut lines = vec!["x,g", "0,0"];
                lines.extend([*a, *b]);
                let rows = lines.iter().filter(|l| l.starts_with('1')).count();
                if *a == "\u{feff}" || *b == "\u{feff}" {
                    continue; // a byte-order mark only starts a file
                }
                lines.push("2,bad");
                let table = lines.join(end) + end;
                let text =
                    format!("{HEAD}[profile]\nkind = \"tabulated\"\ndata = '''\n{table}'''\n");
                let e = error(&text);
                let want = format!("profile.data, line {}: g = \"bad\"", lines.len());
                assert!(e.contains(&want), "{e} ({rows} rows, {table:?})");
            }
        }
    }
}
