"""The generator's boundary: it imports nothing of the runtime but :mod:`hybrid.errors` and
:mod:`hybrid.spec`, and the cache key (:func:`hybrid.native.generator.fingerprint`) changes with every
file of those and of ``codegen/``, and with no other file."""

from __future__ import annotations

import ast
import shutil
from pathlib import Path

import pytest

from hybrid.native import generator

ROOT = Path(__file__).resolve().parent.parent
#: the calls that import a module named by a string
STRING_IMPORTS = {"import_module", "__import__", "find_spec", "run_module"}


def _imported(tree: ast.AST) -> list[tuple[int, str]]:
    """Every absolute module name ``tree`` imports, anywhere (module level, functions, classes), with its
    line: ``import``, ``from ... import`` (a submodule as ``module.name``) and calls that import a module
    named by a string constant. Relative imports stay within the generator and are left out."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom) and not node.level:
            found += [(node.lineno, node.module)] + [(node.lineno, f"{node.module}.{a.name}") for a in node.names]
        elif isinstance(node, ast.Call):
            name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", None)
            if name in STRING_IMPORTS:
                found += [(node.lineno, a.value) for a in node.args
                          if isinstance(a, ast.Constant) and isinstance(a.value, str)]
                # an f-string's constant head: f"hybrid.native.{x}" imports from hybrid.native
                found += [(node.lineno, a.values[0].value.rstrip(".")) for a in node.args
                          if isinstance(a, ast.JoinedStr) and a.values and isinstance(a.values[0], ast.Constant)]
    return found


def _allowed(name: str) -> bool:
    """True for a module the generator may import: anything outside ``hybrid``, the generator itself,
    :mod:`hybrid.errors` and :mod:`hybrid.spec` (``from hybrid import spec`` names ``hybrid.spec``)."""
    parts = name.split(".")
    if parts[0] != "hybrid":
        return True
    return len(parts) > 1 and (parts[1] in ("errors", "spec", "codegen"))


def _runtime_imports(source: str) -> list[tuple[int, str]]:
    """The modules of the runtime that ``source`` imports, ``(line, name)`` each."""
    tree = ast.parse(source)
    # ``from hybrid import spec`` is recorded as both ``hybrid`` and ``hybrid.spec``: the package itself
    # is imported then too, but through an allowed name, so ``hybrid`` alone counts only from ``import hybrid``
    plain = {(n.lineno, a.name) for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    return sorted((line, name) for line, name in set(_imported(tree))
                  if not _allowed(name) and (name != "hybrid" or (line, name) in plain))


def test_the_import_check_finds_runtime_imports_however_written():
    source = '''
import json
import hybrid
from hybrid.spec.chain import Chain
from hybrid.errors import HybridError
from hybrid import spec, native
from . import emit

def f():
    from hybrid.native.units import compiled
    importlib.import_module("hybrid.simulation.closed_loop")
    importlib.import_module(f"hybrid.plants.{name}")
    __import__("hybrid.models")

class C:
    import hybrid.geometry.surfaces
'''
    assert _runtime_imports(source) == [
        (3, "hybrid"), (6, "hybrid.native"), (10, "hybrid.native.units"), (10, "hybrid.native.units.compiled"),
        (11, "hybrid.simulation.closed_loop"), (12, "hybrid.plants"), (13, "hybrid.models"),
        (16, "hybrid.geometry.surfaces")]


def test_the_generator_imports_from_hybrid_only_errors_and_spec():
    modules = sorted((ROOT / "codegen").rglob("*.py"))
    assert len(modules) > 10 and ROOT / "codegen" / "api.py" in modules
    bad = {str(p.relative_to(ROOT)): found for p in modules if (found := _runtime_imports(p.read_text()))}
    assert not bad, f"the generator imports the runtime: {bad}"


def _copy(tmp_path: Path) -> Path:
    """The generator's folder and the ``hybrid`` package copied under ``tmp_path`` (no bytecode)."""
    for name in ("codegen", "hybrid"):
        shutil.copytree(ROOT / name, tmp_path / name, ignore=shutil.ignore_patterns("__pycache__"))
    return tmp_path


@pytest.fixture
def fingerprint_of_copy(tmp_path, monkeypatch):
    """The copy's folder, the fingerprint as it reads a copy of the sources (computed afresh at each call),
    and the checkout's own (afresh too)."""
    checkout = generator.fingerprint.__wrapped__()
    top = _copy(tmp_path)
    monkeypatch.setattr(generator, "_codegen", lambda: top / "codegen")
    monkeypatch.setattr(generator, "_package", lambda: top / "hybrid")
    return top, generator.fingerprint.__wrapped__, checkout


def test_the_fingerprint_reads_the_generator_spec_and_errors():
    package = Path(generator.__file__).resolve().parents[1]
    assert generator.sources() == {"codegen": ROOT / "codegen", "spec": package / "spec",
                                   "errors.py": package / "errors.py"}


def test_every_file_that_shapes_the_generated_bytes_changes_the_fingerprint(fingerprint_of_copy):
    top, fingerprint, checkout = fingerprint_of_copy
    before = fingerprint()
    assert before == checkout  # the copy is the checkout's sources, byte for byte
    shaping = [p for folder in (top / "codegen", top / "hybrid" / "spec") for p in sorted(folder.rglob("*"))
               if p.is_file()] + [top / "hybrid" / "errors.py"]
    assert {"api.py", "emit.py", "chain.py", "surface.py", "stamp.py", "errors.py"} <= {p.name for p in shaping}
    seen = {before}
    for path in shaping:
        original = path.read_bytes()
        path.write_bytes(original + b"#")
        changed = fingerprint()
        assert changed not in seen, f"editing {path.relative_to(top)} leaves the fingerprint as it was"
        seen.add(changed)
        path.write_bytes(original)
        assert fingerprint() == before
    # a new file that is not a module (a template) counts as well, in a new subfolder too
    template = top / "codegen" / "more_templates" / "unit.c.j2"
    template.parent.mkdir()
    template.write_text("/* a template */\n")
    assert fingerprint() != before


def test_files_outside_the_generator_leave_the_fingerprint(fingerprint_of_copy):
    top, fingerprint, _ = fingerprint_of_copy
    before = fingerprint()
    for path in (top / "hybrid" / "plots.py", top / "hybrid" / "native" / "units.py",
                 top / "hybrid" / "geometry" / "surfaces.py"):
        path.write_bytes(path.read_bytes() + b"#")
        assert fingerprint() == before, f"{path.relative_to(top)} is not the generator's"
    # bytecode the interpreter writes beside the sources is no source
    cache = top / "codegen" / "__pycache__"
    cache.mkdir()
    (cache / "emit.cpython-312.pyc").write_bytes(b"\0")
    assert fingerprint() == before
    # nor is an editor's backup or a merge's leftover beside them
    (top / "codegen" / "emit.py.orig").write_text("# an old copy\n")
    (top / "codegen" / "templates" / "unit.c.j2~").write_text("/* a backup */\n")
    assert fingerprint() == before
