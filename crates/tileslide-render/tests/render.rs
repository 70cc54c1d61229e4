//! Pictures checked pixel by pixel, and their PNG and GIF files decoded back.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use tileslide::io::ascii;
use tileslide::{
    Aabb, Bodies, BodyDesc, BodyShape, Cell, Circle, DebugKind, DebugLines, Owner, QueryFilter,
    Ray, Segment, SegmentFlags, TemporarySegment, TileMap, Vec2, VolumeShape,
};
use tileslide_render::{
    Animation, Canvas, Image, MAX_PIXELS, Picture, RenderError, RenderOptions, Rgba, Style,
    VolumeKind, YAxis,
};

const ROOM: &str = "\
########
#......#
#..=...#
#/....\\#
########";

fn room() -> TileMap {
    ascii::parse(ROOM, "room.txt", 1.0).unwrap()
}

/// [`room`] and its canvas at `pixels_per_cell`.
fn room_at(pixels_per_cell: f32) -> (TileMap, Canvas) {
    let map = room();
    let canvas = canvas(&map, pixels_per_cell);
    (map, canvas)
}

fn canvas(map: &TileMap, pixels_per_cell: f32) -> Canvas {
    Canvas::new(
        map,
        &RenderOptions::default().with_pixels_per_cell(pixels_per_cell),
    )
    .unwrap()
}

/// A rect volume from its corners.
fn rect_volume(min: Vec2, max: Vec2) -> VolumeShape {
    VolumeShape::Rect(Aabb { min, max })
}

/// The colour of the pixel under world point `p`.
fn pixel_at(canvas: &Canvas, image: &Image, p: Vec2) -> Rgba {
    let q = canvas.to_pixel(p).unwrap();
    image.pixel(q.x as u32, q.y as u32).unwrap()
}

#[test]
fn solid_cells_are_filled_and_empty_cells_are_background() {
    let (_, canvas) = room_at(16.0);
    let image = canvas.render(&Picture::new());
    let style = Style::default();
    assert_eq!((image.width(), image.height()), (8 * 16, 5 * 16));
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(0.5, 0.5)),
        style.solid_fill
    );
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(4.5, 4.5)),
        style.solid_fill
    );
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(4.5, 1.5)),
        style.background
    );
}

/// Away from the lines drawn along segments and their normals, a pixel has the solid fill
/// exactly where `TileMap::is_point_solid` says its centre is solid — ramps included.
#[test]
fn the_fill_agrees_with_is_point_solid() {
    let map = room();
    let scale = 48.0;
    let canvas = canvas(&map, scale);
    let image = canvas.render(&Picture::new());
    let style = Style::default();
    let mut segments = Vec::new();
    for row in 0..map.height() {
        for col in 0..map.width() {
            for s in map.active_segments(Cell::new(col, row)) {
                let a = canvas.to_pixel(s.segment.a).unwrap();
                let b = canvas.to_pixel(s.segment.b).unwrap();
                segments.push(Segment::new(a, b));
            }
        }
    }
    // A tick is a quarter of a cell long, lines at most 3 pixels wide.
    let margin = scale * 0.25 + 3.0;
    let mut checked = 0;
    for y in 0..image.height() {
        for x in 0..image.width() {
            let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            if segments
                .iter()
                .any(|s| s.distance_squared_to(centre) < margin * margin)
            {
                continue;
            }
            let world = centre / scale;
            let expected = if map.is_point_solid(world) {
                style.solid_fill
            } else {
                style.background
            };
            assert_eq!(image.pixel(x, y), Some(expected), "pixel ({x}, {y})");
            checked += 1;
        }
    }
    assert!(checked > 10_000, "only {checked} pixels checked");
}

#[test]
fn segments_are_drawn_in_their_colours() {
    let map = room();
    // Lines are 3 pixels wide at this scale: the pixel row just below a line on a pixel
    // boundary is fully covered.
    let canvas = canvas(&map, 40.0);
    let image = canvas.render(&Picture::new());
    let style = Style::default();
    // The one-way platform along the top of cell (3, 2), a quarter of the way along.
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(3.25, 2.0)),
        style.one_way
    );
    // The floor's top edge (a solid segment) at x = 4.25.
    assert_eq!(pixel_at(&canvas, &image, Vec2::new(4.25, 4.0)), style.solid);
    // The normal tick of the floor segment in cell (4, 4) rises from its middle.
    assert_eq!(pixel_at(&canvas, &image, Vec2::new(4.5, 3.9)), style.normal);
}

#[test]
fn a_y_up_map_is_drawn_upside_down() {
    let map = ascii::parse("....\n....\n####", "floor.txt", 1.0).unwrap();
    let style = Style::default();
    let down = Canvas::new(&map, &RenderOptions::default()).unwrap();
    let up = Canvas::new(&map, &RenderOptions::default().with_y_axis(YAxis::Up)).unwrap();
    let (down_image, up_image) = (down.render(&Picture::new()), up.render(&Picture::new()));
    // Row 2 (the floor) is at the bottom of the y-down image and the top of the y-up one.
    assert_eq!(down_image.pixel(24, 40), Some(style.solid_fill));
    assert_eq!(up_image.pixel(24, 8), Some(style.solid_fill));
    assert_eq!(up_image.pixel(24, 40), Some(style.background));
    assert_eq!(up.to_pixel(Vec2::new(1.5, 2.5)), Some(Vec2::new(24.0, 8.0)));
}

#[test]
fn a_body_is_filled_with_its_colour() {
    let (_, canvas) = room_at(16.0);
    let mine = Rgba::opaque(10, 20, 200);
    let mut picture = Picture::new();
    picture
        .body(Circle::new(Vec2::new(2.5, 1.5), 0.4))
        .body_with_color(Circle::new(Vec2::new(5.5, 1.5), 0.4), mine);
    let image = canvas.render(&picture);
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(2.5, 1.5)),
        Style::default().body
    );
    assert_eq!(pixel_at(&canvas, &image, Vec2::new(5.5, 1.5)), mine);
    assert_eq!(picture.len(), 2);
    assert_eq!(picture.skipped(), 0);
}

#[test]
fn a_ray_hit_is_marked_with_a_dot() {
    let (map, canvas) = room_at(32.0);
    let ray = Ray::between(Vec2::new(4.5, 1.5), Vec2::new(4.5, 6.0));
    let hit = map.cast_ray(ray, &QueryFilter::default()).unwrap();
    let mut picture = Picture::new();
    picture.ray(ray, Some(&hit));
    let image = canvas.render(&picture);
    let style = Style::default();
    assert_eq!(pixel_at(&canvas, &image, hit.point), style.ray_hit);
    assert_eq!(pixel_at(&canvas, &image, Vec2::new(4.5, 2.5)), style.ray);
}

#[test]
fn volumes_are_tinted_red_for_attack_and_blue_for_vulnerability() {
    let (_, canvas) = room_at(16.0);
    let mut picture = Picture::new();
    let boxed = |x: f32| rect_volume(Vec2::new(x, 1.0), Vec2::new(x + 1.0, 2.0));
    picture
        .volume(boxed(1.0), VolumeKind::Attack)
        .volume(boxed(4.0), VolumeKind::Vulnerability)
        .hit_marker(Vec2::new(6.5, 1.5), true);
    let image = canvas.render(&picture);
    let attack = pixel_at(&canvas, &image, Vec2::new(1.5, 1.5));
    let vulnerable = pixel_at(&canvas, &image, Vec2::new(4.5, 1.5));
    assert!(attack.r > attack.b + 40, "{attack:?}");
    assert!(vulnerable.b > vulnerable.r + 40, "{vulnerable:?}");
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(6.5, 1.5)),
        Style::default().hit
    );
}

#[test]
fn temporary_segments_are_drawn_from_the_map() {
    let mut map = room();
    map.add_temporary(TemporarySegment {
        segment: Segment::new(Vec2::new(1.0, 2.0), Vec2::new(3.0, 2.0)),
        normal: Vec2::new(0.0, -1.0),
        flags: SegmentFlags::SOLID,
        owner: Owner(7),
        velocity: Vec2::ZERO,
    })
    .unwrap();
    let canvas = canvas(&map, 40.0);
    let mut picture = Picture::new();
    picture.temporaries(&map);
    assert_eq!(picture.len(), 1);
    let image = canvas.render(&picture);
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(1.25, 2.0)),
        Style::default().temporary
    );
}

#[test]
fn non_finite_overlays_are_skipped_and_counted() {
    let (_, canvas) = room_at(16.0);
    let mut picture = Picture::new();
    picture
        .body(Circle::new(Vec2::new(f32::NAN, 1.0), 0.5))
        .body(Circle::new(Vec2::new(2.0, 2.0), f32::INFINITY))
        .body(Circle::new(Vec2::new(2.0, 2.0), 0.0))
        .ray(
            Ray::between(Vec2::ZERO, Vec2::new(f32::INFINITY, 0.0)),
            None,
        )
        .polyline(&[Vec2::ZERO, Vec2::new(1.0, f32::NAN)])
        .polyline(&[])
        .volume(
            rect_volume(Vec2::new(3.0, 3.0), Vec2::new(2.0, 4.0)),
            VolumeKind::Attack,
        )
        .hit_marker(Vec2::new(f32::NEG_INFINITY, 0.0), false);
    assert_eq!(picture.skipped(), 8);
    assert!(picture.is_empty());
    assert_eq!(canvas.render(&picture), canvas.render(&Picture::new()));
    picture.clear();
    assert_eq!(picture.skipped(), 0);
}

#[test]
fn huge_finite_coordinates_do_not_panic() {
    let (_, canvas) = room_at(16.0);
    let mut picture = Picture::new();
    let far = Vec2::new(1e30, -1e30);
    picture
        .body(Circle::new(far, 1e30))
        .ray(Ray::between(Vec2::ZERO, far), None)
        .polyline(&[Vec2::ZERO, far, Vec2::new(3.0, 3.0), Vec2::splat(f32::MAX)])
        .volume(
            VolumeShape::Circle(Circle::new(far, 1e20)),
            VolumeKind::Vulnerability,
        )
        .volume(
            rect_volume(Vec2::splat(-f32::MAX), Vec2::splat(f32::MAX)),
            VolumeKind::Attack,
        )
        .hit_marker(far, true);
    assert_eq!(picture.skipped(), 0);
    let image = canvas.render(&picture);
    assert_eq!(image.width(), 128);
}

/// A circle larger than the image is drawn as what it looks like from inside: all fill.
#[test]
fn a_body_covering_the_whole_image_fills_it() {
    let (_, canvas) = room_at(16.0);
    let mut picture = Picture::new();
    picture.body(Circle::new(Vec2::new(4.0, 2.5), 1e30));
    let image = canvas.render(&picture);
    assert_eq!(image.pixel(0, 0), Some(Style::default().body));
    assert_eq!(image.pixel(127, 79), Some(Style::default().body));
}

/// Shapes of every size, anywhere: rendering never panics (tiny-skia's fixed-point
/// rasteriser asserts on coordinates near 10⁹, so they must be clipped first).
#[test]
fn shapes_of_any_finite_size_render_without_panicking() {
    let (_, canvas) = room_at(16.0);
    let magnitudes = [
        0.0,
        1e-3,
        0.5,
        3.0,
        64.0,
        1e3,
        1e6,
        3e6,
        5e6,
        1e7,
        1e9,
        1e15,
        1e30,
        f32::MAX,
    ];
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = || {
        // xorshift64 (Marsaglia 2003): a fixed seed, so a failure repeats.
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let m = magnitudes[(seed % magnitudes.len() as u64) as usize];
        if seed & (1 << 40) == 0 { m } else { -m }
    };
    let mut picture = Picture::new();
    for _ in 0..500 {
        let (p, q) = (Vec2::new(next(), next()), Vec2::new(next(), next()));
        let r = next().abs();
        picture
            .body(Circle::new(p, r))
            .ray(Ray::between(p, q), None)
            .polyline(&[p, q, Vec2::new(next(), next())])
            .volume(VolumeShape::Circle(Circle::new(q, r)), VolumeKind::Attack)
            .volume(rect_volume(p.min(q), p.max(q)), VolumeKind::Vulnerability)
            .hit_marker(p, false)
            .temporary(&TemporarySegment {
                segment: Segment::new(p, q),
                normal: q - p,
                flags: SegmentFlags::SOLID,
                owner: Owner(0),
                velocity: Vec2::ZERO,
            });
    }
    let image = canvas.render(&picture);
    assert_eq!(image.height(), 80);
}

#[test]
fn the_png_decodes_to_the_image_size() {
    let map = room();
    let image = canvas(&map, 12.0).render(&Picture::new());
    let png = image.to_png().unwrap();
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let reader = decoder.read_info().unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (8 * 12, 5 * 12));
    assert_eq!(info.color_type, png::ColorType::Rgba);
}

#[test]
fn save_png_names_the_file_it_cannot_write() {
    let image = canvas(&room(), 4.0).render(&Picture::new());
    let path = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("no/such/dir/out.png");
    let e = image.save_png(&path).unwrap_err();
    assert!(matches!(e, RenderError::Write { .. }));
    assert!(e.to_string().contains("no/such/dir/out.png"), "{e}");
}

#[test]
fn the_gif_decodes_to_every_frame_at_the_canvas_size() {
    let (_, canvas) = room_at(16.0);
    let mut animation = Animation::new(&canvas).unwrap().with_frame_delay(3);
    let mut picture = Picture::new();
    for step in 0..7 {
        picture.clear();
        picture.body(Circle::new(Vec2::new(1.5 + 0.5 * step as f32, 1.5), 0.4));
        animation.push(&picture).unwrap();
    }
    let bytes = animation.finish().unwrap();
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(std::io::Cursor::new(bytes)).unwrap();
    assert_eq!((decoder.width(), decoder.height()), (128, 80));
    let mut frames = 0;
    let style = Style::default();
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        assert_eq!((frame.width, frame.height), (128, 80));
        assert_eq!(frame.delay, 3);
        // The body's centre, in the style's exact colour (the palette holds it).
        let (x, y) = ((1.5 + 0.5 * frames as f32) * 16.0, 1.5 * 16.0);
        let i = 4 * (y as usize * 128 + x as usize);
        let b = style.body;
        assert_eq!(&frame.buffer[i..i + 4], &[b.r, b.g, b.b, 255]);
        frames += 1;
    }
    assert_eq!(frames, 7);
}

#[test]
fn an_empty_animation_still_holds_the_map() {
    let (_, canvas) = room_at(4.0);
    let bytes = Animation::new(&canvas).unwrap().finish().unwrap();
    let mut decoder = gif::DecodeOptions::new()
        .read_info(std::io::Cursor::new(bytes))
        .unwrap();
    assert!(decoder.read_next_frame().unwrap().is_some());
    assert!(decoder.read_next_frame().unwrap().is_none());
}

#[test]
fn too_large_images_are_refused_naming_the_size() {
    let map = room();
    let options = RenderOptions::default().with_pixels_per_cell(10_000.0);
    let e = Canvas::new(&map, &options).unwrap_err();
    assert!(
        matches!(
            e,
            RenderError::TooLarge {
                width: 80_000,
                height: 50_000
            }
        ),
        "{e:?}"
    );
    let message = e.to_string();
    assert!(message.contains("80000 × 50000"), "{message}");
    assert!(message.contains(&MAX_PIXELS.to_string()), "{message}");
    // Even a scale near f32::MAX is measured, not overflowed.
    let options = RenderOptions::default().with_pixels_per_cell(f32::MAX);
    assert!(matches!(
        Canvas::new(&map, &options),
        Err(RenderError::TooLarge { .. })
    ));
}

#[test]
fn bad_scales_are_refused() {
    let map = room();
    for scale in [0.0, -16.0, f32::NAN, f32::INFINITY] {
        let options = RenderOptions::default().with_pixels_per_cell(scale);
        let e = Canvas::new(&map, &options).unwrap_err();
        assert!(matches!(e, RenderError::BadScale(_)), "{e:?}");
    }
}

#[test]
fn an_animation_wider_than_a_gif_is_refused() {
    // 4,375 cells × 16 pixels = 70,000 pixels wide, 16 tall: a small image, too wide a GIF.
    let map = ascii::parse(&"#".repeat(4375), "wide.txt", 1.0).unwrap();
    let canvas = canvas(&map, 16.0);
    let e = Animation::new(&canvas).unwrap_err();
    assert!(
        matches!(
            e,
            RenderError::TooLargeForGif {
                width: 70_000,
                height: 16
            }
        ),
        "{e:?}"
    );
}

/// A map edited after its canvas was drawn: an area covers the dug cell and
/// `cell_walls` draws the walls the edit made, from the map as it is now.
#[test]
fn areas_and_cell_walls_show_an_edit_made_after_the_canvas() {
    let mut map = room();
    let canvas = canvas(&map, 40.0);
    let style = Style::default();
    // Dig into the top wall at (2, 0): its cell becomes floor, walls appear beside it.
    let dug = Cell::new(2, 0);
    map.clear_tile(dug).unwrap();
    let mut picture = Picture::new();
    picture.area(map.cell_rect(dug), style.background);
    let cells: Vec<Cell> = (0..map.height())
        .flat_map(|r| (0..map.width()).map(move |c| Cell::new(c, r)))
        .collect();
    picture.cell_walls(&map, cells);
    let image = canvas.render(&picture);
    // The dug cell's middle is floor now.
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(2.5, 0.5)),
        style.background
    );
    // The new wall on the left side of the dug cell (the right face of (1, 0)).
    assert_eq!(pixel_at(&canvas, &image, Vec2::new(2.0, 0.5)), style.solid);
    // Untouched solid elsewhere keeps its fill.
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(5.5, 0.5)),
        style.solid_fill
    );
    // Cells off the map are skipped and counted; an inverted box too.
    let mut bad = Picture::new();
    bad.cell_walls(&map, [Cell::new(99, 0)]);
    bad.area(
        Aabb {
            min: Vec2::ONE,
            max: Vec2::ZERO,
        },
        style.background,
    );
    assert_eq!(bad.skipped(), 2);
}

/// The canvas draws the map from its debug lines: hidden seam segments are left out by
/// default (the inside of a wall is plain fill) and drawn faint when the layers ask.
#[test]
fn hidden_seams_are_drawn_only_when_asked_for() {
    let map = ascii::parse("###\n###", "block.txt", 1.0).unwrap();
    let style = Style::default();
    let plain = canvas(&map, 40.0);
    let image = plain.render(&Picture::new());
    // (1, 0.5) lies on the seam between cells (0, 0) and (1, 0), inside the block.
    assert_eq!(
        pixel_at(&plain, &image, Vec2::new(1.0, 0.5)),
        style.solid_fill
    );
    let layers = tileslide_render::DEFAULT_LAYERS.with(DebugKind::HiddenSegment);
    let seams = Canvas::new(
        &map,
        &RenderOptions::default()
            .with_pixels_per_cell(40.0)
            .with_layers(layers),
    )
    .unwrap();
    let image = seams.render(&Picture::new());
    let seam = pixel_at(&seams, &image, Vec2::new(1.0, 0.5));
    assert_ne!(seam, style.solid_fill);
    // Faint: between the fill and the wall colour.
    assert!(
        seam.r < style.solid_fill.r && seam.r > style.solid.r,
        "{seam:?}"
    );
    // Away from the seams, the fill is as before.
    assert_eq!(
        pixel_at(&seams, &image, Vec2::new(0.5, 0.5)),
        style.solid_fill
    );
}

/// Bodies are drawn from `Bodies::debug_lines`: each where it is, in the body colour, and
/// after a resolve the boxes the broadphase filed them under.
#[test]
fn bodies_are_drawn_where_they_are() {
    let (map, canvas) = room_at(32.0);
    let mut bodies = Bodies::new();
    for x in [2.5, 5.5] {
        let desc = BodyDesc::new(Vec2::new(x, 1.5), BodyShape::circle(0.4).unwrap());
        bodies.add(desc).unwrap();
    }
    bodies.step(&map);
    let mut picture = Picture::new();
    picture.bodies(&bodies);
    let image = canvas.render(&picture);
    let style = Style::default();
    for (_, body) in bodies.iter() {
        assert_eq!(pixel_at(&canvas, &image, body.position()), style.body);
    }
    assert_eq!(
        pixel_at(&canvas, &image, Vec2::new(4.0, 1.5)),
        style.background
    );
    assert_eq!(picture.len(), 1);
    assert_eq!(picture.skipped(), 0);
}

/// Any debug lines, in their kinds' colours; kinds the canvas's layers leave out are not
/// drawn; shapes that are not finite are skipped and counted.
#[test]
fn debug_lines_are_drawn_in_their_kinds_colours() {
    let map = room();
    let style = Style::default();
    let mut lines = DebugLines::new();
    let cell = |x: f32| Aabb::from_corners(Vec2::new(x, 1.0), Vec2::new(x + 1.0, 2.0));
    lines.push_box(DebugKind::AttackVolume, cell(1.0), Owner(1));
    lines.push_box(DebugKind::VulnerabilityVolume, cell(4.0), Owner(2));
    lines.push_segment(
        DebugKind::Path,
        Segment::new(Vec2::new(1.0, 3.0), Vec2::new(6.0, 3.0)),
        Owner(0),
    );
    lines.push_point(DebugKind::Hit, Vec2::new(6.5, 1.5), Owner(2));
    lines.push_circle(
        DebugKind::Body,
        Circle::new(Vec2::new(1.0, f32::NAN), 1.0),
        Owner(0),
    );
    let mut picture = Picture::new();
    picture.debug_lines(&lines);
    assert_eq!(picture.skipped(), 1);
    let all = canvas(&map, 40.0);
    let image = all.render(&picture);
    let attack = pixel_at(&all, &image, Vec2::new(1.5, 1.5));
    let vulnerable = pixel_at(&all, &image, Vec2::new(4.5, 1.5));
    assert!(attack.r > attack.b + 40, "{attack:?}");
    assert!(vulnerable.b > vulnerable.r + 40, "{vulnerable:?}");
    assert_eq!(pixel_at(&all, &image, Vec2::new(3.5, 3.0)), style.path);
    assert_eq!(pixel_at(&all, &image, Vec2::new(6.5, 1.5)), style.hit);
    // Without the path layer, the path is not drawn.
    let options = RenderOptions::default()
        .with_pixels_per_cell(40.0)
        .with_layers(tileslide_render::DEFAULT_LAYERS.without(DebugKind::Path));
    let no_paths = Canvas::new(&map, &options).unwrap();
    let image = no_paths.render(&picture);
    assert_eq!(
        pixel_at(&no_paths, &image, Vec2::new(3.5, 3.0)),
        style.background
    );
}
