"""The type stubs say what the package has: every public name, the scene keywords of the
library's one table of scene keys, and a docstring on every public function."""

import ast
import inspect
import pathlib

import rodimpact

STUB = pathlib.Path(rodimpact.__file__).with_name("__init__.pyi")


def stub_functions():
    tree = ast.parse(STUB.read_text())
    return {node.name: node for node in tree.body if isinstance(node, ast.FunctionDef)}


def test_every_public_name_is_in_the_stub():
    text = STUB.read_text()
    for name in rodimpact.__all__:
        assert f"def {name}(" in text or f"class {name}" in text or f"{name}:" in text or f"{name} =" in text, name


def test_scene_keywords_are_the_librarys():
    functions = stub_functions()
    for name in ("solve", "formula", "check"):
        args = functions[name].args
        keywords = [a.arg for a in args.args + args.kwonlyargs]
        scene = [k for k in keywords if k in rodimpact.SCENE_KEYS]
        assert scene == list(rodimpact.SCENE_KEYS), name
    assert rodimpact.SCENE_KEYS[:3] == ("m", "M", "l") and "rod_omega" in rodimpact.SCENE_KEYS


def test_public_functions_have_docstrings():
    for name in rodimpact.__all__:
        obj = getattr(rodimpact, name)
        if inspect.isfunction(obj) or inspect.isclass(obj):
            assert obj.__doc__ and len(obj.__doc__) > 40, name
