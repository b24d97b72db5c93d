"""Every public class and function of ``hybrid`` is documented in numpydoc form, and its examples run.

The public names are ``hybrid.__all__``. A class or function needs an ``Examples`` section, a
``Parameters`` section naming each of its parameters (a class: those of its ``__init__``), and a
``Returns`` section when it returns something (a return annotation other than None); the public
methods a class defines need the same ``Parameters`` and ``Returns``. The examples run as doctests,
each in a namespace of its own.
"""

from __future__ import annotations

import doctest
import inspect
import re

import pytest

import hybrid

#: the modules whose names are documented elsewhere (their docstrings are kept with their own changes)
DOCUMENTED_ELSEWHERE = {
    "hybrid",
}


def _public() -> dict[str, object]:
    """The public classes and functions, by name, but those of :data:`DOCUMENTED_ELSEWHERE`."""
    found = {}
    for name in hybrid.__all__:
        obj = getattr(hybrid, name)
        if (inspect.isclass(obj) or inspect.isfunction(obj)) and obj.__module__ not in DOCUMENTED_ELSEWHERE:
            found[name] = obj
    return found


PUBLIC = _public()


def sections(doc: str) -> dict[str, str]:
    """The numpydoc sections of ``doc`` (cleaned by :func:`inspect.cleandoc`), by heading."""
    parts = re.split(r"^(\w[\w ]*)\n-{3,}[ \t]*$", doc, flags=re.M)
    return {heading: body for heading, body in zip(parts[1::2], parts[2::2])}


def documented_names(section: str) -> set[str]:
    """The names a Parameters section documents: ``a, b : type`` lines at the section's indent."""
    names = set()
    for line in section.splitlines():
        if line and not line[0].isspace():
            names.update(n.strip().lstrip("*") for n in line.split(" : ")[0].split(","))
    return names


def returns_something(signature: inspect.Signature) -> bool:
    # the package's modules use postponed annotations: the annotation is the text "None"
    return signature.return_annotation not in (None, "None")


def problems(obj, what: str, *, examples: bool = True, returns: bool = True) -> list[str]:
    """What the docstring of ``obj`` (a class or a function) lacks, each named with ``what``."""
    doc = inspect.getdoc(obj)
    if not doc:
        return [f"{what} has no docstring"]
    found = sections(inspect.cleandoc(obj.__doc__ or doc))
    missing = []
    if examples and "Examples" not in found:
        missing.append(f"{what} has no Examples section")
    if inspect.isclass(obj):
        init = obj.__dict__.get("__init__") or (obj.__init__ if inspect.isfunction(obj.__init__) else None)
        signature, returns = (inspect.signature(init) if init is not None else None), False
    else:
        signature = inspect.signature(obj)
    if signature is not None:
        names = [p for p in signature.parameters if p not in ("self", "cls")]
        if names and "Parameters" not in found:
            missing.append(f"{what} has no Parameters section (it takes {', '.join(names)})")
        elif names:
            undocumented = [n for n in names if n not in documented_names(found["Parameters"])]
            if undocumented:
                missing.append(f"{what}'s Parameters section does not name {', '.join(undocumented)}")
        if returns and returns_something(signature) and "Returns" not in found and "Yields" not in found:
            missing.append(f"{what} has no Returns section (it returns {signature.return_annotation})")
    return missing


def methods(cls) -> dict[str, object]:
    """The public methods ``cls`` defines itself (not those it takes from elsewhere, such as a formula)."""
    found = {}
    for name, value in vars(cls).items():
        if name.startswith("_") and name != "__call__":
            continue
        f = value.__func__ if isinstance(value, (classmethod, staticmethod)) else value
        if inspect.isfunction(f) and f.__qualname__.startswith(f"{cls.__name__}."):
            found[name] = f
    return found


def test_the_walk_finds_the_public_names():
    assert {"Robot", "arm_terms", "task_frame", "DecouplingLaw", "HybridError", "sweep", "CirclePath", "Experiment",
            "SimulationResult", "metrics", "Controller", "Tracking", "Limits", "Sensing"} <= set(PUBLIC)
    # names defined in the modules documented elsewhere are left out, and only those
    left_out = {n for n in hybrid.__all__ if n not in PUBLIC and (inspect.isclass(getattr(hybrid, n))
                                                                 or inspect.isfunction(getattr(hybrid, n)))}
    assert {getattr(hybrid, n).__module__ for n in left_out} <= DOCUMENTED_ELSEWHERE


def test_the_checks_see_what_is_missing():
    def packed(a, b: int = 1) -> float:
        """Summary.

        Parameters
        ----------
        a : the first, its description packed into the type line.
        """

    def complete(a) -> float:
        """Summary.

        Parameters
        ----------
        a : float
            The first.

        Returns
        -------
        float
            Twice ``a``.

        Examples
        --------
        >>> complete(1.0)
        2.0
        """
        return 2 * a

    found = problems(packed, "packed")
    assert any("no Examples" in p for p in found)
    assert any("does not name b" in p for p in found)
    assert any("no Returns" in p for p in found)
    assert problems(complete, "complete") == []


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_numpydoc_sections(name):
    obj = PUBLIC[name]
    missing = problems(obj, name)
    if inspect.isclass(obj):
        for method, f in methods(obj).items():
            missing += problems(f, f"{name}.{method}", examples=False)
    assert not missing, "\n".join(missing)


@pytest.mark.parametrize("name", sorted(PUBLIC))
def test_examples_run(name):
    obj = PUBLIC[name]
    tests = doctest.DocTestFinder().find(obj, name, module=inspect.getmodule(obj), globs={})
    assert any(t.examples for t in tests), f"{name} has no examples to run"
    report: list[str] = []
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    for test in tests:
        runner.run(test, out=report.append)
    assert runner.failures == 0, "".join(report)
