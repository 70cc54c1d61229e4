//! `tileslide-web-bench export DIR` writes the standard scenes for Node;
//! `tileslide-web-bench time DIR [RUNS]` times them natively and prints one line of JSON:
//! the median seconds for the 1,000,000 rays and for one step of the 10,000-circle crowd
//! (100 steps a run), with the answers' checksums. `web/bench/run.mjs` runs both.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

use tileslide_web_bench::{
    BenchError, CROWD, Crowd, Scenes, cast_scene_rays, cast_scene_rays_portable, floats_hash,
    median_seconds,
};

/// Steps a crowd run makes (BENCHMARKS.md's 100).
const CROWD_STEPS: usize = 100;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let result = match args.as_slice() {
        [command, dir] if command == "export" => export(PathBuf::from(dir)),
        [command, dir, rest @ ..] if command == "time" && rest.len() <= 1 => {
            match rest.first().map_or(Ok(5), |r| r.parse::<usize>()) {
                Ok(runs) if runs > 0 => time(PathBuf::from(dir), runs),
                _ => Err(BenchError::from_message(
                    "RUNS must be a positive whole number",
                )),
            }
        }
        _ => Err(BenchError::from_message(
            "usage: tileslide-web-bench export DIR | time DIR [RUNS]",
        )),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn export(dir: PathBuf) -> Result<(), BenchError> {
    Scenes::generate()?.write(&dir)
}

fn time(dir: PathBuf, runs: usize) -> Result<(), BenchError> {
    let scenes = Scenes::generate()?;
    scenes.write(&dir)?;
    let mut answers = Vec::new();
    let rays = median_seconds(runs, || {
        answers = cast_scene_rays(&scenes)?;
        Ok(())
    })?;
    let mut portable_answers = Vec::new();
    let rays_portable = median_seconds(runs, || {
        portable_answers = cast_scene_rays_portable(&scenes)?;
        Ok(())
    })?;
    if floats_hash(&portable_answers) != floats_hash(&answers) {
        return Err(BenchError::from_message(
            "the portable walk's answers differ from cast_rays'",
        ));
    }
    let mut hash = 0;
    let crowd = median_seconds(runs.div_ceil(2), || {
        let mut crowd = Crowd::new(&scenes, CROWD)?;
        for _ in 0..CROWD_STEPS {
            crowd.step(&scenes.map)?;
        }
        hash = crowd.hash();
        Ok(())
    })? / CROWD_STEPS as f64;
    println!(
        "{{\"raysSeconds\": {rays}, \"raysChecksum\": \"{:016x}\", \"raysPortableSeconds\": {rays_portable}, \"crowdStepSeconds\": {crowd}, \"crowdHash\": \"{hash:016x}\", \"crowdSteps\": {CROWD_STEPS}}}",
        floats_hash(&answers)
    );
    Ok(())
}
