//! The platformer player's last move in words, for the playground's click on the player:
//! the move traced by the controller ([`tileslide::MoveTrace`]) worded by
//! `tileslide-explain`, as `tileslide explain --character` words a scene's character.

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
}
