"""The type stubs (tileslide.pyi, shipped in the wheel) declare exactly what the module
has: every class, function, method and property, and nothing it lacks."""

import ast
import inspect
from pathlib import Path

import tileslide

STUB = Path(__file__).resolve().parents[1] / "tileslide.pyi"


def stub_names():
    tree = ast.parse(STUB.read_text())
    top, members = set(), {}
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            top.add(node.name)
            members[node.name] = {
                (n.name if isinstance(n, ast.FunctionDef) else n.target.id)
                for n in node.body
                if isinstance(n, (ast.FunctionDef, ast.AnnAssign))
            } | {
                # Enum members: `NAME = value`.
                t.id
                for n in node.body
                if isinstance(n, ast.Assign)
                for t in n.targets
                if isinstance(t, ast.Name)
            }
        elif isinstance(node, ast.FunctionDef):
            top.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            top.add(node.target.id)
    return top, members


def public(names):
    return {n for n in names if not n.startswith("_")}


def test_the_stub_declares_every_public_name_and_no_other():
    top, _ = stub_names()
    # (Less the extension module itself, which the package's __init__ imports from.)
    module = {n for n in public(dir(tileslide)) if not inspect.ismodule(getattr(tileslide, n))}
    module |= {"__version__"}
    assert public(top) | {"__version__"} == module


def test_each_class_in_the_stub_has_the_classes_members():
    _, members = stub_names()
    for name, declared in members.items():
        cls = getattr(tileslide, name)
        assert inspect.isclass(cls)
        if issubclass(cls, BaseException):
            # Attributes set on each raised error, not on the class.
            assert declared == {"file", "position", "cause"}
            continue
        own = {n for n, _ in inspect.getmembers(cls) if n in cls.__dict__}
        assert public(declared) == public(own), name
        for dunder in {"__len__", "__contains__", "__eq__", "__hash__"} & declared:
            assert dunder in own, f"{name}.{dunder}"
