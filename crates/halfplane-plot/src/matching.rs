//! The load spaces of a prototype and its matched test, side by side
//! ([`halfplane::matching`]).

use crate::{Figure, Legend, LogAxes, Panel, PlotError, Series, Style, Units};
use halfplane::asymptotic::{equivalent_shear, Edge};
use halfplane::matching::{MatchReport, Side};

/// Points sampled along each in-phase segment.
const SAMPLES: usize = 40;

/// One panel per side of the match: the P-Q trajectory with the friction lines `Q = +/- f P`
/// and the ends marked, and the P-S trajectories of both edges, `S = Q +/- pi a sigma/4` (paper
/// eq. (33); left +, right -), sampled along the segment. Where the match holds, the test's
/// S paths are the prototype's scaled by `sqrt(a'/a)` at each point (docs/matching.md).
pub fn match_figure(report: &MatchReport, units: &Units) -> Result<Figure, PlotError> {
    let force = &units.force_per_length;
    let panel = |name: &str, side: &Side| -> Result<Panel, PlotError> {
        let contact = &side.contact;
        let f = contact.friction().value();
        let (p1, p2) = side.cycle.as_given();
        let p_max = 1.15 * p1.normal().max(p2.normal());
        let mut series = vec![
            Series::new(
                "friction lines ±fP",
                Style::Dashed,
                3,
                vec![(0.0, 0.0), (p_max, f * p_max)],
            ),
            Series::new("", Style::Dashed, 3, vec![(0.0, 0.0), (p_max, -f * p_max)]),
            Series::new(
                "Q",
                Style::Line,
                2,
                vec![(p1.normal(), p1.shear()), (p2.normal(), p2.shear())],
            ),
        ];
        for (edge, label, color) in [
            (Edge::Left, "S left = Q + πaσ/4", 0),
            (Edge::Right, "S right = Q − πaσ/4", 1),
        ] {
            let path = (0..=SAMPLES)
                .map(|i| {
                    let x = p1.lerp(&p2, i as f64 / SAMPLES as f64);
                    let a = contact.half_width(x.normal())?;
                    Ok((x.normal(), equivalent_shear(x.shear(), x.bulk(), a, edge)))
                })
                .collect::<Result<Vec<_>, halfplane::Error>>()?;
            series.push(Series::new(label, Style::Line, color, path));
        }
        series.push(Series::new(
            "point 1, point 2",
            Style::Points,
            4,
            vec![(p1.normal(), p1.shear()), (p2.normal(), p2.shear())],
        ));
        Ok(Panel {
            legend: Legend::Auto,
            color_bar: None,
            equal_aspect: false,
            log_axes: LogAxes::Neither,
            title: format!("{name}: {}", kind(side)),
            x_label: format!("normal load P ({force})"),
            y_label: format!("shear Q, equivalent shear S ({force})"),
            series,
        })
    };
    Ok(Figure {
        title: format!("Prototype and matched test ({} match)", report.mode),
        panels: vec![
            panel("prototype", &report.prototype)?,
            panel("test", &report.test)?,
        ],
    })
}

fn kind(side: &Side) -> &'static str {
    match side.contact.profile().shape() {
        halfplane::Shape::Hertz { .. } => "Hertz",
        halfplane::Shape::FlatRounded { .. } => "flat, rounded edges",
        halfplane::Shape::PowerLaw { .. } => "power law",
        _ => "tabulated",
    }
}
