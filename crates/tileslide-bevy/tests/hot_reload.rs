//! A map file changed on disk is reloaded, and the collision map follows (feature
//! `hot_reload`: Bevy's file watcher).

#![cfg(feature = "hot_reload")]
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod support;

use std::time::{Duration, Instant};

use tileslide::Cell;
use tileslide_bevy::CollisionMap;

#[test]
fn a_map_file_changed_on_disk_replaces_the_collision_map() {
    let root = std::env::temp_dir().join(format!("tileslide-bevy-reload-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    std::fs::write(root.join("room.txt"), "####\n#..#\n####\n").unwrap();
    let mut app = support::app_reading(&root);
    let handle = support::load(&mut app, "room.txt");
    app.insert_resource(CollisionMap::from_asset(handle.clone()));
    support::assert_loaded(&mut app, &handle);
    app.update();
    assert_eq!(app.world().resource::<CollisionMap>().generation(), 1);
    // Dig a wall into the room on disk.
    std::fs::write(root.join("room.txt"), "####\n#.##\n####\n").unwrap();
    let start = Instant::now();
    while app.world().resource::<CollisionMap>().generation() < 2 {
        assert!(start.elapsed() < Duration::from_secs(20), "no reload");
        app.update();
        std::thread::sleep(Duration::from_millis(10));
    }
    let map = app.world().resource::<CollisionMap>();
    assert!(map.map().unwrap().tile(Cell::new(2, 1)).is_some());
}
