//! Points given on the command line as `X,Y` (`--from`, `--to`).

use anyhow::{Result, anyhow, bail};
use tileslide::Vec2;

/// Parses `X,Y` into a finite point; errors name the argument.
pub fn parse_point(text: &str, what: &str) -> Result<Vec2> {
    let parts: Vec<&str> = text.split(',').collect();
    let [x, y] = parts.as_slice() else {
        bail!("{what} {text:?}: expected X,Y (two numbers separated by a comma)");
    };
    let parse = |s: &str, axis: &str| -> Result<f32> {
        let v: f32 = s
            .trim()
            .parse()
            .map_err(|_| anyhow!("{what} {text:?}: {axis} = {s:?} is not a number"))?;
        if !v.is_finite() {
            bail!("{what} {text:?}: {axis} = {s:?} is not finite");
        }
        Ok(v)
    };
    Ok(Vec2::new(parse(x, "x")?, parse(y, "y")?))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_parse_and_errors_name_the_argument() {
        assert_eq!(
            parse_point("1.5,-2", "--from").unwrap(),
            Vec2::new(1.5, -2.0)
        );
        let e = parse_point("1.5", "--from").unwrap_err().to_string();
        assert!(e.contains("--from") && e.contains("X,Y"), "{e}");
        let e = parse_point("1,NaN", "--to").unwrap_err().to_string();
        assert!(e.contains("--to") && e.contains("not finite"), "{e}");
        let e = parse_point("1,abc", "--to").unwrap_err().to_string();
        assert!(e.contains("not a number"), "{e}");
    }
}
