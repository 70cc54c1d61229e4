//! The map drawn once: solid material, active segments and their normals, ready for any
//! number of pictures on top.

use tileslide::{Cell, SegmentFlags, TileMap, Vec2};
use tiny_skia::{Path, PathBuilder, Pixmap};

use crate::pen::Pen;
use crate::view::{NORMAL_WIDTH, View};
use crate::{Image, Picture, RenderError, RenderOptions, Style};

/// A map drawn at a scale and orientation, onto which [`Picture`]s are rendered.
///
/// The map is drawn once, when the canvas is made: the inside of every tile shape with
/// closed solid outlines is filled, then every *active* segment (after seam culling) is
/// stroked, one-way platforms in their own colour, each with a short tick along its outward
/// normal. Temporary segments change from frame to frame, so they are not part of the
/// canvas: add them to each picture with [`Picture::temporaries`].
///
/// See [`Picture`] for an example.
#[derive(Clone, Debug)]
pub struct Canvas {
    map: Pixmap,
    view: View,
    style: Style,
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
        let line = view.line_width();
        let mut segments = SegmentPaths::default();
        for row in 0..map.height() {
            for col in 0..map.width() {
                for s in map.active_segments(Cell::new(col, row)) {
                    segments.add(&view, s.segment.a, s.segment.b, s.normal, s.flags);
                }
            }
        }
        segments.draw(&mut pen, &style, line);
        Ok(Self {
            map: pixmap,
            view,
            style,
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
        picture.draw(&mut Pen::new(&mut pixmap), &self.view, &self.style);
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
        picture.draw(&mut Pen::new(pixmap), &self.view, &self.style);
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

/// Active segments sorted into one path per colour, and their normal ticks.
#[derive(Default)]
struct SegmentPaths {
    solid: PathBuilder,
    one_way: PathBuilder,
    normals: PathBuilder,
}

impl SegmentPaths {
    /// Adds the segment `a`–`b` (world coordinates, inside the map) with its outward
    /// normal, coloured by its flags. Left out if a point is not finite.
    fn add(&mut self, view: &View, a: Vec2, b: Vec2, normal: Vec2, flags: SegmentFlags) {
        let (Some(pa), Some(pb)) = (view.pixel_of(a), view.pixel_of(b)) else {
            return;
        };
        let path = if flags.contains(SegmentFlags::ONE_WAY) {
            &mut self.one_way
        } else {
            &mut self.solid
        };
        path.move_to(pa.x, pa.y);
        path.line_to(pb.x, pb.y);
        if let Some((from, to)) = view.normal_tick(pa, pb, normal) {
            self.normals.move_to(from.x, from.y);
            self.normals.line_to(to.x, to.y);
        }
    }

    /// Draws the normals, then the segments over them.
    fn draw(self, pen: &mut Pen<'_>, style: &Style, line: f32) {
        let layers = [
            (self.normals, style.normal, line * NORMAL_WIDTH),
            (self.solid, style.solid, line),
            (self.one_way, style.one_way, line),
        ];
        for (builder, color, width) in layers {
            if let Some(path) = builder.finish() {
                pen.stroke(&path, color, width);
            }
        }
    }
}
