#!/usr/bin/env python3
"""Checks the dependency tree of tileslide (the workspace and fuzz/), from `cargo metadata`.

- Licenses: every package from a registry declares a license expression (SPDX) that some
  alternative of which uses only the licenses in ALLOWED; EXCEPTIONS names the packages
  allowed another license, and why.
- Bans: the crates a user installs (USER_CRATES) never depend, at build or run time, on the
  peers the benchmarks compare with (PEERS): those are for benchmark code only.

Exits non-zero, naming each package and what is wrong, when either fails. Offline once
the registry's index and crates are on the machine (cargo metadata reads Cargo.lock).
"""

import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# Permissive licenses (NCSA: LLVM's libFuzzer, in fuzz/), and Unicode's data license.
ALLOWED = {
    "MIT",
    "MIT-0",
    "Apache-2.0",
    "Apache-2.0 WITH LLVM-exception",
    "BSD-2-Clause",
    "BSD-3-Clause",
    "ISC",
    "Zlib",
    "0BSD",
    "CC0-1.0",
    "Unlicense",
    "BSL-1.0",
    "Unicode-3.0",
    "NCSA",
}

# Packages allowed a license outside ALLOWED.
EXCEPTIONS = {
    # Generates the C header at build time (crates/tileslide-capi); none of its code is
    # in what is built for a user.
    "cbindgen": "MPL-2.0",
}

# What a user installs: the core, its front ends and the renderer.
USER_CRATES = [
    "tileslide",
    "tileslide-capi",
    "tileslide-py",
    "tileslide-wasm",
    "tileslide-bevy",
    "tileslide-render",
]

# The peers the benchmarks measure against.
PEERS = {"parry2d", "rapier2d", "pathfinding", "boxdd", "criterion"}


def metadata(manifest):
    out = subprocess.run(
        ["cargo", "metadata", "--format-version", "1", "--manifest-path", str(manifest)],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    return json.loads(out)


def alternatives(expression):
    """The ways to satisfy an SPDX expression: a list of sets of licenses, any one of which
    is enough (OR of ANDs). Handles OR, AND, WITH, parentheses and the old "/" for OR."""
    tokens = re.findall(r"\(|\)|[A-Za-z0-9.+-]+", expression.replace("/", " OR "))
    pos = 0

    def parse_or():
        nonlocal pos
        ways = parse_and()
        while pos < len(tokens) and tokens[pos] == "OR":
            pos += 1
            ways = ways + parse_and()
        return ways

    def parse_and():
        nonlocal pos
        ways = parse_atom()
        while pos < len(tokens) and tokens[pos] == "AND":
            pos += 1
            right = parse_atom()
            ways = [a | b for a in ways for b in right]
        return ways

    def parse_atom():
        nonlocal pos
        if pos >= len(tokens):
            raise ValueError(f"license expression {expression!r} ends early")
        token = tokens[pos]
        pos += 1
        if token == "(":
            ways = parse_or()
            if pos >= len(tokens) or tokens[pos] != ")":
                raise ValueError(f"license expression {expression!r} has an unclosed (")
            pos += 1
            return ways
        if pos < len(tokens) and tokens[pos] == "WITH":
            exception = tokens[pos + 1] if pos + 1 < len(tokens) else ""
            pos += 2
            return [{f"{token} WITH {exception}"}]
        return [{token}]

    ways = parse_or()
    if pos != len(tokens):
        raise ValueError(f"license expression {expression!r} has {tokens[pos]!r} left over")
    return ways


def check_licenses(meta, where, problems):
    for package in meta["packages"]:
        if package["source"] is None:
            continue
        name, version = package["name"], package["version"]
        license = package.get("license")
        if not license:
            problems.append(f"{where}: {name} {version} declares no license expression")
            continue
        if EXCEPTIONS.get(name) == license:
            continue
        try:
            ways = alternatives(license)
        except ValueError as e:
            problems.append(f"{where}: {name} {version}: {e}")
            continue
        if not any(way <= ALLOWED for way in ways):
            problems.append(f"{where}: {name} {version} is licensed {license!r}, not allowed")


def check_bans(meta, problems):
    nodes = {node["id"]: node for node in meta["resolve"]["nodes"]}
    names = {package["id"]: package["name"] for package in meta["packages"]}
    for crate in USER_CRATES:
        roots = [pid for pid, name in names.items() if name == crate]
        if not roots:
            problems.append(f"workspace: {crate} is not in the workspace")
            continue
        # Normal and build dependencies, transitively: what building the crate pulls in.
        seen, stack, via = set(), list(roots), {}
        while stack:
            pid = stack.pop()
            if pid in seen:
                continue
            seen.add(pid)
            for dep in nodes[pid]["deps"]:
                kinds = {k["kind"] for k in dep["dep_kinds"]}
                if kinds - {"dev"}:
                    if dep["pkg"] not in via:
                        via[dep["pkg"]] = pid
                    stack.append(dep["pkg"])
        for pid in seen:
            if names[pid] in PEERS:
                chain, at = [names[pid]], pid
                while at in via:
                    at = via[at]
                    chain.append(names[at])
                problems.append(
                    f"workspace: {crate} depends on the peer {names[pid]} "
                    f"({' <- '.join(chain)}); peers are for benchmark code only"
                )


def main():
    problems = []
    workspace = metadata(ROOT / "Cargo.toml")
    check_licenses(workspace, "workspace", problems)
    check_bans(workspace, problems)
    check_licenses(metadata(ROOT / "fuzz" / "Cargo.toml"), "fuzz", problems)
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    count = sum(1 for p in workspace["packages"] if p["source"] is not None)
    print(
        f"{count} registry packages in the workspace (and fuzz/'s): every license allowed; "
        f"{', '.join(USER_CRATES)} depend on none of {', '.join(sorted(PEERS))}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
