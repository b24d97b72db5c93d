"""Old names of keywords, settings and attributes, kept for one release with a ``DeprecationWarning``.

A name that had two meanings got a new one for its second (conventions: one meaning per word):
:data:`RENAMED` maps each old name to its new one. An old keyword still takes effect, with a
warning that names the new one; a file written before (a saved experiment, a sweep's folder, a
controller's TOML file) still reads, its old keys read as the new; what is written names only the
new ones.
"""

from __future__ import annotations

import dataclasses
import functools
import inspect
import warnings

from hybrid.errors import HybridError

#: the old name of each renamed setting or keyword, and its new name
RENAMED = {"reference": "frame_direction", "step": "integration_step"}
#: the warnings' message, as a warnings filter matches it (the command line shows them)
MESSAGE = r".*'\w+' is renamed '\w+'"


def warn_renamed(old: str, new: str, where: str, stacklevel: int = 3) -> None:
    """Warn that ``where``'s ``old`` is now ``new`` (``stacklevel`` counts from the caller of this)."""
    warnings.warn(f"{where}: {old!r} is renamed {new!r}; give {new} (the old name goes in the next release)",
                  DeprecationWarning, stacklevel=stacklevel)


def renamed_settings(kwargs: dict, where: str, renamed: dict | None = None, *, old_wins: bool = False,
                     stacklevel: int = 4) -> dict:
    """``kwargs`` with each old name of ``renamed`` (default :data:`RENAMED`) given as its new one, with a
    warning. An old and a new name both given are refused, unless ``old_wins`` (a dataclass's
    ``replace(obj, old=value)`` passes every field by its new name beside the old one given): then the
    old one's value is taken."""
    renamed = RENAMED if renamed is None else renamed
    if not any(old in kwargs for old in renamed):
        return kwargs
    kwargs = dict(kwargs)
    for old, new in renamed.items():
        if old not in kwargs:
            continue
        value = kwargs.pop(old)
        warn_renamed(old, new, where, stacklevel)
        if new in kwargs and not old_wins:
            raise HybridError(f"{where}: {old} and {new} are both given; give {new} alone ({old} is its old name)")
        kwargs[new] = value
    return kwargs


def warn_old_names(names, where: str, stacklevel: int = 4) -> None:
    """Warn for each setting name of ``names`` (a sweep's parameters) that is an old name, or a dotted
    path from one."""
    for name in names:
        head = name.partition(".")[0] if isinstance(name, str) else None
        if head in RENAMED:
            warn_renamed(head, RENAMED[head], where, stacklevel)


def renamed_keys(d: dict, renamed: dict | None = None) -> dict:
    """The data ``d`` a file written before held, its old keys of ``renamed`` (default :data:`RENAMED`)
    read as the new ones, silently: the file is not the reader's to change."""
    renamed = RENAMED if renamed is None else renamed
    # an old key beside its new one (written by neither) yields to it
    return {renamed.get(k, k): v for k, v in d.items() if not (k in renamed and renamed[k] in d)}


def renamed_keywords(**renamed: str):
    """A decorator: the function takes each old keyword of ``renamed`` (``old="new"``) as its new one,
    with a warning (:func:`renamed_settings`)."""

    def decorate(fn):
        where = fn.__qualname__.removesuffix(".__init__")

        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            return fn(*args, **renamed_settings(kwargs, where, renamed, stacklevel=4))

        return wrapper

    return decorate


class RenamedKeywords(type):
    """The metaclass of a dataclass whose fields were renamed: making one (or ``dataclasses.replace``)
    takes the old names of its ``_renamed`` (``{old: new}``) as the new ones, with a warning; a
    subclass's own ``__init__`` too."""

    def __call__(cls, *args, **kwargs):
        # dataclasses.replace passes every field beside the old name given: the old name's value is the change
        replacing = {f.name for f in dataclasses.fields(cls) if f.init} <= set(kwargs)
        kwargs = renamed_settings(kwargs, cls.__name__, cls._renamed, old_wins=replacing, stacklevel=4)
        return super().__call__(*args, **kwargs)

    @property
    def __signature__(cls) -> inspect.Signature:
        """The class's own ``__init__``'s (``help`` and the documentation show its fields, not ``__call__``'s)."""
        signature = inspect.signature(cls.__init__)
        return signature.replace(parameters=list(signature.parameters.values())[1:])


def renamed_attribute(old: str, new: str) -> property:
    """A read-only property ``old`` that warns and gives the attribute ``new``."""

    def get(self):
        warn_renamed(old, new, type(self).__name__, stacklevel=3)
        return getattr(self, new)

    return property(get, doc=f"Deprecated: {new}.")
