//! The shared vocabulary for the pairs a cycle is made of: the two contact [`Edge`]s, the two load
//! points as the caller gave them ([`GivenPoint`]) and the two halves of the cycle ([`Half`]), and
//! pairs of values indexed by them ([`PerEdge`], [`PerPoint`]).
//!
//! Each label has a stable name (`as_str`, also its `Display`): the words the command-line front
//! end prints and reads, so they are a public interface and do not change.
//!
//! Conventions (docs/theory.md, "Conventions"): the *left* edge `x = -a` is the one where bulk tension
//! adds to the shear. Points are "as given", not the internal labelling by Q; half 1 runs from the
//! first point as given to the second, half 2 back.

use std::ops::{Index, IndexMut};

/// A contact edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Edge {
    /// x = -a.
    Left,
    /// x = +a.
    Right,
}

impl Edge {
    /// Both edges, left first.
    pub const BOTH: [Edge; 2] = [Edge::Left, Edge::Right];

    /// +1 at the left edge, -1 at the right: the sign of the bulk-tension term.
    pub(crate) fn bulk_sign(self) -> f64 {
        match self {
            Edge::Left => 1.0,
            Edge::Right => -1.0,
        }
    }

    /// "left" or "right".
    pub fn as_str(self) -> &'static str {
        match self {
            Edge::Left => "left",
            Edge::Right => "right",
        }
    }

    /// "left" or "right" (the same as [`Edge::as_str`]).
    pub fn name(self) -> &'static str {
        self.as_str()
    }
}

/// Which of the caller's two load points, in the order given (not the internal labelling by Q).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum GivenPoint {
    /// The first point as given.
    First,
    /// The second point as given.
    Second,
}

impl GivenPoint {
    /// Both points, first first.
    pub const BOTH: [GivenPoint; 2] = [GivenPoint::First, GivenPoint::Second];

    /// "first" or "second".
    pub fn as_str(self) -> &'static str {
        match self {
            GivenPoint::First => "first",
            GivenPoint::Second => "second",
        }
    }
}

/// A half of the cycle, numbered as the evolution and [`crate::Error::SlipReversesInHalf`] print
/// them: half 1 runs from the first point as given to the second, half 2 back.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Half {
    /// Half 1: from the first point as given to the second.
    First,
    /// Half 2: from the second point as given back to the first.
    Second,
}

impl Half {
    /// Both halves, in cycle order.
    pub const BOTH: [Half; 2] = [Half::First, Half::Second];

    /// 1 or 2, the number the half is printed by.
    pub fn number(self) -> u8 {
        match self {
            Half::First => 1,
            Half::Second => 2,
        }
    }

    /// The half numbered `number` (1 or 2).
    pub fn from_number(number: u8) -> Option<Half> {
        match number {
            1 => Some(Half::First),
            2 => Some(Half::Second),
            _ => None,
        }
    }

    /// "1" or "2": halves are printed by number ("half 1", the `half` column of the evolution
    /// table).
    pub fn as_str(self) -> &'static str {
        match self {
            Half::First => "1",
            Half::Second => "2",
        }
    }

    /// The other half: the same half-cycle, numbered for the points given in the other order.
    pub fn other(self) -> Half {
        match self {
            Half::First => Half::Second,
            Half::Second => Half::First,
        }
    }

    /// The point the half starts from.
    pub fn start(self) -> GivenPoint {
        match self {
            Half::First => GivenPoint::First,
            Half::Second => GivenPoint::Second,
        }
    }

    /// The point the half runs to.
    pub fn end(self) -> GivenPoint {
        match self {
            Half::First => GivenPoint::Second,
            Half::Second => GivenPoint::First,
        }
    }
}

/// `Display` by `as_str`, for the labelled enums of this module and of `steady` and `evolution`.
macro_rules! display_as_str {
    ($($t:ty),*) => {$(
        impl ::std::fmt::Display for $t {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.pad(self.as_str())
            }
        }
    )*};
}
pub(crate) use display_as_str;

display_as_str!(Edge, GivenPoint, Half);

/// One value per contact edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct PerEdge<T> {
    /// At the left edge, x = -a.
    pub left: T,
    /// At the right edge, x = +a.
    pub right: T,
}

impl<T> PerEdge<T> {
    /// The value of `f` at each edge.
    pub fn from_fn(mut f: impl FnMut(Edge) -> T) -> Self {
        Self {
            left: f(Edge::Left),
            right: f(Edge::Right),
        }
    }

    /// Applies `f` to both values.
    pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> PerEdge<U> {
        PerEdge {
            left: f(self.left),
            right: f(self.right),
        }
    }

    /// `[left, right]`.
    pub fn to_array(self) -> [T; 2] {
        [self.left, self.right]
    }

    /// References to the values, left first.
    pub fn iter(&self) -> std::array::IntoIter<&T, 2> {
        [&self.left, &self.right].into_iter()
    }
}

/// The values, left first.
impl<T> IntoIterator for PerEdge<T> {
    type Item = T;
    type IntoIter = std::array::IntoIter<T, 2>;
    fn into_iter(self) -> Self::IntoIter {
        self.to_array().into_iter()
    }
}

impl<'a, T> IntoIterator for &'a PerEdge<T> {
    type Item = &'a T;
    type IntoIter = std::array::IntoIter<&'a T, 2>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<T> Index<Edge> for PerEdge<T> {
    type Output = T;
    fn index(&self, edge: Edge) -> &T {
        match edge {
            Edge::Left => &self.left,
            Edge::Right => &self.right,
        }
    }
}

impl<T> IndexMut<Edge> for PerEdge<T> {
    fn index_mut(&mut self, edge: Edge) -> &mut T {
        match edge {
            Edge::Left => &mut self.left,
            Edge::Right => &mut self.right,
        }
    }
}

/// One value per load point, in the order the caller gave the points.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct PerPoint<T> {
    /// At the first point as given.
    pub first: T,
    /// At the second point as given.
    pub second: T,
}

impl<T> PerPoint<T> {
    /// The value of `f` at each point.
    pub fn from_fn(mut f: impl FnMut(GivenPoint) -> T) -> Self {
        Self {
            first: f(GivenPoint::First),
            second: f(GivenPoint::Second),
        }
    }

    /// Applies `f` to both values.
    pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> PerPoint<U> {
        PerPoint {
            first: f(self.first),
            second: f(self.second),
        }
    }

    /// `[first, second]`.
    pub fn to_array(self) -> [T; 2] {
        [self.first, self.second]
    }

    /// References to the values, first point first.
    pub fn iter(&self) -> std::array::IntoIter<&T, 2> {
        [&self.first, &self.second].into_iter()
    }

    /// Exchanges the two values: the same pair for the points given in the other order.
    pub fn swap(&mut self) {
        std::mem::swap(&mut self.first, &mut self.second);
    }
}

/// The values, first point first.
impl<T> IntoIterator for PerPoint<T> {
    type Item = T;
    type IntoIter = std::array::IntoIter<T, 2>;
    fn into_iter(self) -> Self::IntoIter {
        self.to_array().into_iter()
    }
}

impl<'a, T> IntoIterator for &'a PerPoint<T> {
    type Item = &'a T;
    type IntoIter = std::array::IntoIter<&'a T, 2>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<T> Index<GivenPoint> for PerPoint<T> {
    type Output = T;
    fn index(&self, point: GivenPoint) -> &T {
        match point {
            GivenPoint::First => &self.first,
            GivenPoint::Second => &self.second,
        }
    }
}

impl<T> IndexMut<GivenPoint> for PerPoint<T> {
    fn index_mut(&mut self, point: GivenPoint) -> &mut T {
        match point {
            GivenPoint::First => &mut self.first,
            GivenPoint::Second => &mut self.second,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The names are what the CLI prints; changing one changes its output.
    #[test]
    fn names_are_stable() {
        assert_eq!(Edge::BOTH.map(|e| e.to_string()), ["left", "right"]);
        assert_eq!(Edge::Left.name(), "left");
        assert_eq!(GivenPoint::BOTH.map(|p| p.to_string()), ["first", "second"]);
        assert_eq!(Half::BOTH.map(|h| h.to_string()), ["1", "2"]);
        assert_eq!(format!("[{:>6}]", Edge::Left), "[  left]");
        use crate::evolution::PointState;
        use crate::steady::Regime;
        let regimes = [
            Regime::GrossSliding {
                point: GivenPoint::First,
            },
            Regime::FullStick,
            Regime::PartialSlip,
        ];
        assert_eq!(
            regimes.map(|r| r.to_string()),
            ["gross-sliding", "full-stick", "partial-slip"]
        );
        let states = [
            PointState::FullStick,
            PointState::PartialSlip,
            PointState::OneEdgeSlip {
                slipping: Edge::Left,
            },
        ];
        assert_eq!(
            states.map(|s| s.to_string()),
            ["full-stick", "partial-slip", "one-edge-slip"]
        );
    }

    /// The error messages print the labels as they printed the old `u8` and `&str` fields.
    #[test]
    fn error_messages_print_the_labels() {
        let slip = crate::Error::SlipReversesInHalf {
            half: Half::Second,
            edge: Edge::Right,
            fraction: 0.0,
            boundary_rate: -0.07,
            limit_rate: -0.13,
        }
        .to_string();
        assert!(slip
            .starts_with("slip at the right edge does not keep one direction through half 2 of"));
        let sliding = crate::Error::GrossSliding {
            point: GivenPoint::First,
            shear: 250.0,
            limit: 200.0,
        }
        .to_string();
        assert!(sliding.starts_with("the contact slides at the first point: |Q| = 250.000000"));
    }

    #[test]
    fn halves_number_and_run_between_the_points_as_given() {
        for h in Half::BOTH {
            assert_eq!(Half::from_number(h.number()), Some(h));
            assert_ne!(h.start(), h.end());
        }
        assert_eq!(Half::First.start(), GivenPoint::First);
        assert_eq!(Half::from_number(0), None);
    }

    #[test]
    fn pairs_index_map_and_convert() {
        let mut w = PerEdge::from_fn(|e| e.bulk_sign());
        assert_eq!((w[Edge::Left], w[Edge::Right]), (1.0, -1.0));
        w[Edge::Right] = 3.0;
        assert_eq!(w.map(|v| 2.0 * v).to_array(), [2.0, 6.0]);
        let p = PerPoint::from_fn(|p| p.as_str().len());
        assert_eq!((p[GivenPoint::First], p[GivenPoint::Second]), (5, 6));
        assert_eq!(p.map(|n| n + 1).to_array(), [6, 7]);
    }
}
