//! A player keeps the dungeon: digging and summoning by order, their prices, the refusals
//! and why, replays, and how a game ends.
#![allow(clippy::unwrap_used)]

use tileslide::{Cell, Vec2};
use tileslide_dungeon::{
    DIG_COST, Game, GameConfig, KeeperMode, Kind, MAX_CREATURES, Order, OrderError, Outcome,
    PLAYER_START_GOLD, Party, Team, creature_cost,
};

fn player_game(seed: u64) -> Game {
    Game::with_config(GameConfig::player(seed)).unwrap()
}

/// Earth beside the corridor a player's dungeon starts with (column 32–33).
const BESIDE_CORRIDOR: Cell = Cell { col: 31, row: 20 };

fn centre(cell: Cell) -> Vec2 {
    Vec2::new(cell.col as f32 + 0.5, cell.row as f32 + 0.5)
}

#[test]
fn digging_costs_50_gold_opens_the_square_and_updates_the_navigation() {
    let mut game = player_game(1);
    assert_eq!(game.mode(), KeeperMode::Player);
    assert_eq!(game.gold(), PLAYER_START_GOLD);
    let cell = BESIDE_CORRIDOR;
    let imp = Kind::Imp.radius();
    assert!(game.is_diggable(cell));
    assert!(game.map().tile(cell).is_some());
    assert!(
        !game
            .level()
            .nav
            .fits(game.map(), centre(cell), imp)
            .unwrap()
    );
    let further = Cell::new(30, 20);
    assert!(!game.is_diggable(further), "not beside an open square yet");

    game.dig(cell).unwrap();

    assert_eq!(DIG_COST, 50);
    assert_eq!(game.gold(), PLAYER_START_GOLD - 50);
    assert!(game.map().tile(cell).is_none());
    assert!(
        game.level()
            .nav
            .fits(game.map(), centre(cell), imp)
            .unwrap()
    );
    assert_eq!(game.summary().squares_dug, 1);
    assert_eq!(game.dug(), &[cell]);
    assert!(!game.is_diggable(cell));
    assert!(game.is_diggable(further), "beside the new square");
    let diggable = game.diggable();
    assert!(diggable.contains(&further) && !diggable.contains(&cell));
    assert!(diggable.iter().all(|&c| game.is_diggable(c)));
    assert_eq!(
        game.orders()
            .iter()
            .map(|o| (o.step, o.order))
            .collect::<Vec<_>>(),
        [(0, Order::Dig(cell))]
    );
}

#[test]
fn income_keeps_flowing_for_a_player() {
    let mut game = player_game(1);
    for _ in 0..30 {
        game.step().unwrap();
    }
    assert_eq!(game.gold(), PLAYER_START_GOLD + 20);
}

#[test]
fn summons_cost_their_price_and_stand_where_ordered() {
    let mut game = player_game(1);
    let (skeleton, imp) = (
        creature_cost(Kind::Skeleton).unwrap(),
        creature_cost(Kind::Imp).unwrap(),
    );
    assert_eq!((skeleton, imp, creature_cost(Kind::Hero)), (35, 50, None));
    let at = Vec2::new(32.5, 20.5);
    game.summon(Kind::Skeleton, at).unwrap();
    assert_eq!(game.gold(), PLAYER_START_GOLD - skeleton);
    // The same place is taken: the imp goes to the first free place near it.
    game.summon(Kind::Imp, at).unwrap();
    assert_eq!(game.gold(), PLAYER_START_GOLD - skeleton - imp);
    assert_eq!(game.creatures_alive(), 2);
    assert_eq!(game.summary().creatures_summoned, 2);
    let fighters = game.fighters();
    assert_eq!(fighters.len(), 2);
    assert_eq!(
        (fighters[0].kind, fighters[0].position),
        (Kind::Skeleton, at)
    );
    assert_eq!(fighters[1].kind, Kind::Imp);
    assert_eq!(fighters[1].team, Team::Keeper);
    let gap = fighters[0].position.distance(fighters[1].position);
    assert!(gap > Kind::Skeleton.radius() + Kind::Imp.radius(), "{gap}");
    assert!(gap < 3.0, "{gap}");
}

#[test]
fn refused_orders_say_why_and_change_nothing() {
    let mut game = player_game(1);
    let before = game.state_hash();
    let refusals = [
        (
            Order::Dig(Cell::new(0, 0)),
            "digging square (0, 0): the square is rock; only earth can be dug",
        ),
        (
            Order::Dig(Cell::new(32, 20)),
            "digging square (32, 20): the square is open already",
        ),
        (
            Order::Dig(Cell::new(20, 20)),
            "digging square (20, 20): the square is not beside an open square",
        ),
        (
            Order::Dig(Cell::new(64, 3)),
            "digging square (64, 3): the square is outside the 64 × 64 map",
        ),
        (
            Order::Summon(Kind::Hero, Vec2::new(32.5, 20.5)),
            "summoning a hero at (32.5, 20.5): the keeper summons imps and skeletons only",
        ),
        (
            Order::Summon(Kind::Imp, Vec2::new(f32::NAN, 20.5)),
            "summoning an imp at (NaN, 20.5): the point must be finite",
        ),
        (
            Order::Summon(Kind::Imp, Vec2::new(20.5, 20.5)),
            "summoning an imp at (20.5, 20.5): the point is not in an open square",
        ),
        (
            Order::Summon(Kind::Imp, Vec2::new(-3.0, 1e9)),
            "summoning an imp at (-3, 1000000000): the point is not in an open square",
        ),
    ];
    for (order, message) in refusals {
        let err = game.order(order).unwrap_err();
        assert_eq!(err.to_string(), message);
    }
    assert!(matches!(
        game.order(Order::Dig(Cell::new(0, 0))),
        Err(OrderError::Rock { .. })
    ));
    assert_eq!(game.state_hash(), before);
    assert_eq!(game.gold(), PLAYER_START_GOLD);
    assert!(game.orders().is_empty());
}

#[test]
fn a_keeper_without_the_gold_is_refused() {
    let mut game = player_game(1);
    // 300 gold: six squares down column 31.
    for row in 15..21 {
        game.dig(Cell::new(31, row)).unwrap();
    }
    assert_eq!(game.gold(), 0);
    let err = game.dig(Cell::new(30, 20)).unwrap_err();
    assert!(
        matches!(
            err,
            OrderError::NotEnoughGold {
                cost: 50,
                gold: 0,
                ..
            }
        ),
        "{err}"
    );
    assert_eq!(
        err.to_string(),
        "digging square (30, 20): it costs 50 gold and the keeper has 0"
    );
    assert!(game.map().tile(Cell::new(30, 20)).is_some());
    let err = game.summon(Kind::Imp, Vec2::new(32.5, 20.5)).unwrap_err();
    assert!(
        matches!(err, OrderError::NotEnoughGold { cost: 50, .. }),
        "{err}"
    );
}

#[test]
fn a_keeper_keeps_at_most_eight_creatures() {
    let mut game = player_game(1);
    for k in 0..MAX_CREATURES {
        let at = Vec2::new(32.5, 10.5 + 2.0 * k as f32);
        game.summon(Kind::Skeleton, at).unwrap();
    }
    let err = game
        .summon(Kind::Skeleton, Vec2::new(33.0, 30.5))
        .unwrap_err();
    assert!(matches!(err, OrderError::TooManyCreatures { .. }), "{err}");
    assert_eq!(game.creatures_alive(), MAX_CREATURES);
}

#[test]
fn the_scripted_keeper_takes_no_orders() {
    let mut game = Game::new(1).unwrap();
    let err = game.dig(Cell::new(32, 28)).unwrap_err();
    assert!(matches!(err, OrderError::Scripted { .. }), "{err}");
    // Its squares are still marked diggable for a picture.
    assert!(game.is_diggable(Cell::new(32, 28)));
}

/// A short game of orders: three squares and two creatures before the first party, one
/// more square while it explores.
fn play(game: &mut Game) {
    let mut orders = vec![
        (0, Order::Dig(Cell::new(31, 20))),
        (0, Order::Dig(Cell::new(30, 20))),
        (10, Order::Summon(Kind::Skeleton, Vec2::new(31.0, 20.5))),
        (200, Order::Summon(Kind::Imp, Vec2::new(32.5, 25.5))),
        (400, Order::Dig(Cell::new(34, 24))),
    ];
    orders.reverse();
    for step in 0..600 {
        while orders.last().is_some_and(|o| o.0 == step) {
            let (_, order) = orders.pop().unwrap();
            game.order(order).unwrap();
        }
        game.step().unwrap();
    }
}

#[test]
fn the_same_seed_and_orders_give_the_same_game() {
    let mut played = player_game(5);
    play(&mut played);
    assert_eq!(played.orders().len(), 5);
    // Replaying the log.
    let mut replayed = player_game(5);
    let log = played.orders().to_vec();
    let mut next = 0;
    for step in 0..600 {
        while next < log.len() && log[next].step == step {
            replayed.order(log[next].order).unwrap();
            next += 1;
        }
        replayed.step().unwrap();
    }
    assert_eq!(replayed.state_hash(), played.state_hash());
    assert_eq!(replayed.summary(), played.summary());
    // Without the orders, another game.
    let mut idle = player_game(5);
    for _ in 0..600 {
        idle.step().unwrap();
    }
    assert_ne!(idle.state_hash(), played.state_hash());
}

#[test]
fn an_undefended_players_dungeon_is_lost_when_the_treasure_is_gone() {
    let mut game = player_game(1);
    let mut steps = 0;
    while game.outcome() == Outcome::Playing && steps < 6 * 60 * 30 {
        game.step().unwrap();
        steps += 1;
    }
    let s = game.summary();
    assert_eq!(game.outcome(), Outcome::Lost, "{s:?}");
    assert_eq!((s.treasure_stolen, s.treasure_left), (5, 0), "{s:?}");
    let err = game.dig(BESIDE_CORRIDOR).unwrap_err();
    assert!(matches!(err, OrderError::GameOver { .. }), "{err}");
}

#[test]
fn seeing_off_the_last_party_wins() {
    let mut game = Game::with_config(GameConfig {
        waves_to_win: Some(1),
        party: Party {
            min_heroes: 1,
            max_heroes: 1,
            hero_hp: 5,
        },
        ..GameConfig::player(1)
    })
    .unwrap();
    game.summon(Kind::Skeleton, Vec2::new(32.5, 12.5)).unwrap();
    game.summon(Kind::Imp, Vec2::new(32.5, 16.5)).unwrap();
    let mut steps = 0;
    while game.outcome() == Outcome::Playing && steps < 60 * 30 {
        assert!(game.next_wave_in().is_some() || game.summary().waves == 1);
        game.step().unwrap();
        steps += 1;
    }
    let s = game.summary();
    assert_eq!(game.outcome(), Outcome::Won, "{s:?}");
    assert_eq!(
        (s.waves, s.heroes_lost, s.treasure_left),
        (1, 1, 5),
        "{s:?}"
    );
    assert_eq!(game.next_wave_in(), None);
    assert_eq!(game.heroes_alive(), 0);
}

#[test]
fn the_next_party_is_counted_down() {
    let mut game = player_game(1);
    assert_eq!(game.next_wave_in(), Some(12 * 30));
    for _ in 0..12 * 30 {
        game.step().unwrap();
    }
    assert_eq!(game.next_wave_in(), Some(0));
    game.step().unwrap();
    assert_eq!(game.summary().waves, 1);
    assert_eq!(game.next_wave_in(), Some(30 * 30 - 1));
}
