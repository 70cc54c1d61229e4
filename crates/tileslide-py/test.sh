#!/usr/bin/env sh
# Builds the Python package and runs its tests: a virtual environment in the cargo target
# directory (target/py) with requirements-dev.txt, the wheel built by maturin (the dev
# profile: quicker to build, the same answers bit for bit) and installed, then pytest.
# Extra arguments go to pytest.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
target=${CARGO_TARGET_DIR:-$root/target}
venv=$target/py
wheels=$target/wheels/dev

if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check -r "$here/requirements-dev.txt"
rm -rf "$wheels"
"$venv/bin/maturin" build --quiet --profile dev --manifest-path "$here/Cargo.toml" --out "$wheels"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall --no-deps "$wheels"/tileslide-*.whl
cd "$here"
PYTHONDONTWRITEBYTECODE=1 exec "$venv/bin/python" -m pytest -q -p no:cacheprovider tests "$@"
