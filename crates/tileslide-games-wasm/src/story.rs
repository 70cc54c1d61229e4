//! The last step in words, for the playground's clicks: the platformer player's move traced
//! by the controller ([`tileslide::MoveTrace`]), as `tileslide explain --character` words a
//! scene's character; and a Dungeon Builder fighter's step traced by the resolver
//! ([`tileslide::BodyTrace`]), as `tileslide explain --body` words a body. The words are
//! `tileslide-explain`'s.

use tileslide::BodyHandle;
use tileslide_dungeon::{Game as Dungeon, Kind};
use tileslide_platformer::Game;

/// Starts (`true`) or stops tracing the player's moves; stopping drops the last trace.
pub fn trace_player(game: &mut Game, on: bool) {
    let trace = &mut game.player.trace;
    if on != trace.is_some() {
        *trace = on.then(Default::default);
    }
}

/// The player's last move in words, headed with the game's step; `None` when its moves are
/// not traced or none was made since tracing started.
#[must_use]
pub fn player_story(game: &Game) -> Option<String> {
    let trace = game.player.trace.as_ref()?;
    if trace.events.is_empty() {
        return None;
    }
    let heading = format!("player, step {}", game.summary().steps);
    Some(tileslide_explain::character::step_words(&heading, trace))
}

/// A fighter's name in the stories: its kind and id, e.g. `imp 7`.
fn fighter_name(id: u64, kind: Kind) -> String {
    let kind = match kind {
        Kind::Hero => "hero",
        Kind::Skeleton => "skeleton",
        Kind::Imp => "imp",
    };
    format!("{kind} {id}")
}

/// The fighter alive whose circle holds (`x`, `y`) (the nearest centre), or `None`.
#[must_use]
pub fn fighter_at(game: &Dungeon, x: f32, y: f32) -> Option<u64> {
    let at = tileslide::Vec2::new(x, y);
    game.fighters()
        .iter()
        .map(|f| (f.id, f.position.distance(at), f.radius))
        .filter(|&(_, d, r)| d <= r)
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(id, _, _)| id)
}

/// Fighter `id`'s last step in words, headed with its name and the game's step; `None`
/// when the bodies' steps are not traced, no fighter `id` is alive, or it came after the
/// step.
#[must_use]
pub fn fighter_story(game: &Dungeon, id: u64) -> Option<String> {
    let story = game.body_trace(id)?;
    let (_, kind) = game.fighter_with_body(story.handle)?;
    let heading = format!("{}, step {}", fighter_name(id, kind), game.summary().steps);
    let name = |h: BodyHandle| {
        game.fighter_with_body(h)
            .map(|(id, kind)| fighter_name(id, kind))
    };
    Some(tileslide_explain::body::step_words(&heading, story, &name))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use tileslide_platformer::{Input, Level};

    use super::*;

    const ROOM: &str = "\
#######
#.....#
#..P..#
#######";

    #[test]
    fn the_players_last_move_says_what_it_stands_on() {
        let mut game = Game::new(Level::parse_ascii(ROOM, "room.txt").unwrap()).unwrap();
        assert_eq!(player_story(&game), None);
        trace_player(&mut game, true);
        assert_eq!(player_story(&game), None, "no move made yet");
        game.step_with(Input::default()).unwrap();
        let story = player_story(&game).unwrap();
        assert!(story.starts_with("player, step 1: at "), "{story}");
        assert!(story.contains("on the ground: cell ("), "{story}");
        assert!(story.contains(", 3) tile "), "{story}");
        trace_player(&mut game, false);
        assert_eq!(player_story(&game), None);
    }

    #[test]
    fn a_fighters_last_step_names_what_it_met() {
        let mut dungeon = Dungeon::new(1).unwrap();
        dungeon.trace_bodies(true);
        // The scripted keeper's game: its creatures and the first heroes press against
        // walls and each other within a game minute.
        let mut told = None;
        for _ in 0..1800 {
            dungeon.step().unwrap();
            told = dungeon.fighters().iter().find_map(|f| {
                let story = fighter_story(&dungeon, f.id)?;
                story.contains("<- first").then_some((f.id, story))
            });
            if told.is_some() {
                break;
            }
        }
        let (id, story) = told.expect("a fighter met something");
        let name = story.split(',').next().unwrap();
        assert!(name.ends_with(&format!(" {id}")), "{story}");
        assert!(
            story.contains("cell (") || story.contains(" circle "),
            "{story}"
        );
        let f = dungeon.fighters().into_iter().find(|f| f.id == id).unwrap();
        assert_eq!(fighter_at(&dungeon, f.position.x, f.position.y), Some(id));
        dungeon.trace_bodies(false);
        assert_eq!(fighter_story(&dungeon, id), None);
    }
}
