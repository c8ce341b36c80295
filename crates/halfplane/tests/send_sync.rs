//! The public types can be shared between threads (a sweep driver runs one analysis per thread
//! and sends the results back). Checked at compile time: adding an `Rc` or a `Cell` to any of
//! them breaks this build, not a caller's.

use halfplane::evolution::Evolution;
use halfplane::history::History;
use halfplane::march::{MarchOptions, MarchResult};
use halfplane::{
    Contact, Cycle, Edge, Error, GivenPoint, Half, LoadPoint, PerEdge, PerPoint, Profile,
    SteadyState,
};

const fn assert_send_sync<T: Send + Sync>() {}

const _: () = {
    assert_send_sync::<Contact>();
    assert_send_sync::<Profile>();
    assert_send_sync::<Cycle>();
    assert_send_sync::<LoadPoint>();
    assert_send_sync::<History>();
    assert_send_sync::<SteadyState>();
    assert_send_sync::<Evolution>();
    assert_send_sync::<MarchResult>();
    assert_send_sync::<MarchOptions>();
    assert_send_sync::<Error>();
    assert_send_sync::<Edge>();
    assert_send_sync::<GivenPoint>();
    assert_send_sync::<Half>();
    assert_send_sync::<PerEdge<f64>>();
    assert_send_sync::<PerPoint<f64>>();
};

/// The compile-time assertions above are the test; this one also moves a contact into a thread
/// and an analysis result out of it.
#[test]
fn an_analysis_runs_on_another_thread() {
    let contact = halfplane::reference::hertz();
    let cycle = halfplane::reference::cycle();
    let state = std::thread::spawn(move || {
        halfplane::steady::analyse(&contact, &cycle, &halfplane::SteadyOptions::default())
    })
    .join()
    .unwrap()
    .unwrap();
    assert_eq!(
        state,
        halfplane::steady::analyse(
            &halfplane::reference::hertz(),
            &halfplane::reference::cycle(),
            &halfplane::SteadyOptions::default()
        )
        .unwrap()
    );
}
