//! `tileslide explain`: its words against golden outputs (`tests/explain/*.toml` and
//! `.stdout`, checked by trycmd; `TRYCMD=overwrite` rewrites them, to be read before they
//! are kept), its JSON, and its pictures.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod support;

use serde_json::Value;
use support::{scratch_in, stderr, stdout, tileslide};

/// The bundled scene or map `name` (`examples/NAME`).
fn bundled(name: &str) -> String {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples")
        .join(name)
        .to_str()
        .unwrap()
        .to_owned()
}

#[test]
fn explain_prints_the_golden_stories() {
    trycmd::TestCases::new()
        .register_bin(
            "tileslide",
            std::path::PathBuf::from(env!("CARGO_BIN_EXE_tileslide")),
        )
        .case("tests/explain/*.toml");
}

#[test]
fn the_json_story_of_the_corner_says_where_each_contact_came_from() {
    let scene = bundled("scenes/corner.json");
    let o = tileslide(&["explain", &scene, "--body", "0", "--step", "12", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let step = &v["steps"][0];
    assert_eq!(step["step"], 12);
    let passes = step["passes"].as_array().unwrap();
    assert_eq!(passes.len(), 2);
    // Pass 0 slides along the floor of cell (7, 4); pass 1 stops at the step's face.
    let first = |p: &Value| p["contacts"][p["first"].as_u64().unwrap() as usize].clone();
    assert_eq!(
        first(&passes[0])["source"]["tile"]["cell"],
        serde_json::json!([7, 4])
    );
    assert_eq!(passes[0]["response"], "Slid");
    assert_eq!(
        first(&passes[1])["source"]["tile"]["cell"],
        serde_json::json!([8, 3])
    );
    assert_eq!(first(&passes[1])["normal"], serde_json::json!([-1.0, 0.0]));
    assert_eq!(passes[1]["response"], "StoppedInCorner");
}

#[test]
fn the_json_of_a_cell_names_what_hides_each_segment() {
    let map = bundled("maps/corner.txt");
    let o = tileslide(&["explain", &map, "--cell", "3,4", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let segments = v["segments"].as_array().unwrap();
    assert_eq!(segments.len(), 4);
    let hidden: Vec<&Value> = segments
        .iter()
        .filter(|s| s["active"].as_array().unwrap().is_empty())
        .collect();
    // The two seam faces, each hidden by the neighbour across it.
    assert_eq!(hidden.len(), 2);
    let by: Vec<&Value> = hidden
        .iter()
        .map(|s| &s["hidden"][0]["by"]["cell"])
        .collect();
    assert!(by.contains(&&serde_json::json!([2, 4])) && by.contains(&&serde_json::json!([4, 4])));
    // The top's ends both join flat: no cap.
    let top = segments.iter().find(|s| s["side"] == "MinY").unwrap();
    for end in top["active"][0]["ends"].as_array().unwrap() {
        assert_eq!(end["join"], "Flat");
        assert_eq!(end["cap"], false);
    }
}

#[test]
fn the_json_of_the_character_names_the_one_way_platform_it_passes() {
    let scene = bundled("scenes/one-way.json");
    let o = tileslide(&["explain", &scene, "--character", "--step", "11", "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let events = v["character"][0]["events"].as_array().unwrap();
    let pass = events.iter().find_map(|e| e.get("one_way")).unwrap();
    assert_eq!(pass["pass"], "FromBelow");
    assert_eq!(pass["source"]["tile"]["cell"], serde_json::json!([3, 3]));
}

/// The PNG at `path`: its width, height and RGBA pixels.
fn decode(path: &std::path::Path) -> (u32, u32, Vec<u8>) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    assert_eq!(info.color_type, png::ColorType::Rgba);
    (info.width, info.height, buf)
}

#[test]
fn the_pictures_hold_the_map_the_labels_and_the_legend() {
    let dir = scratch_in("explain-pictures", ".keep", "");
    let dir = dir.parent().unwrap();
    for (name, args) in [
        (
            "body.png",
            vec![bundled("scenes/corner.json"), "--body".into(), "0".into()],
        ),
        (
            "cell.png",
            vec![bundled("maps/corner.txt"), "--cell".into(), "8,3".into()],
        ),
        (
            "character.png",
            vec![bundled("scenes/one-way.json"), "--character".into()],
        ),
    ] {
        let out = dir.join(name);
        let _ = std::fs::remove_file(&out);
        let mut all = vec!["explain".to_owned()];
        all.extend(args);
        all.extend(["-o".to_owned(), out.to_str().unwrap().to_owned()]);
        let refs: Vec<&str> = all.iter().map(String::as_str).collect();
        let o = tileslide(&refs);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert!(stdout(&o).contains(&format!("{name}: ")), "{}", stdout(&o));
        let (w, h, pixels) = decode(&out);
        assert!(
            w > 300 && h > 100 && w < 2000 && h < 2000,
            "{name}: {w} × {h}"
        );
        // The legend on the right: its dark background in the bottom-right corner.
        let at = |x: u32, y: u32| {
            let i = 4 * (y * w + x) as usize;
            [pixels[i], pixels[i + 1], pixels[i + 2]]
        };
        assert_eq!(at(w - 1, h - 1), [36, 36, 44], "{name}");
        // Labels: light text in dark boxes over the map's part, on the left.
        let lit = (0..h)
            .flat_map(|y| (0..w / 2).map(move |x| (x, y)))
            .filter(|&(x, y)| at(x, y) == [36, 36, 44])
            .count();
        assert!(lit > 20, "{name}: no label boxes over the map");
    }
}

#[test]
fn explain_refuses_a_picture_that_is_not_a_png() {
    let scene = bundled("scenes/corner.json");
    let o = tileslide(&["explain", &scene, "--body", "0", "-o", "story.gif"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("-o"), "{}", stderr(&o));
}

#[test]
fn simulate_runs_the_scene_character_to_the_end_of_its_script() {
    let scene = bundled("scenes/one-way.json");
    let o = tileslide(&["simulate", &scene, "--json"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    // 38 steps of script: up through the platform, onto it, down through it, on the floor
    // (its top at y = 5, the box 0.4 tall below its centre, a skin above).
    assert_eq!(v["steps"], 38);
    let c = &v["character"];
    assert_eq!(c["grounded"], true);
    assert!((c["y"].as_f64().unwrap() - 4.599).abs() < 1e-4, "{c}");
    assert!((c["x"].as_f64().unwrap() - 4.7).abs() < 1e-4, "{c}");
}

#[test]
fn a_script_whose_steps_overflow_is_refused_not_wrapped() {
    // Two entries of 2^63 steps each: their total does not fit in 64 bits.
    let scene = scratch_in(
        "simulate-script-overflow",
        "scene.json",
        "{\"ascii\": \"####\\n#..#\\n####\", \"character\": {\"x\": 1.5, \"y\": 1.5, \
         \"half_width\": 0.3, \"half_height\": 0.3, \"script\": [{\"steps\": 9223372036854775808}, \
         {\"steps\": 9223372036854775808}]}}",
    );
    let o = tileslide(&["simulate", scene.to_str().unwrap(), "--json"]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("character.script: its steps add up to more than"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn a_character_without_a_shape_is_refused_by_name() {
    let scene = scratch_in(
        "explain-bad-character",
        "scene.json",
        // (Escaped: a raw string cannot hold `"####`.)
        "{\"ascii\": \"####\\n#..#\\n####\", \"character\": {\"x\": 1.5, \"y\": 1.5, \"script\": []}}",
    );
    let o = tileslide(&["explain", scene.to_str().unwrap(), "--character"]);
    assert!(!o.status.success());
    assert!(stderr(&o).contains("character.shape"), "{}", stderr(&o));
}
