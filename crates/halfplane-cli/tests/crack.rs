//! End-to-end tests of `halfplane crack`: the public columns and JSON keys on the bundled
//! example, and bad `[crack]` input (exit 2 naming the field, the value and what is valid).

mod common;
use common::*;

#[test]
fn example_rows_columns_and_verdict() {
    let o = run(&["crack", &example("crack.toml"), "--csv"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let mut lines = out.lines();
    assert_eq!(
        lines.next().unwrap(),
        "length,k1_max,k1_min,k2_max,k2_min,delta_k1,delta_k2,delta_k_eff,threshold"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 20);
    assert!((rows[0][0] - 0.002).abs() < 1e-15 && (rows[19][0] - 0.3).abs() < 1e-15);
    for r in &rows {
        assert!(r[2] >= 0.0, "K_I never negative: {r:?}");
        assert!((r[5] - (r[1] - r[2])).abs() < 1e-9 * r[1].max(1.0));
        assert!((r[6] - (r[3] - r[4])).abs() < 1e-9 * r[3].abs().max(1.0));
    }
    let o = run(&["crack", &example("crack.toml"), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["rows"].as_array().unwrap().len(), 20);
    let verdict = v["verdict"].as_str().unwrap();
    assert!(["arrests", "propagates", "no-growth"].contains(&verdict));
    assert_eq!(v["arrest_length"].is_null(), verdict != "arrests");
    assert_eq!(v["intensity_unit"], "MPa sqrt(mm)");
    // The default position is an edge of the contact (a = 0.761 mm).
    assert!((v["position"].as_f64().unwrap().abs() - 0.7611).abs() < 1e-3);
}

#[test]
fn bad_crack_input_exits_2_naming_the_field() {
    let dir = scratch("crack-bad");
    let base = std::fs::read_to_string(examples().join("crack.toml")).unwrap();
    let lengths = "lengths = { from = 0.002, to = 0.3, count = 20 }";
    let cases = [
        ("angle = 0.0", "angle = 90.0", "crack.angle = 90"),
        ("angle = 0.0", "angle = -95.0", "crack.angle = -95"),
        ("angle = 0.0", "angle = \"sideways\"", "crack.angle"),
        (
            "face_friction = 0.0",
            "face_friction = -0.1",
            "crack.face_friction = -0.1",
        ),
        (lengths, "lengths = [0.01, -0.02]", "crack.lengths = -0.02"),
        (lengths, "lengths = [0.0]", "crack.lengths = 0"),
        (lengths, "lengths = [0.02, 0.01]", "crack.lengths[1] = 0.01"),
        (lengths, "lengths = [0.01, 5.0]", "crack.lengths = 5"),
        (
            lengths,
            "lengths = { from = 0.3, to = 0.1, count = 5 }",
            "crack.lengths",
        ),
        (
            lengths,
            "lengths = { from = 0.01, to = 0.1, count = 1 }",
            "crack.lengths.count = 1",
        ),
        (
            "angle = 0.0",
            "angle = 0.0\nposition = \"middle\"",
            "crack.position",
        ),
        (
            "angle = 0.0",
            "angle = 0.0\nposition = 1e40",
            "crack.position",
        ),
        (
            "angle = 0.0",
            "angle = 0.0\nradius = 3.0",
            "unknown field crack.radius",
        ),
        (
            "threshold = 160.0 ",
            "",
            "fatigue.threshold and fatigue.endurance_range",
        ),
        // A point below the surface: the crack starts on the surface, at an x.
        (
            "angle = 0.0",
            "angle = 0.0\nposition = [0.1, 0.05]",
            "crack.position = [0.1, 0.05]",
        ),
        (
            "angle = 0.0",
            "angle = \"critical-plane\"\ninitiation_parameter = \"crossland\"",
            "crack.initiation_parameter = \"crossland\"",
        ),
        (
            "angle = 0.0",
            "angle = \"critical-plane\"\ninitiation_parameter = \"swat\"",
            "crack.initiation_parameter = \"swat\"",
        ),
        (
            "angle = 0.0",
            "angle = 10.0\ninitiation_parameter = \"swt\"",
            "crack.initiation_parameter is used only with angle = \"critical-plane\"",
        ),
    ];
    for (from, to, expect) in cases {
        assert!(base.contains(from), "{from}");
        let path = dir.join("case.toml");
        std::fs::write(&path, base.replacen(from, to, 1)).unwrap();
        let o = run(&["crack", path.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{to}: {}", stdout(&o));
        let e = stderr(&o);
        assert!(e.contains(expect), "{to}: {e}");
        assert!(!e.contains("panicked"), "{e}");
    }
    // No [fatigue] section at all: the threshold's constants are missing.
    let path = dir.join("no-fatigue.toml");
    let (start, end) = (
        base.find("[fatigue]").unwrap(),
        base.find("[crack]").unwrap(),
    );
    std::fs::write(&path, format!("{}{}", &base[..start], &base[end..])).unwrap();
    let o = run(&["crack", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("fatigue.threshold and fatigue.endurance_range"),
        "{}",
        stderr(&o)
    );
    // No [crack] section at all.
    let path = dir.join("none.toml");
    let cut = base.find("[crack]").unwrap();
    std::fs::write(&path, &base[..cut]).unwrap();
    let o = run(&["crack", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing section [crack]"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn critical_plane_angle_is_reported() {
    // angle = "critical-plane" takes the SWT plane at the mouth (here the trailing edge, where
    // the surface is free of traction at the largest load and the plane is close to normal);
    // the report carries the angle it took, strictly inside (-90, 90).
    let dir = scratch("crack-plane");
    let base = std::fs::read_to_string(examples().join("crack.toml")).unwrap();
    let case = base
        .replacen(
            "angle = 0.0",
            "angle = \"critical-plane\"\ninitiation_parameter = \"findley\"",
            1,
        )
        .replacen("count = 20", "count = 4", 1);
    let path = dir.join("case.toml");
    std::fs::write(&path, case).unwrap();
    let o = run(&["crack", path.to_str().unwrap(), "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let angle = v["angle"].as_f64().unwrap();
    assert!(angle.abs() < 90.0, "{angle}");
    assert_eq!(v["rows"].as_array().unwrap().len(), 4);
}
