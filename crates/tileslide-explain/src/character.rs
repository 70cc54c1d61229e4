//! A character's move in words: each sweep and slide, ground snap, step-up, one-way pass,
//! carry and push, with the surfaces met and where they came from (a [`MoveTrace`] of
//! [`Character::move_by_traced`](tileslide::Character::move_by_traced)).

use tileslide::{MoveEvent, MoveTrace, OneWayPass, SlideResponse, Surface, SweepPurpose};

use crate::words::{num, point, wall};

/// What a sweep was for, in a word or two.
#[must_use]
pub fn purpose_words(p: SweepPurpose) -> &'static str {
    match p {
        SweepPurpose::Carry => "carried",
        SweepPurpose::PushOut => "pushed out",
        SweepPurpose::Walk => "walk",
        SweepPurpose::Air => "air",
        SweepPurpose::StepUp => "step up",
        SweepPurpose::Roll => "roll",
        SweepPurpose::StepOff => "step off",
        SweepPurpose::Settle => "settle",
        _ => "move",
    }
}

/// The surface a slide met.
#[must_use]
pub fn surface_words(s: Surface) -> &'static str {
    match s {
        Surface::Ground => "ground",
        Surface::Ceiling => "a ceiling",
        Surface::Left => "a wall on the left",
        Surface::Right => "a wall on the right",
    }
}

/// What the character did at a surface.
#[must_use]
pub fn response_words(r: SlideResponse) -> &'static str {
    match r {
        SlideResponse::Landed => "landed",
        SlideResponse::WalkedOn => "walked on along it",
        SlideResponse::SlidAlong => "slid along it",
        SlideResponse::SlidDown => "slid down it (sideways motion does not climb it)",
        SlideResponse::Stopped => "stopped (a walk does not climb it)",
        SlideResponse::Rolled => "rolled round the corner",
        _ => "went on",
    }
}

/// One event, in words; `n` numbers the surfaces met (counted up by each sweep that met
/// one).
#[must_use]
pub fn event_words(e: &MoveEvent, n: &mut usize) -> String {
    match *e {
        MoveEvent::Carried { owner, by } => {
            format!("carried {} by the platform of owner {}", point(by), owner.0)
        }
        MoveEvent::PlatformGone { owner } => {
            format!("the platform of owner {} is gone: off it", owner.0)
        }
        MoveEvent::Pushed {
            source,
            direction,
            depth,
            crushed,
        } => {
            let crush = if crushed {
                ": crushed, the world left no room"
            } else {
                ""
            };
            format!(
                "pushed out of {} ({} deep, towards {}){crush}",
                wall(&source),
                num(depth),
                point(direction)
            )
        }
        MoveEvent::Sweep(s) => {
            let met = match s.hit {
                Some(h) => {
                    *n += 1;
                    let one_way = if h.flags.contains(tileslide::SegmentFlags::ONE_WAY) {
                        " one-way"
                    } else {
                        ""
                    };
                    let end = if h.rounded { " (rounded end)" } else { "" };
                    format!(
                        ": [{n}] met {}{one_way}{end}, t {}, at {}, normal {}",
                        wall(&h.source),
                        num(h.t),
                        point(h.point),
                        point(h.normal)
                    )
                }
                None => ": clear".to_owned(),
            };
            format!(
                "sweep ({}) {} from {}{met}; moved {}",
                purpose_words(s.purpose),
                point(s.motion),
                point(s.from),
                point(s.moved)
            )
        }
        MoveEvent::Slide {
            surface,
            response,
            next,
        } => format!(
            "{}: {}, next {}",
            surface_words(surface),
            response_words(response),
            point(next)
        ),
        MoveEvent::OneWay { source, pass } => match pass {
            OneWayPass::FromBelow => format!(
                "one-way platform {}: passed, the character is below it",
                wall(&source)
            ),
            OneWayPass::DroppedThrough => {
                format!("one-way platform {}: dropped through", wall(&source))
            }
            _ => format!("one-way platform {}: not held", wall(&source)),
        },
        MoveEvent::SteppedUp { by } => format!("stepped up the ledge by {}", point(by)),
        MoveEvent::StepUpRefused => "step up tried and undone".to_owned(),
        MoveEvent::LeftGround { at } => format!("walked off the ground's edge at {}", point(at)),
        MoveEvent::Grounded {
            source,
            normal,
            drop,
        } => format!(
            "on the ground: {}, normal {}, dropped {}",
            wall(&source),
            point(normal),
            num(drop)
        ),
        MoveEvent::Airborne => "in the air".to_owned(),
        _ => format!("{e:?}"),
    }
}

/// One move of the character, in words, one line an event, headed `heading` (e.g.
/// `"character, step 3"`).
#[must_use]
pub fn step_words(heading: &str, t: &MoveTrace) -> String {
    let mut s = format!(
        "{heading}: at {}, move {}\n",
        point(t.start),
        point(t.displacement)
    );
    let mut n = 0;
    for e in &t.events {
        s += &format!("  {}\n", event_words(e, &mut n));
    }
    s += &format!("  ends at {}\n", point(t.end));
    s
}

#[cfg(test)]
mod tests {
    use tileslide::io::ascii;
    use tileslide::{Character, CharacterShape, ControllerConfig, MoveOptions, Vec2};

    use super::*;

    #[test]
    fn a_fall_onto_the_floor_lands_on_the_floors_cell() {
        let map = ascii::parse("#####\n#...#\n#...#\n#####", "test.txt", 1.0).unwrap();
        let shape = CharacterShape::rect(Vec2::new(0.25, 0.25)).unwrap();
        let mut hero = Character::new(
            shape,
            Vec2::new(2.5, 1.5),
            Vec2::NEG_Y,
            ControllerConfig::default(),
        )
        .unwrap();
        let mut trace = MoveTrace::default();
        hero.move_by_traced(
            &map,
            Vec2::new(0.0, 2.0),
            MoveOptions::default(),
            &mut trace,
        )
        .unwrap();
        let words = step_words("hero", &trace);
        assert!(
            words.starts_with("hero: at (2.500, 1.500), move (0.000, 2.000)\n"),
            "{words}"
        );
        assert!(words.contains("[1] met cell (2, 3) tile "), "{words}");
        assert!(words.contains("ground: landed"), "{words}");
    }
}
