//! A body's step in words: each pass of the resolver, every contact it considered with
//! where it came from, and what the resolver did (a [`BodyTrace`] of
//! [`Bodies::resolve_traced`](tileslide::Bodies::resolve_traced)).

use tileslide::{
    BodyFate, BodyHandle, BodyTrace, ContactPart, ContactSource, ContactTrace, PassTrace, Response,
};

use crate::words::{num, point, wall};

/// What a contact came from, in words. `name` names another body (e.g. `"body 2"`), or
/// gives `None` for one the caller does not know.
#[must_use]
pub fn source_words(c: &ContactTrace, name: &impl Fn(BodyHandle) -> Option<String>) -> String {
    let part = match c.part {
        ContactPart::Face => " (face)",
        ContactPart::RoundedEnd => " (rounded end)",
        _ => "",
    };
    match c.source {
        ContactSource::Wall(w) => format!("{}{part}", wall(&w)),
        ContactSource::Body { handle, circle } => match name(handle) {
            Some(body) => format!("{body} circle {circle}"),
            None => format!("a body not in the scene, circle {circle}"),
        },
        _ => "something new".to_owned(),
    }
}

/// What the resolver did in a pass, in words.
#[must_use]
pub fn response_words(pass: &PassTrace) -> String {
    let said = match pass.response {
        Response::Free => "free: the rest of the move made".to_owned(),
        Response::Slid { slide } => format!("slid along it: next {}", point(slide)),
        Response::RoundedCorner { slide } => {
            format!("rounded the convex corner: next {}", point(slide))
        }
        Response::TieBreak { slide } => format!(
            "met head-on: the tie-break turns it (the lower slot one way, the higher the other): next {}",
            point(slide)
        ),
        Response::StoppedHeadOn => "stopped: met straight on, no side to slide to".to_owned(),
        Response::StoppedInCorner => {
            "stopped in a concave corner: the slide along the last wall ran straight into this one"
                .to_owned()
        }
        Response::NoSlide => "stopped at the contact (slide mode Stop)".to_owned(),
        Response::CutShort => "cut short at the contact: the passes are used up".to_owned(),
        Response::OutOfRange => "stopped: the slide would leave the coordinate range".to_owned(),
        _ => format!("{:?}", pass.response),
    };
    // (Noted only where it matters: a contact at t = 0 has no safe part.)
    let dropped = !pass.step_taken && pass.chosen().is_some_and(|c| c.t > 0.0);
    if dropped {
        format!("{said} (the safe part, under an eighth of the gap, not taken)")
    } else {
        said
    }
}

/// The response in a few words (a picture's label).
#[must_use]
pub fn response_short(r: &Response) -> &'static str {
    match r {
        Response::Free => "free",
        Response::Slid { .. } => "slid",
        Response::RoundedCorner { .. } => "rounded the corner",
        Response::TieBreak { .. } => "tie-break",
        Response::StoppedHeadOn => "stopped head-on",
        Response::StoppedInCorner => "stopped in a concave corner",
        Response::NoSlide => "stopped (no slide)",
        Response::CutShort => "cut short (passes used up)",
        Response::OutOfRange => "stopped (range)",
        _ => "?",
    }
}

/// One step of a body's story, in words, one line a fact, headed `heading` (e.g.
/// `"body 0, step 3"`); `name` names the other bodies met (see [`source_words`]).
#[must_use]
pub fn step_words(
    heading: &str,
    story: &BodyTrace,
    name: &impl Fn(BodyHandle) -> Option<String>,
) -> String {
    let mut s = format!(
        "{heading}: at {}, proposed {}\n",
        point(story.start),
        point(story.proposed)
    );
    match story.fate {
        BodyFate::Still => s.push_str("  still: no move proposed\n"),
        BodyFate::Settled => s.push_str(
            "  skipped as settled: blocked in place last step, and nothing it sees changed\n",
        ),
        _ => {}
    }
    let mut n = 0;
    for pass in &story.passes {
        s += &format!("  pass {}: sweeps {}\n", pass.pass, point(pass.motion));
        for (i, c) in pass.contacts.iter().enumerate() {
            n += 1;
            let mark = if c.grazed {
                "  ignored: a graze (moving along it)"
            } else if pass.first == Some(i) {
                "  <- first"
            } else {
                ""
            };
            s += &format!(
                "    [{n}] {}: t {}, at {}, normal {}{mark}\n",
                source_words(c, name),
                num(c.t),
                point(c.point),
                point(c.normal)
            );
        }
        s += &format!(
            "    moved {}; {}\n",
            point(pass.moved),
            response_words(pass)
        );
    }
    s += &format!(
        "  resolved {}: ends at {}\n",
        point(story.resolved),
        point(story.start + story.resolved)
    );
    s
}

#[cfg(test)]
mod tests {
    use tileslide::io::ascii;
    use tileslide::{Bodies, BodyDesc, BodyShape, ResolveTrace, Vec2};

    use super::*;

    #[test]
    fn a_body_stopped_by_a_wall_names_the_cell_and_the_response() {
        let map = ascii::parse("#####\n#...#\n#####", "test.txt", 1.0).unwrap();
        let mut bodies = Bodies::new();
        let shape = BodyShape::circle(0.4).unwrap();
        let ball = bodies
            .add(BodyDesc::new(Vec2::new(1.5, 1.5), shape.clone()))
            .unwrap();
        let other = bodies
            .add(BodyDesc::new(Vec2::new(3.0, 1.5), shape))
            .unwrap();
        bodies.propose(ball, Vec2::new(-1.0, 0.0)).unwrap();
        bodies.propose(other, Vec2::new(-1.0, 0.0)).unwrap();
        let mut trace = ResolveTrace::new();
        bodies.step_traced(&map, &mut trace);
        let name = |h: BodyHandle| (h == ball).then(|| "body A".to_owned());
        let words = step_words("body B, last step", trace.body(other).unwrap(), &name);
        assert!(
            words.starts_with("body B, last step: at (3.000, 1.500), proposed (-1.000, 0.000)\n"),
            "{words}"
        );
        assert!(words.contains("body A circle 0"), "{words}");
        let words = step_words("ball", trace.body(ball).unwrap(), &name);
        assert!(words.contains("cell (0, 1) tile"), "{words}");
        assert!(words.contains("stopped: met straight on"), "{words}");
    }
}
