//! The matching equations (docs/matching.md, "Method"): the test half-width from `K_N`
//! (eq. (31)), then Q and sigma from `K_T` (eq. (32)) or from the stick-zone equations (16) and
//! (23) with the prototype's slip zones.

use super::report::Side;
use super::{LoadIndex, MatchConstraint, MatchSide};
use crate::asymptotic::EdgeState;
use crate::error::{Error, Result};
use crate::labels::{Edge, GivenPoint, PerPoint};
use crate::load::{Cycle, LoadPoint};
use crate::normal::Contact;
use crate::roots::{bracket_positive, brent, Bracket};
use crate::steady::StickZone;
use std::f64::consts::PI;

/// Relative tolerance of the test half-width: a few rounding units (`K_N` varies like a power
/// of a, so K_N is then matched to about the same relative accuracy).
const HALF_WIDTH_TOLERANCE: f64 = 1e-15;

/// Doublings and halvings tried from the starting half-width when bracketing `K_N`: 2^110 either
/// way covers every half-width the magnitude limit 1e30 allows.
const BRACKET_STEPS: usize = 110;

/// The test contact half-width whose `K_N = (1/pi) sqrt(2/a) dP/da` (eq. (31)) equals `target`,
/// by Brent's method on `K_N(a)/target - 1`, bracketed from `start` by doubling and halving.
///
/// Errors: [`Error::MatchNotBracketed`] when `K_N` never crosses the target (for example a power
/// law with exponent 3/2, whose `K_N` does not depend on the load).
pub(crate) fn matched_half_width(
    test: &Contact,
    target: f64,
    start: f64,
    load: LoadIndex,
) -> Result<f64> {
    let residual = |a: f64| -> Result<f64> { Ok(test.normal_intensity(a)? / target - 1.0) };
    match bracket_positive(residual, start, BRACKET_STEPS)? {
        Bracket::Found(lo, hi) => brent(residual, lo, hi, HALF_WIDTH_TOLERANCE),
        Bracket::NotFound { low, high } => Err(Error::MatchNotBracketed {
            load,
            target,
            searched: [low, high],
        }),
    }
}

/// Normal load and half-width of the test at the prototype's `K_N` at `edge`, starting the
/// search from `start`.
fn matched_normal(
    test: &Contact,
    proto: &EdgeState,
    edge: Edge,
    start: f64,
    load: LoadIndex,
) -> Result<(f64, f64)> {
    let target = proto.contact.normal_intensity(edge);
    let a = matched_half_width(test, target, start, load)?;
    Ok((test.load(a)?, a))
}

/// The test load with the prototype's `K_N` and, at both edges, its `K_T`
/// (docs/matching.md, "Asymptotic match"). With the test half-width `a'` from eq. (31), equal
/// `K_T = Q/(pi sqrt(2a)) +/- (sigma/4) sqrt(a/2)` (eq. (32)) at both edges means equal sum and
/// difference of the two, so `Q' = Q sqrt(a'/a)` and `sigma' = sigma sqrt(a/a')`; then
/// `S' = S sqrt(a'/a)` at each edge (eq. (33)). Sign convention of [`crate::asymptotic`].
///
/// `start` is the half-width the `K_N` search starts from (the prototype's when `None`).
/// Returns the test load (named by `index` in errors) and its contact half-width `a'`.
/// Errors: [`Error::MatchNotBracketed`], or the edge description's own (`K_N` not > 0).
pub fn map_point(
    prototype: &Contact,
    test: &Contact,
    load: &LoadPoint,
    index: LoadIndex,
    start: Option<f64>,
) -> Result<(LoadPoint, f64)> {
    map_point_at(prototype, test, load, index, start, Edge::Left)
}

/// [`map_point`] with the test's `K_N` from the prototype's at `matched` (the same at both edges
/// without a moment on a symmetric profile).
pub fn map_point_at(
    prototype: &Contact,
    test: &Contact,
    load: &LoadPoint,
    index: LoadIndex,
    start: Option<f64>,
    matched: Edge,
) -> Result<(LoadPoint, f64)> {
    let edge = EdgeState::at(prototype, load)?;
    let (normal, a) = matched_normal(
        test,
        &edge,
        matched,
        start.unwrap_or(edge.half_width),
        index,
    )?;
    let ratio = (a / edge.half_width).sqrt();
    let point = LoadPoint::new(
        &index.to_string(),
        normal,
        load.shear() * ratio,
        load.bulk() / ratio,
    )?;
    Ok((point, a))
}

/// Every load of a prototype history mapped by [`map_point`] (the asymptotic match, row by row);
/// each search starts from the previous row's test half-width. Errors name the 1-based row.
pub fn map_history(
    prototype: &Contact,
    test: &Contact,
    loads: &[LoadPoint],
) -> Result<Vec<LoadPoint>> {
    map_history_at(prototype, test, loads, Edge::Left)
}

/// [`map_history`] with each row's `K_N` taken at the prototype's edge `matched`
/// ([`map_point_at`]).
pub fn map_history_at(
    prototype: &Contact,
    test: &Contact,
    loads: &[LoadPoint],
    matched: Edge,
) -> Result<Vec<LoadPoint>> {
    let mut start = None;
    loads
        .iter()
        .enumerate()
        .map(|(i, load)| {
            let (point, a) =
                map_point_at(prototype, test, load, LoadIndex::Row(i + 1), start, matched)?;
            start = Some(a);
            Ok(point)
        })
        .collect()
}

/// The asymptotic test cycle: each point mapped by [`map_point`].
pub(super) fn asymptotic_cycle(proto: &Side, test: &Contact) -> Result<Cycle> {
    let [first, second] = GivenPoint::BOTH.map(|p| {
        map_point_at(
            &proto.contact,
            test,
            &proto.point(p),
            LoadIndex::Point(p),
            None,
            proto.edge,
        )
        .map(|(point, _)| point)
    });
    Ok(Cycle::new(first?, second?))
}

/// The exact test cycle (docs/matching.md, "Exact match").
///
/// 1. P'_i from `K_N` at each point, as in the asymptotic match (eq. (31)).
/// 2. The prototype's slip zones `w` at the second point (as given) and the test's half-width
///    there fix the test's stick zone: `m' = a'_2 - w_left`, `n' = a'_2 - w_right`. The stick-zone
///    equations, linear in the ranges once `(d', e')` is known, then give them:
///    eq. (16) `dsigma' = -8 f' J0(d', e')/(pi A')` and eq. (23)
///    `dQ' = f'(P'_1 + P'_2) - pi e' dsigma'/4 - (2 f'/A') J1(d', e')`, with
///    `J0 = integral_0^pi g'(e + d cos t) dt`, `J1 = integral_0^pi xi g'(xi) dt`.
/// 3. The mean of `K_T` (eq. (32)) over the two points at each edge equal to the prototype's:
///    the mean of the edges' sum fixes Q at the smaller-Q end, their difference sigma there.
///
/// The point that has the smaller Q in the prototype has it in the test too. The caller analyses
/// the cycle returned ([`crate::steady::analyse`]: sliding, slip direction along both halves).
///
/// Errors: [`Error::NoValidMatch`] when the stick zone asked for is not inside the smaller test
/// contact or needs `dQ' <= 0` (full stick); [`Error::MatchNotBracketed`] from step 1.
pub(super) fn exact_cycle(proto: &Side, test: &Contact) -> Result<Cycle> {
    let f = test.friction.value();
    let a_comp = test.compliance().value();
    let mut half_width = PerPoint::<f64>::default();
    let mut normal = PerPoint::<f64>::default();
    for p in GivenPoint::BOTH {
        let edge = &proto.edges[p];
        (normal[p], half_width[p]) =
            matched_normal(test, edge, proto.edge, edge.half_width, LoadIndex::Point(p))?;
    }
    let slip = proto.slip_zones();
    let zone = StickZone {
        left: -(half_width.second - slip.left.second),
        right: half_width.second - slip.right.second,
    };
    let smaller = half_width.first.min(half_width.second);
    if !(-smaller < zone.left && zone.left < zone.right && zone.right < smaller) {
        return Err(Error::NoValidMatch {
            side: MatchSide::Test,
            constraint: MatchConstraint::StickZoneOutsideContact,
            cause: Some(Box::new(Error::StickZoneOutsideContact {
                left: zone.left,
                right: zone.right,
                common: [-smaller, smaller],
            })),
        });
    }
    let (d, e) = (zone.half_width(), zone.eccentricity());
    let s = test.profile.stick_integrals(d, e)?;
    let bulk_range = -8.0 * f * s.j0 / (PI * a_comp);
    let shear_range =
        f * (normal.first + normal.second) - PI * e * bulk_range / 4.0 - 2.0 * f / a_comp * s.j1;
    if shear_range.is_nan() || shear_range <= 0.0 {
        return Err(Error::NoValidMatch {
            side: MatchSide::Test,
            constraint: MatchConstraint::FullStick,
            cause: None,
        });
    }
    // Step 3, with `low` the point of smaller Q in the prototype: Q_high = Q_low + dQ',
    // sigma_high = sigma_low - dsigma'.
    let low = if proto.cycle.swapped() {
        GivenPoint::Second
    } else {
        GivenPoint::First
    };
    let high = other(low);
    let mean =
        |f: &dyn Fn(&EdgeState) -> f64| 0.5 * (f(&proto.edges.first) + f(&proto.edges.second));
    let mean_shear = mean(&|s| 0.5 * (s.shear_intensity.left + s.shear_intensity.right));
    let mean_bulk = mean(&|s| 0.5 * (s.shear_intensity.left - s.shear_intensity.right));
    // K_T sum term Q c(a), difference term sigma s(a) (eq. (32)).
    let c = half_width.map(|a| 1.0 / (PI * (2.0 * a).sqrt()));
    let t = half_width.map(|a| 0.25 * (0.5 * a).sqrt());
    let mut shear = PerPoint::<f64>::default();
    let mut bulk = PerPoint::<f64>::default();
    shear[low] = (2.0 * mean_shear - shear_range * c[high]) / (c[low] + c[high]);
    shear[high] = shear[low] + shear_range;
    bulk[low] = (2.0 * mean_bulk + bulk_range * t[high]) / (t[low] + t[high]);
    bulk[high] = bulk[low] - bulk_range;
    let [first, second] = GivenPoint::BOTH.map(|p| {
        LoadPoint::new(
            &LoadIndex::Point(p).to_string(),
            normal[p],
            shear[p],
            bulk[p],
        )
    });
    Ok(Cycle::new(first?, second?))
}

fn other(p: GivenPoint) -> GivenPoint {
    match p {
        GivenPoint::First => GivenPoint::Second,
        GivenPoint::Second => GivenPoint::First,
    }
}
