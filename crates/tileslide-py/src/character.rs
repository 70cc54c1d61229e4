//! `Character`, `Contact` and `MoveResult`: a platformer's box or circle moved through a
//! map and its temporary segments (moving platforms). Values are converted here; the move
//! is the core's.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use tileslide::{
    CharacterShape, Contacts, ControllerConfig, ControllerError, MoveOptions, SegmentFlags,
    SegmentSource, Vec2,
};

use crate::errors::{finite, finite_point, whole_or};
use crate::map::TileMap;

/// One surface a character touched.
#[pyclass(module = "tileslide", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct Contact {
    /// The surface's unit normal at the contact, pointing towards the character.
    nx: f32,
    ny: f32,
    /// The segment's flags (1 solid, 2 one-way).
    flags: u32,
    /// The tile's cell `(col, row)`, or None for a temporary segment.
    cell: Option<(u32, u32)>,
    /// The tile's id, or None.
    tile: Option<u32>,
    /// The temporary segment's owner, or None for a tile.
    owner: Option<u64>,
    /// How fast the surface moves (a moving platform's velocity; zero for a tile).
    vx: f32,
    vy: f32,
}

impl Contact {
    pub(crate) fn of(contact: &tileslide::Contact) -> Self {
        let (cell, tile, owner, velocity) = match contact.source {
            SegmentSource::Tile { segment, tile } => (
                Some((segment.cell.col, segment.cell.row)),
                Some(tile.0),
                None,
                Vec2::ZERO,
            ),
            SegmentSource::Temporary {
                owner, velocity, ..
            } => (None, None, Some(owner.0), velocity),
            // A source the core adds later: reported without a cell, tile or owner.
            #[allow(unreachable_patterns)]
            _ => (None, None, None, Vec2::ZERO),
        };
        Contact {
            nx: contact.normal.x,
            ny: contact.normal.y,
            flags: contact.flags.0,
            cell,
            tile,
            owner,
            vx: velocity.x,
            vy: velocity.y,
        }
    }
}

#[pymethods]
impl Contact {
    fn __repr__(&self) -> String {
        let source = match (self.cell, self.tile, self.owner) {
            (Some((c, r)), Some(t), _) => format!("cell=({c}, {r}), tile={t}"),
            (_, _, Some(o)) => format!("owner={o}, vx={}, vy={}", self.vx, self.vy),
            _ => "source=None".to_owned(),
        };
        format!(
            "Contact(nx={}, ny={}, flags={}, {source})",
            self.nx, self.ny, self.flags
        )
    }
}

/// What a move did: where the character is and the surfaces it touched, by kind.
#[pyclass(module = "tileslide", frozen, get_all)]
#[derive(Clone, Debug)]
pub struct MoveResult {
    /// The character's position after the move.
    x: f32,
    y: f32,
    /// Whether it stands on walkable ground.
    grounded: bool,
    /// The ground under it at the end of the move, or None in the air.
    ground: Option<Contact>,
    /// The last ceiling, left wall and right wall met, or None.
    ceiling: Option<Contact>,
    left: Option<Contact>,
    right: Option<Contact>,
    /// A moving platform that pressed it into the world (crushed), or None.
    crush: Option<Contact>,
    /// `move_and_slide`: the velocity the surfaces leave, to keep; None for `move_by`.
    vx: Option<f32>,
    vy: Option<f32>,
}

#[pymethods]
impl MoveResult {
    fn __repr__(&self) -> String {
        let kinds = [
            ("ground", &self.ground),
            ("ceiling", &self.ceiling),
            ("left", &self.left),
            ("right", &self.right),
            ("crush", &self.crush),
        ];
        let touched: Vec<&str> = kinds
            .iter()
            .filter(|(_, c)| c.is_some())
            .map(|(name, _)| *name)
            .collect();
        let velocity = match (self.vx, self.vy) {
            (Some(vx), Some(vy)) => format!(", vx={vx}, vy={vy}"),
            _ => String::new(),
        };
        format!(
            "MoveResult(x={}, y={}, grounded={}, touched=[{}]{velocity})",
            self.x,
            self.y,
            if self.grounded { "True" } else { "False" },
            touched.join(", ")
        )
    }
}

/// A platformer character: a box or a circle with an up direction, moved by the
/// displacement the game wants each step.
#[pyclass(module = "tileslide")]
pub struct Character {
    pub(crate) character: tileslide::Character,
    /// What the last move touched, for `clip_velocity` and the debug lines.
    pub(crate) last: Contacts,
}

/// A `ValueError` with the core's message.
fn controller_error(e: &ControllerError) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The shape the keyword arguments ask for: a circle of `radius`, or a box of half extents
/// `half_width` × `half_height`.
fn shape_of(
    radius: Option<f32>,
    half_width: Option<f32>,
    half_height: Option<f32>,
) -> PyResult<CharacterShape> {
    let shape = match (radius, half_width, half_height) {
        (Some(r), None, None) => CharacterShape::circle(finite("radius", r)?),
        (None, Some(w), Some(h)) => {
            CharacterShape::rect(finite_point(["half_width", "half_height"], w, h)?)
        }
        _ => {
            return Err(PyValueError::new_err(
                "a character is a circle (radius=) or a box (half_width= and half_height=), \
                 one of the two",
            ));
        }
    };
    shape.map_err(|e| controller_error(&e))
}

fn options(drop_through: bool) -> MoveOptions {
    MoveOptions { drop_through }
}

#[pymethods]
impl Character {
    /// A character centred at (`x`, `y`): a circle of `radius`, or a box of half extents
    /// `half_width` × `half_height`; `up` (normalised; default (0, -1), for y-down maps);
    /// the controller's configuration as keyword arguments, the core's defaults.
    #[new]
    #[pyo3(signature = (
        x, y, *, radius = None, half_width = None, half_height = None, up = (0.0, -1.0),
        max_slope_degrees = 50.0, snap_distance = 0.3, skin = 0.001, max_slides = None,
        step_height = 0.0, mask = None,
    ))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        x: f32,
        y: f32,
        radius: Option<f32>,
        half_width: Option<f32>,
        half_height: Option<f32>,
        up: (f32, f32),
        max_slope_degrees: f32,
        snap_distance: f32,
        skin: f32,
        max_slides: Option<Bound<'_, PyAny>>,
        step_height: f32,
        mask: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let position = finite_point(["x", "y"], x, y)?;
        let shape = shape_of(radius, half_width, half_height)?;
        let up = finite_point(["up[0]", "up[1]"], up.0, up.1)?;
        if up == Vec2::ZERO {
            return Err(PyValueError::new_err(
                "up is (0, 0): it must be a direction",
            ));
        }
        let d = ControllerConfig::default();
        let max = u64::from(u32::MAX);
        let config = ControllerConfig {
            max_slope_degrees,
            snap_distance,
            skin,
            max_slides: whole_or("max_slides", max_slides.as_ref(), max, d.max_slides.into())?
                as u32,
            step_height,
            mask: SegmentFlags(whole_or("mask", mask.as_ref(), max, d.mask.0.into())? as u32),
        };
        // The core names the field (`max_slope_degrees`, `skin`, …) as the keyword does.
        config.validate().map_err(|e| controller_error(&e))?;
        let character = tileslide::Character::new(shape, position, up, config)
            .map_err(|e| controller_error(&e))?;
        Ok(Character {
            character,
            last: Contacts::default(),
        })
    }

    /// The x of the shape's centre.
    #[getter]
    fn x(&self) -> f32 {
        self.character.position.x
    }

    /// The y of the shape's centre.
    #[getter]
    fn y(&self) -> f32 {
        self.character.position.y
    }

    /// The unit up direction `(x, y)`.
    #[getter]
    fn up(&self) -> (f32, f32) {
        let up = self.character.up();
        (up.x, up.y)
    }

    /// The circle's radius, or None for a box.
    #[getter]
    fn radius(&self) -> Option<f32> {
        match self.character.shape() {
            CharacterShape::Circle { radius } => Some(radius),
            _ => None,
        }
    }

    /// The box's half extents `(half_width, half_height)`, or None for a circle.
    #[getter]
    fn half_extents(&self) -> Option<(f32, f32)> {
        match self.character.shape() {
            CharacterShape::Rect { half } => Some((half.x, half.y)),
            _ => None,
        }
    }

    /// The ground under the character after its last move, or None in the air.
    #[getter]
    fn ground(&self) -> Option<Contact> {
        self.character.ground().map(Contact::of)
    }

    /// Moves the character to (`x`, `y`) at once (no sweep), forgetting its ground.
    fn teleport(&mut self, x: f32, y: f32) -> PyResult<()> {
        let position = finite_point(["x", "y"], x, y)?;
        self.character
            .teleport(position)
            .map_err(|e| controller_error(&e))?;
        self.last = Contacts::default();
        Ok(())
    }

    /// Moves the character by (`dx`, `dy`) through `map` and its temporary segments, as
    /// far as they let it: walks slopes, snaps to the ground, lands, slides, rides moving
    /// platforms. `drop_through` falls through one-way platforms during this move.
    #[pyo3(signature = (map, dx, dy, *, drop_through = false))]
    fn move_by(
        &mut self,
        map: &TileMap,
        dx: f32,
        dy: f32,
        drop_through: bool,
    ) -> PyResult<MoveResult> {
        let displacement = finite_point(["dx", "dy"], dx, dy)?;
        let contacts = self
            .character
            .move_by(&map.map, displacement, options(drop_through))
            .map_err(|e| controller_error(&e))?;
        self.last = contacts;
        Ok(self.result(None))
    }

    /// Moves the character by velocity (`vx`, `vy`) × `dt` (as `move_by`), then takes out
    /// of the velocity what the surfaces it touched stopped: landing zeroes the fall, a
    /// ceiling the rise, a wall the speed into it. The result's `vx`, `vy` are the velocity
    /// to keep.
    #[pyo3(signature = (map, vx, vy, dt, *, drop_through = false))]
    fn move_and_slide(
        &mut self,
        map: &TileMap,
        vx: f32,
        vy: f32,
        dt: f32,
        drop_through: bool,
    ) -> PyResult<MoveResult> {
        let mut velocity = finite_point(["vx", "vy"], vx, vy)?;
        let dt = finite("dt", dt)?;
        if dt < 0.0 {
            return Err(PyValueError::new_err(format!(
                "dt is {dt}: it must not be negative"
            )));
        }
        let contacts = self
            .character
            .move_and_slide(&map.map, &mut velocity, dt, options(drop_through))
            .map_err(|e| controller_error(&e))?;
        self.last = contacts;
        Ok(self.result(Some(velocity)))
    }

    /// The velocity (`vx`, `vy`) without what the surfaces the last move touched stop, as
    /// `move_and_slide` clips it: for a displacement made with `move_by`.
    fn clip_velocity(&self, vx: f32, vy: f32) -> PyResult<(f32, f32)> {
        let velocity = finite_point(["vx", "vy"], vx, vy)?;
        let v = self
            .character
            .clip_velocity(velocity, &self.last)
            .map_err(|e| controller_error(&e))?;
        Ok((v.x, v.y))
    }

    fn __repr__(&self) -> String {
        let p = self.character.position;
        let shape = match self.character.shape() {
            CharacterShape::Circle { radius } => format!("radius={radius}"),
            CharacterShape::Rect { half } => {
                format!("half_width={}, half_height={}", half.x, half.y)
            }
            _ => String::new(),
        };
        format!("Character(x={}, y={}, {shape})", p.x, p.y)
    }
}

impl Character {
    fn result(&self, velocity: Option<Vec2>) -> MoveResult {
        let p = self.character.position;
        let c = &self.last;
        let of = |c: &Option<tileslide::Contact>| c.as_ref().map(Contact::of);
        MoveResult {
            x: p.x,
            y: p.y,
            grounded: c.is_grounded(),
            ground: of(&c.ground),
            ceiling: of(&c.ceiling),
            left: of(&c.left),
            right: of(&c.right),
            crush: of(&c.crush),
            vx: velocity.map(|v| v.x),
            vy: velocity.map(|v| v.y),
        }
    }
}
