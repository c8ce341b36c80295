//! PNG rendering: the SVG rendered by resvg with the bundled font only.

use super::draw_error;
use super::font::DEJAVU;
use crate::PlotError;
use std::sync::{Arc, OnceLock};

/// The SVG rendered to PNG by resvg, with the bundled font only.
pub(super) fn render_png(svg: &str, (width, height): (u32, u32)) -> Result<Vec<u8>, PlotError> {
    use resvg::{tiny_skia, usvg};
    static FONTS: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    let fontdb = FONTS.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(DEJAVU.to_vec());
        db.set_sans_serif_family("DejaVu Sans");
        Arc::new(db)
    });
    let options = usvg::Options {
        font_family: "DejaVu Sans".into(),
        fontdb: fontdb.clone(),
        ..Default::default()
    };
    let tree = usvg::Tree::from_str(svg, &options).map_err(draw_error)?;
    let mut pixmap = tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| PlotError::Draw(format!("cannot make a {width}x{height} image")))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(draw_error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{palette, render_svg, Figure, Legend, LogAxes, Panel, Series, Style};

    #[test]
    fn the_png_is_the_svg_rendered_with_text_and_data() {
        let figure = Figure {
            title: "Title 0.5".into(),
            panels: vec![Panel {
                legend: Legend::Auto,
                color_bar: None,
                equal_aspect: false,
                log_axes: LogAxes::Neither,
                title: "panel".into(),
                x_label: "x".into(),
                y_label: "y".into(),
                series: vec![Series::new(
                    "line",
                    Style::Line,
                    1,
                    vec![(0.0, 0.0), (1.0, 1.0)],
                )],
            }],
        };
        let (svg, size) = render_svg(&figure).unwrap();
        let png = render_png(&svg, size).unwrap();
        let image = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
        assert_eq!((image.width(), image.height()), size);
        let (r, g, b) = palette(1);
        let red = image
            .pixels()
            .iter()
            .filter(|p| (p.red(), p.green(), p.blue()) == (r, g, b))
            .count();
        assert!(red > 100, "the data line is drawn: {red} pixels");
        // The title's text is rendered: dark pixels in the top band.
        let dark_top = image.pixels()[..(size.0 * 25) as usize]
            .iter()
            .filter(|p| p.red() < 100)
            .count();
        assert!(dark_top > 50, "title text rendered: {dark_top} dark pixels");
    }
}
