#!/usr/bin/env python3
"""Prints every feature of every workspace crate, as `crate/feature` separated by commas,
but the Bevy plugin's `examples` (its windowed examples: Bevy's window, text and UI crates,
which CI leaves out of clippy and the docs for time). Reads `cargo metadata`."""
import json
import subprocess
import sys

LEFT_OUT = {("tileslide-bevy", "examples")}


def main() -> int:
    meta = json.loads(
        subprocess.run(
            ["cargo", "metadata", "--format-version", "1", "--no-deps"],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
    )
    members = set(meta["workspace_members"])
    features = sorted(
        f"{package['name']}/{feature}"
        for package in meta["packages"]
        if package["id"] in members
        for feature in package["features"]
        if feature != "default" and (package["name"], feature) not in LEFT_OUT
    )
    print(",".join(features))
    return 0


if __name__ == "__main__":
    sys.exit(main())
