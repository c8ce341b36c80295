//! Designs of experiments for sweeps: which values each varied input takes in each row.
//!
//! Three plans:
//! - **grid**: every combination of the axes' values, the first axis outermost (it changes
//!   slowest) and the last innermost;
//! - **random**: `samples` rows, each value drawn independently and uniformly (on a linear or a
//!   logarithmic scale) from its range, or uniformly from its list;
//! - **Latin hypercube**: `samples` rows; along every axis the rows fall one in each of `samples`
//!   equal strata (of the range, on its scale), at a uniformly random place inside the stratum.
//!
//! Every value is a pure function of `(seed, row, axis)`, so any subset of rows (a shard of a
//! cluster job, a chunk of a thread pool) is computed alone and agrees with the whole sweep:
//! - uniform numbers come from a counter-based generator, `unit(seed, stream, row)`: three rounds of
//!   the SplitMix64 finaliser (Steele, Lea & Flood, "Fast splittable pseudorandom number
//!   generators", OOPSLA 2014), mixing in the seed, the stream (one per axis and purpose) and the
//!   row in turn, with the top 53 bits scaled to [0, 1);
//! - the Latin-hypercube stratum of row `i` along an axis is `π(i)`, where `π` is a bijection of
//!   `0..samples` keyed by `(seed, axis)`: a balanced four-round Feistel network on the smallest
//!   power-of-four domain holding `samples` (bijective whatever its round function), restricted to
//!   `0..samples` by cycle-walking (apply it again until the result is in range; Black & Rogaway,
//!   "Ciphers with arbitrary finite domains", CT-RSA 2002). The domain is less than four times
//!   `samples`, so a row takes fewer than four walks on average, and no array of `samples`
//!   entries is ever built.
//!
//! The numbers are reproducible across machines, thread counts and shardings: only integer
//! arithmetic, `ln`, `exp` and IEEE multiplication and addition enter a value.

mod counter;

use crate::error::{physical, Error, Result};
use counter::{stream, unit, Permutation, JITTER};

/// The most rows a design may have: 2^53, so that every row index is exact as a float.
pub const MAX_ROWS: u64 = 1 << 53;

/// The most values an axis may list, or steps a grid axis may take.
pub const MAX_AXIS_VALUES: usize = 1 << 24;

/// How a range is spanned.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Evenly in the value.
    Linear,
    /// Evenly in the logarithm of the value (both ends > 0).
    Log,
}

/// A closed range of values `from <= to` on a scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Range {
    from: f64,
    to: f64,
    scale: Scale,
}

impl Range {
    /// The range `[from, to]`; `field` names it in errors.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for an end that is not finite or exceeds 1e30 in magnitude;
    /// [`Error::InvalidRange`] for `from > to`, or a logarithmic scale with an end at or below 0.
    pub fn new(field: &str, from: f64, to: f64, scale: Scale) -> Result<Self> {
        physical(&format!("{field}.from"), from)?;
        physical(&format!("{field}.to"), to)?;
        let problem = if from > to {
            Some("from must not exceed to")
        } else if scale == Scale::Log && from <= 0.0 {
            Some("scale = \"log\" needs both ends > 0 (a logarithmic scale cannot reach or cross zero); use scale = \"linear\"")
        } else {
            None
        };
        match problem {
            Some(problem) => Err(Error::InvalidRange {
                field: field.to_string(),
                from,
                to,
                problem,
            }),
            None => Ok(Self { from, to, scale }),
        }
    }

    /// The first end.
    pub fn from(&self) -> f64 {
        self.from
    }

    /// The last end.
    pub fn to(&self) -> f64 {
        self.to
    }

    /// The scale.
    pub fn scale(&self) -> Scale {
        self.scale
    }

    /// The value at fraction `t` of the range (0: `from`, 1: `to`), on its scale; the ends are
    /// returned exactly and every value lies inside the range.
    pub fn at(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return self.from;
        }
        if t >= 1.0 {
            return self.to;
        }
        let v = match self.scale {
            Scale::Linear => self.from + (self.to - self.from) * t,
            Scale::Log => {
                let (l0, l1) = (self.from.ln(), self.to.ln());
                (l0 + (l1 - l0) * t).exp()
            }
        };
        v.clamp(self.from, self.to)
    }
}

/// An axis of a grid: listed values, or `count` values spanning a range, both ends included.
#[derive(Debug, Clone, PartialEq)]
pub enum GridAxis {
    /// The values, in the order given.
    List(Vec<f64>),
    /// `count` values from `from` to `to` on the range's scale (`count = 1`: `from` alone).
    Steps(Range, usize),
}

/// An axis of a random or Latin-hypercube design: a range, or listed values picked with equal
/// probability (in a Latin hypercube, each in an equal share of the strata).
#[derive(Debug, Clone, PartialEq)]
pub enum SampledAxis {
    /// The values to choose from.
    List(Vec<f64>),
    /// A range, sampled on its scale.
    Range(Range),
}

/// Which plan a design follows.
#[derive(Debug, Clone, PartialEq)]
enum Plan {
    Grid(Vec<GridAxis>),
    Random {
        axes: Vec<SampledAxis>,
        seed: u64,
    },
    Latin {
        axes: Vec<SampledAxis>,
        seed: u64,
        permutations: Vec<Permutation>,
    },
}

/// A validated design: its rows and, for any row, the value of every axis.
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    plan: Plan,
    rows: u64,
}

fn check_list(field: &str, values: &[f64]) -> Result<()> {
    if values.is_empty() || values.len() > MAX_AXIS_VALUES {
        return Err(Error::InvalidCount {
            field: field.to_string(),
            value: values.len() as u64,
            min: 1,
            max: MAX_AXIS_VALUES as u64,
        });
    }
    for v in values {
        physical(field, *v)?;
    }
    Ok(())
}

fn check_samples(samples: u64) -> Result<u64> {
    if samples == 0 || samples > MAX_ROWS {
        return Err(Error::InvalidCount {
            field: "sweep.samples".into(),
            value: samples,
            min: 1,
            max: MAX_ROWS,
        });
    }
    Ok(samples)
}

impl Design {
    /// Every combination of the axes' values; `names` (one per axis) name them in errors.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for an empty list or a count of 0 (or above
    /// [`MAX_AXIS_VALUES`]), or more than [`MAX_ROWS`] combinations; [`Error::InvalidInput`] for
    /// a listed value that is not finite.
    pub fn grid(names: &[&str], axes: Vec<GridAxis>) -> Result<Self> {
        let mut rows: u64 = 1;
        for (name, axis) in names.iter().zip(&axes) {
            let n = match axis {
                GridAxis::List(values) => {
                    check_list(name, values)?;
                    values.len()
                }
                GridAxis::Steps(_, count) => {
                    if *count == 0 || *count > MAX_AXIS_VALUES {
                        return Err(Error::InvalidCount {
                            field: format!("{name}.count"),
                            value: *count as u64,
                            min: 1,
                            max: MAX_AXIS_VALUES as u64,
                        });
                    }
                    *count
                }
            };
            rows = rows
                .checked_mul(n as u64)
                .filter(|&r| r <= MAX_ROWS)
                .ok_or_else(|| Error::InvalidCount {
                    field: "sweep (the product of the grid's counts)".into(),
                    value: rows.saturating_mul(n as u64),
                    min: 1,
                    max: MAX_ROWS,
                })?;
        }
        Ok(Self {
            plan: Plan::Grid(axes),
            rows,
        })
    }

    /// `samples` rows of independent uniform values.
    ///
    /// # Errors
    /// [`Error::InvalidCount`] for `samples` outside 1..=[`MAX_ROWS`] or an empty list;
    /// [`Error::InvalidInput`] for a listed value that is not finite.
    pub fn random(names: &[&str], axes: Vec<SampledAxis>, samples: u64, seed: u64) -> Result<Self> {
        check_sampled(names, &axes)?;
        Ok(Self {
            rows: check_samples(samples)?,
            plan: Plan::Random { axes, seed },
        })
    }

    /// A Latin hypercube of `samples` rows.
    ///
    /// # Errors
    /// As [`Design::random`].
    pub fn latin_hypercube(
        names: &[&str],
        axes: Vec<SampledAxis>,
        samples: u64,
        seed: u64,
    ) -> Result<Self> {
        check_sampled(names, &axes)?;
        let samples = check_samples(samples)?;
        let permutations = (0..axes.len())
            .map(|j| Permutation::new(samples, seed, j as u64))
            .collect();
        Ok(Self {
            rows: samples,
            plan: Plan::Latin {
                axes,
                seed,
                permutations,
            },
        })
    }

    /// The number of rows.
    pub fn rows(&self) -> u64 {
        self.rows
    }

    /// The number of axes.
    pub fn axes(&self) -> usize {
        match &self.plan {
            Plan::Grid(axes) => axes.len(),
            Plan::Random { axes, .. } | Plan::Latin { axes, .. } => axes.len(),
        }
    }

    /// The values of row `row` (0-based, below [`Design::rows`]), one per axis, into `out`
    /// (whose length must be [`Design::axes`]).
    pub fn values(&self, row: u64, out: &mut [f64]) {
        match &self.plan {
            Plan::Grid(axes) => {
                let mut rest = row;
                for (axis, slot) in axes.iter().zip(out.iter_mut()).rev() {
                    let n = match axis {
                        GridAxis::List(v) => v.len(),
                        GridAxis::Steps(_, count) => *count,
                    } as u64;
                    let k = (rest % n) as usize;
                    rest /= n;
                    *slot = match axis {
                        GridAxis::List(v) => v[k],
                        GridAxis::Steps(range, count) if *count > 1 => {
                            range.at(k as f64 / (*count - 1) as f64)
                        }
                        GridAxis::Steps(range, _) => range.from(),
                    };
                }
            }
            Plan::Random { axes, seed } => {
                for (j, (axis, slot)) in axes.iter().zip(out.iter_mut()).enumerate() {
                    *slot = pick(axis, unit(*seed, stream(j, JITTER), row));
                }
            }
            Plan::Latin {
                axes,
                seed,
                permutations,
            } => {
                for (j, ((axis, perm), slot)) in axes
                    .iter()
                    .zip(permutations)
                    .zip(out.iter_mut())
                    .enumerate()
                {
                    let stratum = perm.apply(row) as f64;
                    let jitter = unit(*seed, stream(j, JITTER), row);
                    let t = ((stratum + jitter) / self.rows as f64).min(ONE_BELOW);
                    *slot = pick(axis, t);
                }
            }
        }
    }
}

fn check_sampled(names: &[&str], axes: &[SampledAxis]) -> Result<()> {
    for (name, axis) in names.iter().zip(axes) {
        if let SampledAxis::List(values) = axis {
            check_list(name, values)?;
        }
    }
    Ok(())
}

/// The largest float below 1.
const ONE_BELOW: f64 = 1.0 - f64::EPSILON / 2.0;

/// The value of a sampled axis at uniform `t` in [0, 1).
fn pick(axis: &SampledAxis, t: f64) -> f64 {
    match axis {
        SampledAxis::Range(range) => range.at(t),
        SampledAxis::List(values) => {
            let k = ((t * values.len() as f64) as usize).min(values.len() - 1);
            values[k]
        }
    }
}

/// The rows of shard `index` (1-based) of `count` disjoint, contiguous shards of `rows` rows:
/// `floor((index - 1) rows / count) .. floor(index rows / count)`. Their union, in order, is
/// `0..rows`; shard sizes differ by at most one.
///
/// # Errors
/// [`Error::InvalidCount`] for `count` of 0 or `index` outside `1..=count`.
pub fn shard(rows: u64, index: u64, count: u64) -> Result<std::ops::Range<u64>> {
    if count == 0 {
        return Err(Error::InvalidCount {
            field: "shard count N (--shard I/N)".into(),
            value: 0,
            min: 1,
            max: u64::MAX,
        });
    }
    if index == 0 || index > count {
        return Err(Error::InvalidCount {
            field: "shard index I (--shard I/N)".into(),
            value: index,
            min: 1,
            max: count,
        });
    }
    let at = |k: u64| (u128::from(k) * u128::from(rows) / u128::from(count)) as u64;
    Ok(at(index - 1)..at(index))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn range(from: f64, to: f64, scale: Scale) -> Range {
        Range::new("x", from, to, scale).expect("valid range")
    }

    #[test]
    fn latin_hypercube_puts_one_row_in_each_stratum_of_each_axis() {
        let n = 997u64;
        let axes = vec![
            SampledAxis::Range(range(0.0, 1.0, Scale::Linear)),
            SampledAxis::Range(range(1.0, 1000.0, Scale::Log)),
        ];
        let d = Design::latin_hypercube(&["a", "b"], axes, n, 42).expect("valid");
        let mut strata = [vec![0u32; n as usize], vec![0u32; n as usize]];
        let mut v = [0.0; 2];
        for i in 0..n {
            d.values(i, &mut v);
            let t = [v[0], v[1].log10() / 3.0];
            for j in 0..2 {
                // The log axis is stratified in log10(value)/3; rounding at a stratum edge is
                // absorbed by nudging inwards by 1e-9 of a stratum.
                let k = ((t[j] * n as f64) - 1e-9).max(0.0) as usize;
                strata[j][k.min(n as usize - 1)] += 1;
            }
        }
        for (j, s) in strata.iter().enumerate() {
            assert!(s.iter().all(|&c| c == 1), "axis {j}: {s:?}");
        }
    }

    #[test]
    fn values_depend_only_on_seed_row_and_axis() {
        let axes = || {
            vec![
                SampledAxis::Range(range(-3.0, 5.0, Scale::Linear)),
                SampledAxis::List(vec![0.3, 0.6]),
            ]
        };
        let a = Design::random(&["a", "b"], axes(), 100, 7).expect("valid");
        let b = Design::random(&["a", "b"], axes(), 100, 7).expect("valid");
        let c = Design::random(&["a", "b"], axes(), 100, 8).expect("valid");
        let (mut va, mut vb, mut vc) = ([0.0; 2], [0.0; 2], [0.0; 2]);
        let mut differ = 0;
        for i in (0..100).rev() {
            a.values(i, &mut va);
            b.values(i, &mut vb);
            c.values(i, &mut vc);
            assert_eq!(va, vb, "row {i}");
            assert!((-3.0..5.0).contains(&va[0]) && [0.3, 0.6].contains(&va[1]));
            differ += usize::from(va != vc);
        }
        assert!(differ > 90, "another seed gives other values: {differ}");
    }

    #[test]
    fn random_values_are_uniform() {
        // 10^5 draws in 10 bins: each bin's count has standard deviation sqrt(10^4 * 0.9) = 95,
        // so 5 sigma (475) bounds a fair generator's deviation with room to spare.
        let d = Design::random(
            &["a"],
            vec![SampledAxis::Range(range(0.0, 1.0, Scale::Linear))],
            100_000,
            1,
        )
        .expect("valid");
        let mut bins = [0i64; 10];
        let mut v = [0.0];
        for i in 0..100_000 {
            d.values(i, &mut v);
            bins[(v[0] * 10.0) as usize] += 1;
        }
        assert!(bins.iter().all(|&b| (b - 10_000).abs() < 475), "{bins:?}");
    }

    #[test]
    fn grid_is_every_combination_first_axis_outermost() {
        let d = Design::grid(
            &["a", "b"],
            vec![
                GridAxis::List(vec![0.3, 0.6]),
                GridAxis::Steps(range(0.0, 600.0, Scale::Linear), 3),
            ],
        )
        .expect("valid");
        assert_eq!(d.rows(), 6);
        let mut v = [0.0; 2];
        let rows: Vec<[f64; 2]> = (0..6)
            .map(|i| {
                d.values(i, &mut v);
                v
            })
            .collect();
        assert_eq!(
            rows,
            [
                [0.3, 0.0],
                [0.3, 300.0],
                [0.3, 600.0],
                [0.6, 0.0],
                [0.6, 300.0],
                [0.6, 600.0]
            ]
        );
        let log = range(10.0, 1000.0, Scale::Log);
        assert_eq!((log.at(0.0), log.at(1.0)), (10.0, 1000.0), "exact ends");
        assert!((log.at(0.5) - 100.0).abs() < 1e-12);
    }

    #[test]
    fn shards_are_disjoint_and_cover_the_rows() {
        for rows in [0u64, 1, 5, 10, 1001] {
            for count in [1u64, 2, 3, 7, 12] {
                let mut next = 0;
                for i in 1..=count {
                    let s = shard(rows, i, count).expect("valid shard");
                    assert_eq!(s.start, next, "rows {rows}, shard {i}/{count}");
                    assert!(s.end - s.start <= rows / count + 1);
                    next = s.end;
                }
                assert_eq!(next, rows);
            }
        }
        assert!(shard(10, 0, 3).is_err() && shard(10, 4, 3).is_err() && shard(10, 1, 0).is_err());
    }

    #[test]
    fn bad_axes_name_the_problem() {
        let bad = |r: Result<Range>, want: &str| match r {
            Err(Error::InvalidRange { field, problem, .. }) => {
                assert_eq!(field, "x");
                assert!(problem.contains(want), "{problem}")
            }
            other => panic!("accepted: {other:?}"),
        };
        bad(
            Range::new("x", 2.0, 1.0, Scale::Linear),
            "from must not exceed to",
        );
        bad(
            Range::new("x", 0.0, 1.0, Scale::Log),
            "cannot reach or cross zero",
        );
        bad(
            Range::new("x", -1.0, 1.0, Scale::Log),
            "cannot reach or cross zero",
        );
        bad(
            Range::new("x", -10.0, -1.0, Scale::Log),
            "cannot reach or cross zero",
        );
        assert!(matches!(
            Range::new("x", f64::NAN, 1.0, Scale::Linear),
            Err(Error::InvalidInput { field, .. }) if field == "x.from"
        ));
        let zero = Design::grid(
            &["x"],
            vec![GridAxis::Steps(range(0.0, 1.0, Scale::Linear), 0)],
        );
        assert!(
            matches!(zero, Err(Error::InvalidCount { field, value: 0, .. }) if field == "x.count")
        );
        assert!(matches!(
            Design::random(&["x"], vec![SampledAxis::List(vec![])], 10, 1),
            Err(Error::InvalidCount { value: 0, .. })
        ));
        assert!(matches!(
            Design::latin_hypercube(&["x"], vec![SampledAxis::List(vec![1.0])], 0, 1),
            Err(Error::InvalidCount { field, .. }) if field == "sweep.samples"
        ));
        let huge = GridAxis::Steps(range(0.0, 1.0, Scale::Linear), MAX_AXIS_VALUES);
        assert!(Design::grid(
            &["a", "b", "c", "d"],
            vec![huge.clone(), huge.clone(), huge.clone(), huge]
        )
        .is_err());
    }
}
