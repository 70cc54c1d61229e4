//! The map drawn once: solid material, active segments and their normals, ready for any
//! number of pictures on top.

use tileslide::debug::DebugKinds;
use tileslide::{Cell, DebugKind, DebugLines, SegmentFlags, TileMap, Vec2};
use tiny_skia::{Path, PathBuilder, Pixmap};

use crate::lines::draw_segments;
use crate::pen::Pen;
use crate::view::View;
use crate::{Image, Picture, RenderError, RenderOptions, Style};

/// The kinds of the map's debug lines the canvas draws (when the options' layers hold
/// them): temporary segments change every frame, so pictures draw them.
const MAP_KINDS: DebugKinds = DebugKinds::NONE
    .with(DebugKind::ActiveSegment)
    .with(DebugKind::OneWaySegment)
    .with(DebugKind::Normal)
    .with(DebugKind::HiddenSegment);

/// A map drawn at a scale and orientation, onto which [`Picture`]s are rendered.
///
/// The map is drawn once, when the canvas is made: the inside of every tile shape with
/// closed solid outlines is filled, then the map's [debug lines](TileMap::debug_lines) are
/// stroked in their kinds' colours: every *active* segment (after seam culling), one-way
/// platforms in their own colour, each with a short tick along its outward normal, and,
/// when the options' [layers](RenderOptions::layers) hold them, the hidden seam segments,
/// faint. Temporary segments change from frame to frame, so they are not part of the
/// canvas: add them to each picture with [`Picture::temporaries`].
///
/// See [`Picture`] for an example.
#[derive(Clone, Debug)]
pub struct Canvas {
    map: Pixmap,
    view: View,
    style: Style,
    layers: DebugKinds,
}

impl Canvas {
    /// Draws `map` with `options`, or refuses a scale that is not a positive finite number
    /// ([`RenderError::BadScale`]) or an image larger than [`MAX_PIXELS`](crate::MAX_PIXELS)
    /// ([`RenderError::TooLarge`]).
    pub fn new(map: &TileMap, options: &RenderOptions) -> Result<Self, RenderError> {
        Self::with_view(map, View::new(map, options)?, options)
    }

    /// Draws `map` as `view` places it.
    pub(crate) fn with_view(
        map: &TileMap,
        view: View,
        options: &RenderOptions,
    ) -> Result<Self, RenderError> {
        let style = options.style;
        let too_large = || RenderError::TooLarge {
            width: view.width().into(),
            height: view.height().into(),
        };
        let mut pixmap = Pixmap::new(view.width(), view.height()).ok_or_else(too_large)?;
        pixmap.fill(style.background.to_skia());
        let mut pen = Pen::new(&mut pixmap);
        if let Some(solid) = solid_area(map, &view) {
            pen.fill(&solid, style.solid_fill);
        }
        let mut lines = DebugLines::new().with_kinds(DebugKinds(MAP_KINDS.0 & options.layers.0));
        map.debug_lines(&mut lines);
        draw_segments(&mut pen, &view, &style, options.layers, lines.segments());
        Ok(Self {
            map: pixmap,
            view,
            style,
            layers: options.layers,
        })
    }

    /// Image width in pixels.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.view.width()
    }

    /// Image height in pixels.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.view.height()
    }

    /// Pixels per cell along x.
    #[must_use]
    pub fn pixels_per_cell(&self) -> f32 {
        self.view.pixels_per_cell()
    }

    /// Where world point `p` lands in the image, in pixels from the top-left corner (pixel
    /// `(x, y)` covers `[x, x + 1) × [y, y + 1)`), or `None` for a non-finite point.
    #[must_use]
    pub fn to_pixel(&self, p: Vec2) -> Option<Vec2> {
        self.view.pixel_of(p)
    }

    /// The map with `picture` drawn on top.
    #[must_use]
    pub fn render(&self, picture: &Picture) -> Image {
        let mut pixmap = self.map.clone();
        picture.draw(
            &mut Pen::new(&mut pixmap),
            &self.view,
            &self.style,
            self.layers,
        );
        Image::from_pixmap(pixmap)
    }

    /// Like [`render`](Self::render), into an image that is reused (no allocation when it
    /// already has the canvas's size).
    pub fn render_into(&self, picture: &Picture, image: &mut Image) {
        let pixmap = image.pixmap_mut();
        if (pixmap.width(), pixmap.height()) == (self.map.width(), self.map.height()) {
            pixmap.data_mut().copy_from_slice(self.map.data());
        } else {
            *pixmap = self.map.clone();
        }
        picture.draw(&mut Pen::new(pixmap), &self.view, &self.style, self.layers);
    }

    /// The style the canvas draws with.
    pub(crate) fn style(&self) -> &Style {
        &self.style
    }
}

/// The inside of every closed tile shape, as one even-odd path, or `None` if there is none.
///
/// Each shape is filled as a fan of triangles from one of its vertices, one per solid
/// segment: by the crossing-number argument (a point is inside iff a ray from it crosses the
/// outline an odd number of times, and it lies in the fan triangle of exactly those
/// segments such a ray crosses), the even-odd union of the fan is the shape's inside,
/// whatever the order and direction of its segments. It is the same rule as
/// `TileShape::contains_point`, so the picture and `TileMap::is_point_solid` agree.
fn solid_area(map: &TileMap, view: &View) -> Option<Path> {
    let set = map.tile_set();
    let mut builder = PathBuilder::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            let cell = Cell::new(col, row);
            let Some(shape) = map.tile(cell).and_then(|id| set.shape(id)) else {
                continue;
            };
            if !shape.has_inside() {
                continue;
            }
            let solid = shape
                .segments()
                .iter()
                .filter(|s| s.flags.contains(SegmentFlags::SOLID));
            let Some(pivot) = solid
                .clone()
                .next()
                .and_then(|s| view.cell_point(cell, s.a))
            else {
                continue;
            };
            for s in solid {
                let (Some(a), Some(b)) = (view.cell_point(cell, s.a), view.cell_point(cell, s.b))
                else {
                    continue;
                };
                if a != pivot && b != pivot {
                    builder.move_to(pivot.x, pivot.y);
                    builder.line_to(a.x, a.y);
                    builder.line_to(b.x, b.y);
                    builder.close();
                }
            }
        }
    }
    builder.finish()
}
