//! The bundled DejaVu Sans: its bytes, the private family name plotters knows it by, the family
//! the written SVG asks for, and its one-time registration with plotters.

use plotters::style::FontStyle;
use std::sync::Once;

/// The bundled font.
pub(super) const DEJAVU: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
/// The private name under which plotters knows the bundled font: plotters' font table is
/// process-wide, so a common name such as "sans-serif" would replace an embedding application's.
pub(super) const FAMILY: &str = "halfplane-dejavu";
/// What the written SVG asks for instead of the private name.
pub(super) const SVG_FAMILY: &str = "DejaVu Sans, sans-serif";

static FONT: Once = Once::new();

/// plotters measures text only with registered fonts; the bundled font is registered once, under
/// a private family name.
pub(super) fn register_font() {
    FONT.call_once(|| {
        // The bytes are a valid TrueType font (checked by the tests), so this cannot fail.
        let _ = plotters::style::register_font(FAMILY, FontStyle::Normal, DEJAVU);
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{render_svg, Figure};
    use plotters::style::{IntoFont, TextStyle};

    #[test]
    fn the_font_is_registered_under_a_private_name_only() {
        let figure = Figure {
            title: "t".into(),
            panels: vec![],
        };
        render_svg(&figure).unwrap();
        let ours = TextStyle::from((FAMILY, 12).into_font());
        assert!(ours.font.box_size("0.5").is_ok(), "bundled font usable");
        // An application's "sans-serif" (here: none registered) is left alone.
        let theirs = TextStyle::from(("sans-serif", 12).into_font());
        assert!(theirs.font.box_size("0.5").is_err());
    }
}
