//! A batch runs where its caller says: on a thread count or on the caller's own rayon pool, never
//! sized by the environment (the front ends read `HALFPLANE_NUM_THREADS`, the library does not).
//! Its own test binary, because it sets an environment variable for the whole process.

use halfplane::batch::{threads_from_text, Batch, THREADS_VARIABLE};
use halfplane::Error;
use std::ops::ControlFlow;
use std::sync::Arc;

fn squares(batch: &Batch, rows: usize) -> (Vec<u64>, Vec<Option<usize>>) {
    let mut values = Vec::new();
    let mut workers = Vec::new();
    let stopped = batch
        .run(
            rows,
            |i| ((i as u64) * (i as u64), rayon::current_thread_index()),
            |_, part| {
                for (v, w) in part {
                    values.push(v);
                    workers.push(w);
                }
                ControlFlow::<()>::Continue(())
            },
        )
        .expect("runs");
    assert_eq!(stopped, None);
    (values, workers)
}

#[test]
fn the_environment_does_not_size_a_batch_and_a_callers_pool_runs_it() {
    // Before, `Batch::new(None)` read the variable and failed on this value.
    std::env::set_var(THREADS_VARIABLE, "lots");
    let batch = Batch::new(None).expect("the library does not read the environment");
    let expected: Vec<u64> = (0..500u64).map(|i| i * i).collect();
    assert_eq!(squares(&batch, 500).0, expected);

    // The caller's pool of 3 threads solves every row on one of its workers.
    let pool = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(3)
            .build()
            .expect("pool starts"),
    );
    let batch = Batch::in_pool(Arc::clone(&pool))
        .with_chunk_rows(64)
        .expect("valid chunk");
    assert_eq!(batch.threads(), Some(3));
    let (values, workers) = squares(&batch, 500);
    assert_eq!(values, expected, "the same rows whatever runs them");
    assert!(
        workers.iter().all(|w| w.is_some_and(|i| i < 3)),
        "every row on a worker of the caller's pool: {workers:?}"
    );
}

#[test]
fn a_front_end_reads_the_variable_with_the_librarys_parser() {
    // The error each front end gives for a bad value: text, or a count out of range.
    match threads_from_text("lots") {
        Err(Error::InvalidText { field, value, .. }) => {
            assert_eq!((field.as_str(), value.as_str()), (THREADS_VARIABLE, "lots"))
        }
        other => panic!("{other:?}"),
    }
    assert!(matches!(
        threads_from_text("0"),
        Err(Error::InvalidCount { field, .. }) if field == THREADS_VARIABLE
    ));
    assert_eq!(threads_from_text(" 2 ").ok(), Some(Some(2)));
    assert_eq!(threads_from_text("").ok(), Some(None));
}
