//! The pictures of `explain`: the part of the map a story happens in, what was met drawn
//! on it with numbered labels, and a legend on the right saying what each number is.

use std::path::Path;

use anyhow::{Result, anyhow};
use tileslide::debug::DebugKinds;
use tileslide::{Aabb, TileMap, Vec2};
use tileslide_render::{
    Anchor, Canvas, FontSize, Framing, Panel, Picture, RenderOptions, Rgba, Swatch, YAxis,
};

use crate::map_file::MapFormat;

/// The longest side of the map's part of a picture, in pixels (fewer when cells would be
/// drawn larger than [`MAX_CELL_PIXELS`]).
const VIEW_PIXELS: f32 = 480.0;
/// The largest and smallest cells drawn, in pixels.
const MAX_CELL_PIXELS: f32 = 96.0;
const MIN_CELL_PIXELS: f32 = 8.0;
/// Behind labels and the legend.
const LABEL_BACKGROUND: Rgba = Rgba::opaque(36, 36, 44);
/// Pixels of padding around the legend's text.
const LEGEND_PADDING: u32 = 16;

/// A text placed at a point of the world.
pub struct Label {
    pub at: Vec2,
    pub text: String,
    pub color: Rgba,
}

/// One row of the legend.
pub enum Row {
    Heading(String),
    Line(String),
    Key(Swatch, String),
}

/// A picture being put together: what to draw over the map, labels, and the legend.
pub struct Sketch {
    pub picture: Picture,
    pub labels: Vec<Label>,
    pub legend: Vec<Row>,
    /// What the picture must show, in world coordinates.
    pub area: Option<Aabb>,
}

impl Sketch {
    pub fn new() -> Self {
        Self {
            picture: Picture::new(),
            labels: Vec::new(),
            legend: Vec::new(),
            area: None,
        }
    }

    /// Makes sure the picture shows `p`, with `margin` around it.
    pub fn show(&mut self, p: Vec2, margin: f32) {
        let b = Aabb::from_corners(p - Vec2::splat(margin), p + Vec2::splat(margin));
        self.area = Some(match self.area {
            Some(a) => Aabb::from_corners(a.min.min(b.min), a.max.max(b.max)),
            None => b,
        });
    }

    /// Labels world point `at` with `text`.
    pub fn label(&mut self, at: Vec2, text: impl Into<String>, color: Rgba) {
        self.labels.push(Label {
            at,
            text: text.into(),
            color,
        });
    }

    /// Draws the sketch over `map` (`hidden`: with the segments seam culling hides) and
    /// writes it to `path` as a PNG; says what it wrote on stderr under `--json`, stdout
    /// otherwise.
    pub fn save(
        &self,
        map: &TileMap,
        format: MapFormat,
        hidden: bool,
        path: &Path,
        json: bool,
    ) -> Result<()> {
        let cell = map.cell_size().min_element();
        // The area grown by a cell, within the map (a story happens in it).
        let bounds = map.bounds();
        let area = self.area.unwrap_or(bounds);
        let grown = Aabb::from_corners(area.min - cell, area.max + cell);
        let min = grown.min.max(bounds.min);
        let max = grown.max.min(bounds.max);
        let window = if min.cmplt(max).all() {
            Aabb::from_corners(min, max)
        } else {
            grown
        };
        let size = window.max - window.min;
        let scale =
            (VIEW_PIXELS / size.max_element() * cell).clamp(MIN_CELL_PIXELS, MAX_CELL_PIXELS);
        let viewport = (
            (size.x / cell * scale).ceil() as u32,
            (size.y / cell * scale).ceil() as u32,
        );
        let (legend_width, legend_height) = self.legend_size();
        let image = (viewport.0 + legend_width, viewport.1.max(legend_height));
        let y_axis = if format == MapFormat::ReplicaIsland {
            YAxis::Up
        } else {
            YAxis::Down
        };
        let mut options = RenderOptions::default().with_y_axis(y_axis);
        if hidden {
            options = options.with_layers(DebugKinds::ALL);
        }
        let framing = Framing {
            window,
            image,
            viewport,
        };
        let canvas = Canvas::framed(map, &options, &framing)
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let mut rendered = canvas.render(&self.picture);
        let font = FontSize::Medium;
        // Each label's box, moved down past the boxes placed before it, so none hides
        // another.
        let mut placed: Vec<(i32, i32, i32, i32)> = Vec::new();
        for label in &self.labels {
            let Some(p) = canvas.to_pixel(label.at) else {
                continue;
            };
            let (w, h) = (
                font.width_of(&label.text) as i32 + 4,
                font.height() as i32 + 2,
            );
            let mut corner = (p.x.round() as i32 - w / 2, p.y.round() as i32 - h / 2);
            while let Some(&(_, y, _, bh)) = placed.iter().find(|&&(x, y, bw, bh)| {
                corner.0 < x + bw && x < corner.0 + w && corner.1 < y + bh && y < corner.1 + h
            }) {
                corner.1 = y + bh + 1;
            }
            placed.push((corner.0, corner.1, w, h));
            // A dark box behind the text, so it reads over anything.
            rendered.fill_rect(corner, (w as u32, h as u32), LABEL_BACKGROUND);
            rendered.text(
                &label.text,
                (corner.0 + 2, corner.1 + 1),
                font,
                Anchor::TopLeft,
                label.color,
            );
        }
        let mut panel = Panel::new(LABEL_BACKGROUND, Rgba::opaque(235, 235, 235));
        for row in &self.legend {
            match row {
                Row::Heading(text) => panel.heading(text.as_str()),
                Row::Line(text) => panel.line(text.as_str()),
                Row::Key(swatch, text) => panel.key(swatch.clone(), text.as_str()),
            };
        }
        panel.draw(
            &mut rendered,
            (viewport.0 as i32, 0),
            (legend_width, image.1),
        );
        rendered.save_png(path)?;
        let note = format!(
            "{}: {} × {} pixels",
            path.display(),
            rendered.width(),
            rendered.height()
        );
        if json {
            eprintln!("{note}");
        } else {
            println!("{note}");
        }
        Ok(())
    }

    /// The legend's width and height in pixels, room for every row.
    fn legend_size(&self) -> (u32, u32) {
        let width = self
            .legend
            .iter()
            .map(|row| match row {
                Row::Heading(t) => FontSize::Large.width_of(t),
                Row::Line(t) => FontSize::Medium.width_of(t),
                // The swatch and the space after it.
                Row::Key(_, t) => FontSize::Medium.width_of(t) + 24,
            })
            .max()
            .unwrap_or(0);
        let height: u32 = self
            .legend
            .iter()
            .map(|row| match row {
                Row::Heading(_) => FontSize::Large.height() + 4,
                _ => FontSize::Medium.height().max(16) + 4,
            })
            .sum();
        (width + 2 * LEGEND_PADDING, height + 2 * LEGEND_PADDING)
    }
}
