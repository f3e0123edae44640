"""The type stubs (pgm/__init__.pyi) against the code: every public name has a stub, with the
same parameters, defaults and keyword-only marks, so an editor's hints never lie."""

import ast
import inspect
import math
from pathlib import Path

import pytest

import pgm

STUB = Path(pgm.__file__).with_name("__init__.pyi")
SHOWN = {"__init__", "_repr_html_", "_repr_svg_"}  # the private names a stub must carry too


def stub_tree():
    return ast.parse(STUB.read_text(encoding="utf-8"))


def stub_functions(body):
    return {node.name: node for node in body if isinstance(node, ast.FunctionDef)}


def stub_classes():
    return {node.name: node for node in stub_tree().body if isinstance(node, ast.ClassDef)}


def default_of_stub(node):
    """A stub's default: a literal, or math.inf (a count without a limit)."""
    if ast.unparse(node) == "math.inf":
        return math.inf
    return ast.literal_eval(node)


def parameters_of_stub(function):
    """[(name, kind, default)] of a stub's parameters; default is inspect's empty when none."""
    arguments = function.args
    positional = arguments.posonlyargs + arguments.args
    defaults = [inspect.Parameter.empty] * (len(positional) - len(arguments.defaults)) + [
        default_of_stub(d) for d in arguments.defaults
    ]
    result = [(a.arg, "positional", d) for a, d in zip(positional, defaults)]
    for a, d in zip(arguments.kwonlyargs, arguments.kw_defaults):
        result.append((a.arg, "keyword", inspect.Parameter.empty if d is None else default_of_stub(d)))
    return result


def parameters_of_code(function):
    result = []
    for p in inspect.signature(function).parameters.values():
        kind = "keyword" if p.kind is inspect.Parameter.KEYWORD_ONLY else "positional"
        result.append((p.name, kind, p.default))
    return result


def test_the_package_declares_it_is_typed():
    assert STUB.is_file()
    assert STUB.with_name("py.typed").is_file()


def test_every_public_name_has_a_stub():
    tree = stub_tree()
    declared = set(stub_functions(tree.body)) | set(stub_classes())
    for node in tree.body:
        if isinstance(node, (ast.AnnAssign)):
            declared.add(node.target.id)
    missing = [name for name in pgm.__all__ + ["__version__"] if name not in declared]
    assert not missing, f"no stub for {missing}"


@pytest.mark.parametrize("name", [n for n in pgm.__all__ if inspect.isfunction(getattr(pgm, n))])
def test_a_function_stub_has_the_code_s_parameters(name):
    stub = stub_functions(stub_tree().body)[name]
    assert parameters_of_stub(stub) == parameters_of_code(getattr(pgm, name))


@pytest.mark.parametrize("cls", [pgm.Network, pgm.InferenceEngine])
def test_a_class_stub_has_the_code_s_methods_and_properties(cls):
    stub = stub_classes()[cls.__name__]
    methods = stub_functions(stub.body)
    stub_properties = {
        name for name, node in methods.items() if any(getattr(d, "id", None) == "property" for d in node.decorator_list)
    }
    for name, member in vars(cls).items():
        if name.startswith("_") and name not in SHOWN:
            continue
        if isinstance(member, property):
            assert name in stub_properties, f"{cls.__name__}.{name}: no property in the stub"
        elif inspect.isfunction(member):
            assert name in methods, f"{cls.__name__}.{name}: no stub"
            assert parameters_of_stub(methods[name]) == parameters_of_code(member), f"{cls.__name__}.{name}"
    for name in methods:
        assert name in vars(cls), f"the stub declares {cls.__name__}.{name}, which the code does not have"


def test_the_version_is_the_libraries():
    assert pgm.__version__ == pgm._core.__version__
    assert all(part.isdigit() for part in pgm.__version__.split("."))
