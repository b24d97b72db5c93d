"""Every public class and function refuses a call that does not fit its signature with a HybridError whose first
line says what was wrong and what to give (a keyword misspelt: the one meant), never Python's TypeError.

The names are walked, not listed: every class and function of ``hybrid.__all__`` (but the errors and warnings,
which the package raises) and the distributions of :mod:`hybrid.sweeps`. A public name added without the check
(:func:`hybrid.validate.checked_keywords`) fails here.
"""

from __future__ import annotations

import dataclasses
import inspect

import pytest

import hybrid
import hybrid.sweeps
from hybrid.experiments.settings import setting_aliases

SPHERE = hybrid.Sphere((0.5, 0.0, 0.2), 0.15)


def _public() -> dict[str, object]:
    """The public classes and functions, by the name their refusals give them (``sweeps.<name>`` for a
    distribution)."""
    found = {}
    for name in hybrid.__all__:
        obj = getattr(hybrid, name)
        if inspect.isclass(obj) and issubclass(obj, (BaseException, Warning)):
            continue
        if inspect.isclass(obj) or inspect.isfunction(obj):
            found[name] = obj
    return found | {f"sweeps.{cls.__name__}": cls for cls in hybrid.sweeps.DISTRIBUTIONS.values()}


PUBLIC = _public()
#: the functions that take the experiment's settings by name (``**overrides``), and the names they take: the
#: Experiment's fields, each gain by its own name, ``F_d`` and ``v_d``
SETTINGS = {"paper_experiment", "tracing_experiment", "panda_experiment"}


def first_line(exc: BaseException) -> str:
    return str(exc).splitlines()[0]


def _parameters(name: str) -> list[inspect.Parameter]:
    return list(inspect.signature(PUBLIC[name]).parameters.values())


def _keywords(name: str) -> list[str]:
    """The keywords of a public callable, as its documented signature shows them (the Controller's task arguments
    apart: they come by position; the experiment's settings for a factory of them)."""
    if name in SETTINGS:
        return [f.name for f in dataclasses.fields(hybrid.Experiment) if f.init]
    return [p.name for p in _parameters(name)
            if p.kind is p.KEYWORD_ONLY or (p.kind is p.POSITIONAL_OR_KEYWORD and name != "Controller")]


def _typos(keyword: str) -> set[str]:
    """``keyword`` misspelt: its middle letter dropped, the two about the middle swapped, capitalized."""
    k = len(keyword) // 2
    return {keyword[:k] + keyword[k + 1:], keyword[:k - 1] + keyword[k] + keyword[k - 1] + keyword[k + 1:],
            keyword.capitalize()} - {keyword}


def test_the_walk_finds_the_public_names():
    assert {"Controller", "Experiment", "Measurement", "SimulationResult", "Khatib", "simulate", "sweep", "ur5",
            "metrics", "sweeps.Uniform"} <= set(PUBLIC)
    # a new function of settings by name says here which it takes
    assert {n for n in PUBLIC if any(p.kind is p.VAR_KEYWORD for p in _parameters(n))} == SETTINGS


@pytest.mark.parametrize("name", list(PUBLIC))
def test_a_keyword_it_has_not_is_refused_with_the_nearest_it_has(name):
    """Each keyword misspelt (a letter dropped, two swapped, a capital) is refused, naming the misspelling and
    suggesting the keyword it came from; a word like none of them is named without a suggestion; one that takes
    no keywords says so."""
    args = (hybrid.ur5(), SPHERE) if name == "Controller" else ()
    keywords = _keywords(name)
    assert "sample_time" in keywords if name in ("Controller", "Limits") else True
    known = set(keywords) | (set(setting_aliases()) if name in SETTINGS else set())
    typos = {keyword: _typos(keyword) - known for keyword in keywords}
    for keyword in keywords:
        others = set().union(*(t for k, t in typos.items() if k != keyword))
        for typo in typos[keyword] - others:  # a typo of two keywords (L1, L2: "L") is either's
            with pytest.raises(hybrid.HybridError) as err:
                PUBLIC[name](*args, **{typo: None})
            line = first_line(err.value)
            if name in SETTINGS:
                assert line.startswith(f"unknown setting(s) {typo} for {name}; did you mean {keyword!r}?"), line
            else:
                assert line.startswith(f"{name} has no keyword {typo!r}; did you mean {keyword!r}?"), line
                assert line.endswith(f"(help(hybrid.{name}))"), line
            assert len(line) <= 240 and keyword in str(err.value).splitlines()[1]
    refusal = (f"unknown setting\\(s\\) xyzzy for {name}; see the known ones" if name in SETTINGS else
               f"{name} has no keyword 'xyzzy'; {'give one of its keywords' if keywords else 'it takes none'}")
    with pytest.raises(hybrid.HybridError, match=f"^{refusal}"):
        PUBLIC[name](*args, xyzzy=1.0)


@pytest.mark.parametrize("name", list(PUBLIC))
def test_more_arguments_by_position_than_the_signature_has_are_refused(name):
    """One argument by position beyond those the signature takes by position (none for the Experiment's, all
    keywords; none at all for a scheme): refused, naming how many it takes and the first extra."""
    positional = [p.name for p in _parameters(name) if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    with pytest.raises(hybrid.HybridError) as err:
        PUBLIC[name](*[None] * len(positional), "extra")
    takes = (f"takes {len(positional)} argument{'s' * (len(positional) != 1)} by position (" if positional else
             "takes its arguments by keyword only," if _keywords(name) else "takes no arguments,")
    line = first_line(err.value)
    assert line.startswith(f"{name} {takes}") and f"{len(positional) + 1} w" in line, line
    assert "the first extra: 'extra'" in line and len(line) <= 240, line
    assert all(p in str(err.value).splitlines()[1] for p in positional)


def test_a_call_that_fits_is_the_callable_own():
    """A call that fits is made as before (a scheme made without arguments is the registered one); one missing
    an argument is refused by name."""
    assert hybrid.Khatib() == hybrid.SCHEMES["khatib"]() and hybrid.Scheme() != hybrid.Khatib()
    assert hybrid.ur5().n == 6 and hybrid.paper_arm() == hybrid.paper_arm()
    with pytest.raises(hybrid.HybridError, match="^Khatib has no keyword 'name'; it takes none"):
        hybrid.Khatib(name="task")
    with pytest.raises(hybrid.HybridError, match="^simulate: exp not given; give exp"):
        hybrid.simulate()
