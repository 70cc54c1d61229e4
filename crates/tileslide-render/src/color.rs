//! Colours and the style that assigns one to each thing drawn.

use tileslide::DebugKind;

/// A colour with straight (not premultiplied) alpha: `a = 255` is opaque.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgba {
    /// Red.
    pub r: u8,
    /// Green.
    pub g: u8,
    /// Blue.
    pub b: u8,
    /// Opacity: 0 transparent, 255 opaque.
    pub a: u8,
}

impl Rgba {
    /// The colour `(r, g, b, a)`.
    #[must_use]
    pub const fn new(r: u8, g: u8, b: u8, a: u8) -> Self {
        Self { r, g, b, a }
    }

    /// The opaque colour `(r, g, b)`.
    #[must_use]
    pub const fn opaque(r: u8, g: u8, b: u8) -> Self {
        Self::new(r, g, b, 255)
    }

    /// This colour with opacity `a`.
    #[must_use]
    pub const fn with_alpha(self, a: u8) -> Self {
        Self { a, ..self }
    }

    pub(crate) fn to_skia(self) -> tiny_skia::Color {
        tiny_skia::Color::from_rgba8(self.r, self.g, self.b, self.a)
    }
}

/// The colour of each thing drawn. The default is light: dark outlines on an off-white
/// background, grey solid material.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Style {
    /// Empty space (and everything outside solid outlines).
    pub background: Rgba,
    /// The inside of solid tile shapes.
    pub solid_fill: Rgba,
    /// Active segments that are not one-way platforms.
    pub solid: Rgba,
    /// Active one-way platform segments.
    pub one_way: Rgba,
    /// Temporary segments (moving platforms, doors).
    pub temporary: Rgba,
    /// The short ticks along segment normals and at ray hits.
    pub normal: Rgba,
    /// Bodies drawn without a colour of their own.
    pub body: Rgba,
    /// The outline of every body.
    pub body_outline: Rgba,
    /// Rays up to their hit (the part past the hit is drawn fainter).
    pub ray: Rgba,
    /// The dot at a ray's hit point.
    pub ray_hit: Rgba,
    /// Paths (polylines).
    pub path: Rgba,
    /// Attack volumes (filled with a quarter of this opacity, outlined with all of it).
    pub attack: Rgba,
    /// Vulnerability volumes (likewise).
    pub vulnerability: Rgba,
    /// Accepted hit events.
    pub hit: Rgba,
    /// Hit events the victim refused.
    pub hit_refused: Rgba,
    /// Pieces of tile segments that seam culling hides (drawn only when asked for, see
    /// [`RenderOptions::layers`](crate::RenderOptions::layers)): faint.
    pub hidden: Rgba,
    /// Characters' outlines.
    pub character: Rgba,
    /// The surfaces a character touched, along their normals.
    pub contact: Rgba,
    /// Flow field arrows.
    pub flow: Rgba,
    /// Broadphase boxes' outlines.
    pub broadphase: Rgba,
}

impl Default for Style {
    fn default() -> Self {
        Self {
            background: Rgba::opaque(247, 247, 242),
            solid_fill: Rgba::opaque(154, 160, 168),
            solid: Rgba::opaque(30, 35, 41),
            one_way: Rgba::opaque(224, 122, 16),
            temporary: Rgba::opaque(142, 68, 173),
            normal: Rgba::opaque(22, 160, 133),
            body: Rgba::opaque(39, 174, 96),
            body_outline: Rgba::opaque(20, 90, 50),
            ray: Rgba::opaque(208, 48, 127),
            ray_hit: Rgba::opaque(120, 20, 70),
            path: Rgba::opaque(204, 153, 0),
            attack: Rgba::opaque(220, 50, 47),
            vulnerability: Rgba::opaque(38, 110, 220),
            hit: Rgba::opaque(200, 10, 60),
            hit_refused: Rgba::opaque(120, 120, 120),
            hidden: Rgba::new(30, 35, 41, 70),
            character: Rgba::opaque(41, 128, 185),
            contact: Rgba::opaque(230, 126, 34),
            flow: Rgba::opaque(127, 140, 141),
            broadphase: Rgba::new(142, 68, 173, 110),
        }
    }
}

impl Style {
    /// Every colour of the style, for a palette that must reproduce them exactly.
    pub(crate) fn colors(&self) -> [Rgba; 20] {
        [
            self.background,
            self.solid_fill,
            self.solid,
            self.one_way,
            self.temporary,
            self.normal,
            self.body,
            self.body_outline,
            self.ray,
            self.ray_hit,
            self.path,
            self.attack,
            self.vulnerability,
            self.hit,
            self.hit_refused,
            self.hidden,
            self.character,
            self.contact,
            self.flow,
            self.broadphase,
        ]
    }

    /// The colour [debug lines](tileslide::DebugLines) of `kind` are drawn in, or `None`
    /// for a kind this version does not know (a newer `tileslide`'s): those are not drawn.
    ///
    /// ```
    /// use tileslide::DebugKind;
    /// use tileslide_render::Style;
    ///
    /// let style = Style::default();
    /// assert_eq!(style.color_of(DebugKind::ActiveSegment), Some(style.solid));
    /// assert_eq!(style.color_of(DebugKind::HiddenSegment), Some(style.hidden));
    /// ```
    #[must_use]
    pub fn color_of(&self, kind: DebugKind) -> Option<Rgba> {
        Some(match kind {
            DebugKind::ActiveSegment => self.solid,
            DebugKind::OneWaySegment => self.one_way,
            DebugKind::Normal => self.normal,
            DebugKind::HiddenSegment => self.hidden,
            DebugKind::TemporarySegment => self.temporary,
            DebugKind::Body => self.body,
            DebugKind::Character => self.character,
            DebugKind::Contact => self.contact,
            DebugKind::Ray => self.ray,
            DebugKind::RayHit => self.ray_hit,
            DebugKind::AttackVolume => self.attack,
            DebugKind::VulnerabilityVolume => self.vulnerability,
            DebugKind::Hit => self.hit,
            DebugKind::RefusedHit => self.hit_refused,
            DebugKind::Path => self.path,
            DebugKind::FlowArrow => self.flow,
            DebugKind::BroadphaseBox => self.broadphase,
            _ => return None,
        })
    }
}
