//! Errors seen through the public API: inputs that go together value by value and differ in
//! length are refused with `Error::LengthMismatch` carrying both lengths (they were reported as
//! a count or a table problem before), and errors classify themselves for front ends.

use halfplane::error::{one_of_each, ErrorKind};
use halfplane::stress::Traction;
use halfplane::{Error, Profile};

fn lengths(result: Result<impl std::fmt::Debug, Error>) -> (String, usize, usize) {
    match result {
        Err(Error::LengthMismatch {
            field,
            length,
            expected,
            per,
        }) => {
            assert!(!per.is_empty());
            (field, length, expected)
        }
        other => panic!("expected a length mismatch, got {other:?}"),
    }
}

#[test]
fn a_profile_table_with_fewer_gaps_than_positions_is_a_length_mismatch() {
    let x = vec![0.0, 0.5, 1.0, 1.5];
    let g = vec![0.0, 0.1, 0.4];
    assert_eq!(
        lengths(Profile::tabulated(x, g, vec![])),
        ("g".to_string(), 3, 4)
    );
}

#[test]
fn traction_values_of_the_wrong_length_are_a_length_mismatch() {
    let x = [-1.0, 0.0, 1.0];
    assert_eq!(
        lengths(Traction::piecewise_linear(
            &x,
            &[0.0, 1.0],
            &[0.0, 0.0, 0.0]
        )),
        ("traction pressure".to_string(), 2, 3)
    );
    assert_eq!(
        lengths(Traction::piecewise_constant(&x, &[1.0, 1.0], &[0.0])),
        ("traction shear".to_string(), 1, 2),
        "two cells between three edges"
    );
}

#[test]
fn the_message_names_the_input_and_both_lengths() {
    let e = Profile::tabulated(vec![0.0, 0.5, 1.0, 1.5], vec![0.0; 3], vec![]).unwrap_err();
    assert_eq!(e.name(), "LengthMismatch");
    assert_eq!(e.kind(), ErrorKind::Input);
    assert_eq!(
        e.to_string(),
        "invalid g: 3 values, but 4 are needed (one gap g per x)"
    );
}

#[test]
fn every_example_has_a_distinct_name_and_a_message() {
    let examples = one_of_each();
    let mut names: Vec<&str> = examples.iter().map(Error::name).collect();
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), examples.len());
    assert!(examples.iter().all(|e| !e.to_string().is_empty()));
}
