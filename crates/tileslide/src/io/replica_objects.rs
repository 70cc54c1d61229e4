//! What a Replica Island level places beside its collision: the object layer's spawn points
//! and the hot-spot layer's codes, as plain data ([`LevelObjects`]), with the game's names
//! for the numbers it defines ([`ObjectKind`], [`HotSpotKind`]). Read by
//! [`replica::parse_objects`](super::replica::parse_objects).
//!
//! The numbers are the game's own: its object factory's type numbers (the order of the
//! level editor's object tiles) and its hot-spot system's codes.

use std::fmt;

use glam::Vec2;

use crate::tiles::Cell;

use super::replica::TILE_SIZE;

/// Defines [`ObjectKind`]: each variant with its type number and the game's name for it.
macro_rules! object_kinds {
    ($($(#[doc = $doc:literal])* $variant:ident = $number:literal, $name:literal;)*) => {
        /// A kind of object the game defines, by its type number in the object layer.
        ///
        /// The names are the game's (`GameObjectType`); [`ObjectKind::name`] spells them as it
        /// does. Numbers the game does not define have no kind (see [`SpawnPoint::kind`]).
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[non_exhaustive]
        pub enum ObjectKind {
            $($(#[doc = $doc])* $variant,)*
        }

        impl ObjectKind {
            /// Every kind, by increasing type number.
            pub const ALL: &'static [ObjectKind] = &[$(ObjectKind::$variant,)*];

            /// The kind of type number `number`, or `None` when the game defines none.
            #[must_use]
            pub const fn from_type(number: u8) -> Option<Self> {
                match number {
                    $($number => Some(Self::$variant),)*
                    _ => None,
                }
            }

            /// Its type number in the object layer.
            #[must_use]
            pub const fn type_number(self) -> u8 {
                match self {
                    $(Self::$variant => $number,)*
                }
            }

            /// The game's name for it, as its source spells it (`"BAT"`, `"DOOR_RED"`).
            #[must_use]
            pub const fn name(self) -> &'static str {
                match self {
                    $(Self::$variant => $name,)*
                }
            }
        }
    };
}

object_kinds! {
    /// Where the player starts (the game spawns one player per `PLAYER` spawn and plays the last).
    Player = 0, "PLAYER";
    /// A coin (a pearl, in the game's pictures).
    Coin = 1, "COIN";
    /// A ruby (one of the three gems a level hides).
    Ruby = 2, "RUBY";
    /// A diary page.
    Diary = 3, "DIARY";
    /// A bat: flies back and forth.
    Bat = 6, "BAT";
    /// A sting: flies back and forth.
    Sting = 7, "STING";
    /// An onion: walks back and forth.
    Onion = 8, "ONION";
    /// Wanda (a story character).
    Wanda = 10, "WANDA";
    /// Kyle (a story character).
    Kyle = 11, "KYLE";
    /// Kyle, dead (a story prop).
    KyleDead = 12, "KYLE_DEAD";
    /// Andou, dead (a story prop).
    AndouDead = 13, "ANDOU_DEAD";
    /// A brobot: walks back and forth.
    Brobot = 16, "BROBOT";
    /// A snail bomb: walks back and forth and shoots.
    SnailBomb = 17, "SNAILBOMB";
    /// A shadow slime: rises from the ground near the player.
    ShadowSlime = 18, "SHADOWSLIME";
    /// A mud man: walks back and forth and strikes.
    Mudman = 19, "MUDMAN";
    /// A skeleton: walks back and forth and strikes.
    Skeleton = 20, "SKELETON";
    /// A karaguin: swims (flies) back and forth.
    Karaguin = 21, "KARAGUIN";
    /// A pink namazu: a large fish that jumps from the ground.
    PinkNamazu = 22, "PINK_NAMAZU";
    /// A turret facing right.
    Turret = 23, "TURRET";
    /// A turret facing left.
    TurretLeft = 24, "TURRET_LEFT";
    /// Kabocha (a story character).
    Kabocha = 26, "KABOCHA";
    /// Rokudou's terminal.
    RokudouTerminal = 27, "ROKUDOU_TERMINAL";
    /// Kabocha's terminal.
    KabochaTerminal = 28, "KABOCHA_TERMINAL";
    /// Evil Kabocha (a boss).
    EvilKabocha = 29, "EVIL_KABOCHA";
    /// Rokudou (a boss).
    Rokudou = 30, "ROKUDOU";
    /// A red door, opened by the red button.
    DoorRed = 32, "DOOR_RED";
    /// A blue door, opened by the blue button.
    DoorBlue = 33, "DOOR_BLUE";
    /// A green door, opened by the green button.
    DoorGreen = 34, "DOOR_GREEN";
    /// The red button.
    ButtonRed = 35, "BUTTON_RED";
    /// The blue button.
    ButtonBlue = 36, "BUTTON_BLUE";
    /// The green button.
    ButtonGreen = 37, "BUTTON_GREEN";
    /// A cannon that launches the player.
    Cannon = 38, "CANNON";
    /// A brobot spawner facing right.
    BrobotSpawner = 39, "BROBOT_SPAWNER";
    /// A brobot spawner facing left.
    BrobotSpawnerLeft = 40, "BROBOT_SPAWNER_LEFT";
    /// A block the player breaks by stomping.
    BreakableBlock = 41, "BREAKABLE_BLOCK";
    /// The Source (the last level's goal).
    TheSource = 42, "THE_SOURCE";
    /// A sign with a hint.
    HintSign = 43, "HINT_SIGN";
    /// A puff of dust (an effect).
    Dust = 48, "DUST";
    /// A small explosion (an effect).
    ExplosionSmall = 49, "EXPLOSION_SMALL";
    /// A large explosion (an effect).
    ExplosionLarge = 50, "EXPLOSION_LARGE";
    /// A giant explosion (an effect).
    ExplosionGiant = 51, "EXPLOSION_GIANT";
    /// A red door that does not block.
    DoorRedNonblocking = 52, "DOOR_RED_NONBLOCKING";
    /// A blue door that does not block.
    DoorBlueNonblocking = 53, "DOOR_BLUE_NONBLOCKING";
    /// A green door that does not block.
    DoorGreenNonblocking = 54, "DOOR_GREEN_NONBLOCKING";
    /// An invisible character moved by hot spots.
    GhostNpc = 55, "GHOST_NPC";
    /// A point the camera leans towards.
    CameraBias = 56, "CAMERA_BIAS";
    /// A frame-rate watcher (a test object).
    FramerateWatcher = 57, "FRAMERATE_WATCHER";
    /// A spawner without end (a test object).
    InfiniteSpawner = 58, "INFINITE_SPAWNER";
    /// Andou crushed (a story prop).
    CrusherAndou = 59, "CRUSHER_ANDOU";
    /// A cannon ball.
    CannonBall = 65, "CANNON_BALL";
    /// A turret's bullet.
    TurretBullet = 66, "TURRET_BULLET";
    /// A brobot's bullet.
    BrobotBullet = 67, "BROBOT_BULLET";
    /// An energy ball (the game also numbers a breakable block's piece 68; it spawns this).
    EnergyBall = 68, "ENERGY_BALL";
    /// What spawns a breakable block's pieces.
    BreakableBlockPieceSpawner = 69, "BREAKABLE_BLOCK_PIECE_SPAWNER";
    /// Wanda's shot.
    WandaShot = 70, "WANDA_SHOT";
}

impl fmt::Display for ObjectKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One object of a level's object layer: what the game spawns, and where.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpawnPoint {
    /// The type number in the file (0 to 127).
    pub type_number: u8,
    /// The game's kind for that number, or `None` when the game defines none (it then
    /// spawns nothing there).
    pub kind: Option<ObjectKind>,
    /// The cell, in the map's rows (row 0 at the bottom, as [`parse_level`]'s map).
    ///
    /// [`parse_level`]: super::replica::parse_level
    pub cell: Cell,
    /// The bottom-left corner of the cell, in world pixels: the point the game spawns the
    /// object at. The game then centres an object across the cell, and stands an object at
    /// least a tile tall on the cell's bottom or centres a shorter one in it.
    pub position: Vec2,
}

impl SpawnPoint {
    /// The spawn point of type `type_number` in `cell`.
    #[must_use]
    pub fn new(type_number: u8, cell: Cell) -> Self {
        Self {
            type_number,
            kind: ObjectKind::from_type(type_number),
            cell,
            position: Vec2::new(cell.col as f32, cell.row as f32) * TILE_SIZE,
        }
    }

    /// The middle of the cell's bottom side: where the game stands an object at least a
    /// tile tall.
    #[must_use]
    pub fn bottom_middle(&self) -> Vec2 {
        self.position + Vec2::new(0.5 * TILE_SIZE, 0.0)
    }

    /// The centre of the cell: where the game centres an object smaller than a tile.
    #[must_use]
    pub fn center(&self) -> Vec2 {
        self.position + Vec2::splat(0.5 * TILE_SIZE)
    }
}

/// What a hot-spot code tells the game objects over it, as the game names its codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum HotSpotKind {
    /// `GO_RIGHT` (0): an enemy patrolling here turns right.
    GoRight,
    /// `GO_LEFT` (1): an enemy patrolling here turns left.
    GoLeft,
    /// `GO_UP` (2): a flying enemy turns up.
    GoUp,
    /// `GO_DOWN` (3): a flying enemy turns down.
    GoDown,
    /// `WAIT_SHORT` (4).
    WaitShort,
    /// `WAIT_MEDIUM` (5).
    WaitMedium,
    /// `WAIT_LONG` (6).
    WaitLong,
    /// `ATTACK` (7).
    Attack,
    /// `TALK` (8): a character starts a conversation.
    Talk,
    /// `DIE` (9): whatever enters dies (pits, spikes).
    Die,
    /// `WALK_AND_TALK` (10).
    WalkAndTalk,
    /// `TAKE_CAMERA_FOCUS` (11).
    TakeCameraFocus,
    /// `RELEASE_CAMERA_FOCUS` (12).
    ReleaseCameraFocus,
    /// `END_LEVEL` (13): the player ends the level here.
    EndLevel,
    /// `GAME_EVENT` (14).
    GameEvent,
    /// `NPC_RUN_QUEUED_COMMANDS` (15).
    NpcRunQueuedCommands,
    /// `NPC_GO_RIGHT` (16).
    NpcGoRight,
    /// `NPC_GO_LEFT` (17).
    NpcGoLeft,
    /// `NPC_GO_UP` (18).
    NpcGoUp,
    /// `NPC_GO_DOWN` (19).
    NpcGoDown,
    /// `NPC_GO_UP_RIGHT` (20).
    NpcGoUpRight,
    /// `NPC_GO_UP_LEFT` (21).
    NpcGoUpLeft,
    /// `NPC_GO_DOWN_LEFT` (22).
    NpcGoDownLeft,
    /// `NPC_GO_DOWN_RIGHT` (23).
    NpcGoDownRight,
    /// `NPC_GO_TOWARDS_PLAYER` (24).
    NpcGoTowardsPlayer,
    /// `NPC_GO_RANDOM` (25).
    NpcGoRandom,
    /// `NPC_GO_UP_FROM_GROUND` (26).
    NpcGoUpFromGround,
    /// `NPC_GO_DOWN_FROM_CEILING` (27).
    NpcGoDownFromCeiling,
    /// `NPC_STOP` (28).
    NpcStop,
    /// `NPC_SLOW` (29).
    NpcSlow,
    /// `NPC_SELECT_DIALOG_C_E` (32–36 for character 1, 38–42 for character 2): a character
    /// walking here picks entry `entry` (1–5) of character `character`'s (1 or 2) dialog.
    NpcSelectDialog {
        /// Whose dialog: 1 or 2.
        character: u8,
        /// Which entry of it: 1 to 5.
        entry: u8,
    },
}

/// The codes of the hot spots without data, in code order from 0.
const PLAIN_HOT_SPOTS: [(HotSpotKind, &str); 30] = [
    (HotSpotKind::GoRight, "GO_RIGHT"),
    (HotSpotKind::GoLeft, "GO_LEFT"),
    (HotSpotKind::GoUp, "GO_UP"),
    (HotSpotKind::GoDown, "GO_DOWN"),
    (HotSpotKind::WaitShort, "WAIT_SHORT"),
    (HotSpotKind::WaitMedium, "WAIT_MEDIUM"),
    (HotSpotKind::WaitLong, "WAIT_LONG"),
    (HotSpotKind::Attack, "ATTACK"),
    (HotSpotKind::Talk, "TALK"),
    (HotSpotKind::Die, "DIE"),
    (HotSpotKind::WalkAndTalk, "WALK_AND_TALK"),
    (HotSpotKind::TakeCameraFocus, "TAKE_CAMERA_FOCUS"),
    (HotSpotKind::ReleaseCameraFocus, "RELEASE_CAMERA_FOCUS"),
    (HotSpotKind::EndLevel, "END_LEVEL"),
    (HotSpotKind::GameEvent, "GAME_EVENT"),
    (HotSpotKind::NpcRunQueuedCommands, "NPC_RUN_QUEUED_COMMANDS"),
    (HotSpotKind::NpcGoRight, "NPC_GO_RIGHT"),
    (HotSpotKind::NpcGoLeft, "NPC_GO_LEFT"),
    (HotSpotKind::NpcGoUp, "NPC_GO_UP"),
    (HotSpotKind::NpcGoDown, "NPC_GO_DOWN"),
    (HotSpotKind::NpcGoUpRight, "NPC_GO_UP_RIGHT"),
    (HotSpotKind::NpcGoUpLeft, "NPC_GO_UP_LEFT"),
    (HotSpotKind::NpcGoDownLeft, "NPC_GO_DOWN_LEFT"),
    (HotSpotKind::NpcGoDownRight, "NPC_GO_DOWN_RIGHT"),
    (HotSpotKind::NpcGoTowardsPlayer, "NPC_GO_TOWARDS_PLAYER"),
    (HotSpotKind::NpcGoRandom, "NPC_GO_RANDOM"),
    (HotSpotKind::NpcGoUpFromGround, "NPC_GO_UP_FROM_GROUND"),
    (
        HotSpotKind::NpcGoDownFromCeiling,
        "NPC_GO_DOWN_FROM_CEILING",
    ),
    (HotSpotKind::NpcStop, "NPC_STOP"),
    (HotSpotKind::NpcSlow, "NPC_SLOW"),
];

/// The first code of each character's dialog entries (five codes each).
const DIALOG_CODES: [u8; 2] = [32, 38];

/// The game's names of the dialog codes, character by character.
const DIALOG_NAMES: [[&str; 5]; 2] = [
    [
        "NPC_SELECT_DIALOG_1_1",
        "NPC_SELECT_DIALOG_1_2",
        "NPC_SELECT_DIALOG_1_3",
        "NPC_SELECT_DIALOG_1_4",
        "NPC_SELECT_DIALOG_1_5",
    ],
    [
        "NPC_SELECT_DIALOG_2_1",
        "NPC_SELECT_DIALOG_2_2",
        "NPC_SELECT_DIALOG_2_3",
        "NPC_SELECT_DIALOG_2_4",
        "NPC_SELECT_DIALOG_2_5",
    ],
];

impl HotSpotKind {
    /// The kind of hot-spot code `code`, or `None` when the game defines none.
    #[must_use]
    pub fn from_code(code: u8) -> Option<Self> {
        if let Some((kind, _)) = PLAIN_HOT_SPOTS.get(usize::from(code)) {
            return Some(*kind);
        }
        DIALOG_CODES
            .iter()
            .zip(1u8..)
            .find(|&(&first, _)| (first..first + 5).contains(&code))
            .map(|(&first, character)| Self::NpcSelectDialog {
                character,
                entry: code - first + 1,
            })
    }

    /// Its code in the hot-spot layer. A dialog entry out of the game's range (character
    /// not 1 or 2, entry not 1 to 5) has none.
    #[must_use]
    pub fn code(self) -> Option<u8> {
        match self {
            Self::NpcSelectDialog { character, entry } => {
                let first = DIALOG_CODES.get(usize::from(character).checked_sub(1)?)?;
                (1..=5).contains(&entry).then(|| first + entry - 1)
            }
            plain => (0u8..)
                .zip(PLAIN_HOT_SPOTS)
                .find(|(_, (kind, _))| *kind == plain)
                .map(|(code, _)| code),
        }
    }

    /// The game's name for it (`"GO_LEFT"`, `"NPC_SELECT_DIALOG_2_1"`); `"NPC_SELECT_DIALOG"`
    /// for a dialog entry out of the game's range.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::NpcSelectDialog { character, entry } => usize::from(character)
                .checked_sub(1)
                .and_then(|c| DIALOG_NAMES.get(c))
                .and_then(|names| names.get(usize::from(entry).checked_sub(1)?))
                .copied()
                .unwrap_or("NPC_SELECT_DIALOG"),
            plain => PLAIN_HOT_SPOTS
                .iter()
                .find(|(kind, _)| *kind == plain)
                .map_or("", |(_, name)| name),
        }
    }
}

impl fmt::Display for HotSpotKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A level's hot-spot layer: one code per cell of the collision layer's grid, or none.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HotSpots {
    width: u32,
    height: u32,
    /// Row-major from the bottom row (the map's rows); negative: no hot spot.
    codes: Vec<i8>,
}

impl HotSpots {
    /// A grid of `width × height` cells from the layer's bytes (top row first, as in the
    /// file). The caller has checked that `bytes` holds `width × height` cells.
    pub(super) fn from_file_rows(width: u32, height: u32, bytes: &[u8]) -> Self {
        let w = width as usize;
        let codes = bytes
            .chunks_exact(w.max(1))
            .rev()
            .flat_map(|row| row.iter().map(|&b| b as i8))
            .collect();
        Self {
            width,
            height,
            codes,
        }
    }

    /// Columns.
    #[must_use]
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Rows.
    #[must_use]
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The code in `cell` (0 to 127), or `None` for no hot spot or a cell outside the grid.
    #[must_use]
    pub fn code(&self, cell: Cell) -> Option<u8> {
        if cell.col >= self.width || cell.row >= self.height {
            return None;
        }
        let code = *self
            .codes
            .get(cell.row as usize * self.width as usize + cell.col as usize)?;
        u8::try_from(code).ok()
    }

    /// The named kind of the hot spot in `cell`, or `None` for no hot spot, a code the
    /// game does not define, or a cell outside the grid.
    #[must_use]
    pub fn kind(&self, cell: Cell) -> Option<HotSpotKind> {
        self.code(cell).and_then(HotSpotKind::from_code)
    }

    /// The code of the hot spot under world point `p` (pixels), as the game looks it up;
    /// `None` off the grid or for no hot spot.
    #[must_use]
    pub fn code_at(&self, p: Vec2) -> Option<u8> {
        let g = (p / TILE_SIZE).floor();
        if !(g.x >= 0.0 && g.y >= 0.0 && g.x < self.width as f32 && g.y < self.height as f32) {
            return None;
        }
        self.code(Cell::new(g.x as u32, g.y as u32))
    }

    /// Every cell that holds a hot spot, with its code: the bottom row first, left to right.
    pub fn iter(&self) -> impl Iterator<Item = (Cell, u8)> + '_ {
        let w = self.width.max(1);
        (0u32..).zip(&self.codes).filter_map(move |(i, &code)| {
            let code = u8::try_from(code).ok()?;
            Some((Cell::new(i % w, i / w), code))
        })
    }
}

/// A layer of a level file whose cells the file cuts short. The game reads such a layer as
/// empty, and so does [`parse_objects`](super::replica::parse_objects).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutLayer {
    /// Its place among the file's layers, from 0.
    pub index: usize,
    /// Its `type` byte: 2 for objects, 3 for hot spots.
    pub layer_type: i8,
    /// Byte offset of its first cell.
    pub cells_at: u64,
    /// The cells its header declares.
    pub cells: u64,
    /// The bytes of them the file holds.
    pub present: u64,
}

/// What a Replica Island level places beside its collision: the spawn points of its object
/// layer and the codes of its hot-spot layer, on the collision layer's grid.
#[derive(Clone, Debug, PartialEq)]
pub struct LevelObjects {
    /// Columns of the collision layer (and of the object and hot-spot layers).
    pub width: u32,
    /// Rows of the collision layer.
    pub height: u32,
    /// Every object of the object layer, in the file's order (the game's spawn order: the
    /// top row first, left to right). Empty when the level has no object layer.
    pub objects: Vec<SpawnPoint>,
    /// The hot-spot layer, when the level has one.
    pub hot_spots: Option<HotSpots>,
    /// The last layer, when the file cuts it short (read as empty, as the game does).
    pub cut_short: Option<CutLayer>,
}

impl LevelObjects {
    /// Where the player starts: the last `PLAYER` spawn in the file's order (the game
    /// spawns a player at each and plays the last one spawned), or `None` without one.
    #[must_use]
    pub fn player_spawn(&self) -> Option<&SpawnPoint> {
        self.objects
            .iter()
            .rev()
            .find(|o| o.kind == Some(ObjectKind::Player))
    }

    /// The objects of `kind`, in the file's order.
    pub fn of_kind(&self, kind: ObjectKind) -> impl Iterator<Item = &SpawnPoint> + '_ {
        self.objects.iter().filter(move |o| o.kind == Some(kind))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn object_kinds_round_trip_through_their_numbers() {
        for &kind in ObjectKind::ALL {
            assert_eq!(ObjectKind::from_type(kind.type_number()), Some(kind));
        }
        let numbers: Vec<u8> = ObjectKind::ALL.iter().map(|k| k.type_number()).collect();
        assert!(numbers.windows(2).all(|w| w[0] < w[1]), "{numbers:?}");
        assert_eq!(ObjectKind::from_type(6), Some(ObjectKind::Bat));
        assert_eq!(ObjectKind::Bat.to_string(), "BAT");
        // Gaps in the game's numbering have no kind.
        for n in [4, 5, 9, 14, 15, 25, 31, 44, 60, 64, 71, 127] {
            assert_eq!(ObjectKind::from_type(n), None, "{n}");
        }
    }

    #[test]
    fn hot_spot_codes_round_trip_and_dialogs_carry_their_entry() {
        let mut named = 0;
        for code in 0..=127u8 {
            if let Some(kind) = HotSpotKind::from_code(code) {
                named += 1;
                assert_eq!(kind.code(), Some(code), "{kind:?}");
                assert!(!kind.name().is_empty());
            }
        }
        assert_eq!(named, 40);
        assert_eq!(
            HotSpotKind::from_code(39),
            Some(HotSpotKind::NpcSelectDialog {
                character: 2,
                entry: 2
            })
        );
        assert_eq!(
            HotSpotKind::from_code(39).unwrap().name(),
            "NPC_SELECT_DIALOG_2_2"
        );
        assert_eq!(HotSpotKind::from_code(9), Some(HotSpotKind::Die));
        for code in [30, 31, 37, 43, 127] {
            assert_eq!(HotSpotKind::from_code(code), None, "{code}");
        }
        let stray = HotSpotKind::NpcSelectDialog {
            character: 3,
            entry: 1,
        };
        assert_eq!((stray.code(), stray.name()), (None, "NPC_SELECT_DIALOG"));
    }

    #[test]
    fn hot_spots_flip_file_rows_so_row_0_is_the_bottom() {
        // Two rows of three, top row first in the file: GO_LEFT top left, DIE bottom right.
        let spots = HotSpots::from_file_rows(3, 2, &[1, 0xff, 0xff, 0xff, 0xff, 9]);
        assert_eq!(spots.kind(Cell::new(0, 1)), Some(HotSpotKind::GoLeft));
        assert_eq!(spots.kind(Cell::new(2, 0)), Some(HotSpotKind::Die));
        assert_eq!(spots.code(Cell::new(1, 0)), None);
        assert_eq!(spots.code(Cell::new(3, 0)), None);
        assert_eq!(
            spots.iter().collect::<Vec<_>>(),
            [(Cell::new(2, 0), 9), (Cell::new(0, 1), 1)]
        );
        assert_eq!(spots.code_at(Vec2::new(70.0, 5.0)), Some(9));
        assert_eq!(spots.code_at(Vec2::new(5.0, 40.0)), Some(1));
        for off in [
            Vec2::new(-0.5, 5.0),
            Vec2::new(96.0, 5.0),
            Vec2::new(5.0, 64.0),
            Vec2::NAN,
        ] {
            assert_eq!(spots.code_at(off), None, "{off}");
        }
    }

    #[test]
    fn a_spawn_point_is_placed_at_its_cells_corner() {
        let p = SpawnPoint::new(1, Cell::new(2, 3));
        assert_eq!(p.kind, Some(ObjectKind::Coin));
        assert_eq!(p.position, Vec2::new(64.0, 96.0));
        assert_eq!(p.center(), Vec2::new(80.0, 112.0));
        assert_eq!(p.bottom_middle(), Vec2::new(80.0, 96.0));
        assert_eq!(SpawnPoint::new(4, Cell::new(0, 0)).kind, None);
    }
}
