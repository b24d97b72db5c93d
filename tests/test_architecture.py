"""The package's shape: a light import, no import cycles, and ``regenerate`` only where it belongs.

- ``import hybrid`` loads neither the generator (SymPy, CasADi) nor the optional heavy libraries,
  and opens no file of the project's other than the sources of the modules it imports;
- the imports among ``hybrid.*`` (``hybrid.codegen`` included) form no cycle, counting those at module
  level, those inside functions (each one of a short list, with its reason) and those by name
  (``importlib.import_module``, ``hybrid._LAZY``, ``generator("model")``); nor do the generator and the
  runtime import each other;
- ``regenerate`` rebuilds a checkout's emptied ``generated/`` byte for byte, and an installed
  package refuses it (unless given a folder) without writing anything.
"""

from __future__ import annotations

import ast
import json
import os
import shutil
import stat
import subprocess
import sys
from collections import Counter
from importlib.metadata import PackageNotFoundError, version
from pathlib import Path

import pytest

from hybrid.native.cache import cache_dir

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parent.parent
GENERATED = ROOT / "generated"
#: the generator and the libraries only some commands need: none may load with ``import hybrid`` (nor the
#: reader of a controller's file and its schema)
HEAVY = ("sympy", "casadi", "hybrid.codegen", "pandas", "matplotlib", "mujoco", "hybrid.control.config", "scipy",
         "cvxpy", "plotly")
REFUSAL = "error: regenerate needs a checkout of the project's repository"

#: Imports of the project's own modules made inside a function, and why each is not at module level.
LAZY_IMPORTS = {
    ("hybrid.cli.experiments", "hybrid.plots"): "matplotlib loads only for the commands that draw",
    ("hybrid.cli.sweep", "hybrid.plots"): "matplotlib loads only when a sweep draws its heatmaps",
    ("hybrid.simulation.results", "hybrid.plots"): "matplotlib loads only when a result is drawn (res.plot())",
    ("hybrid.simulation.results", "hybrid.animation"): "matplotlib loads only when a result is animated",
    ("hybrid.simulation.results", "hybrid.view3d"): "plotly (an optional extra) loads only when a result is viewed",
    ("hybrid.plants.registry", "hybrid.plants.mujoco"): "MuJoCo is an optional extra: it loads when a run asks",
    ("hybrid.plants.registry", "hybrid.plants.mujoco_contact"): "MuJoCo is an optional extra: it loads when a run "
                                                               "asks",
    ("hybrid.experiments.serialisation", "hybrid.geometry.parts"): "a part needs SciPy (an extra): its kinds load "
                                                                   "when a saved part is read",
    ("hybrid.experiments.serialisation", "hybrid.geometry.implicit"):
        "SymPy loads only when a file names a surface a user wrote down",
    ("hybrid.stability.maps", "hybrid.stability.figures"): "matplotlib loads only when a map is drawn",
    ("hybrid.cli.stability", "hybrid.stability.figures"): "matplotlib loads only when the command draws a map",
    ("hybrid.stability.figures", "hybrid.plots"): "pyplot loads only when a map is written to a file",
    ("hybrid.stability.tuning", "hybrid.stability.tuning_figure"): "matplotlib loads only when a tuning is drawn",
    ("hybrid.cli.tune", "hybrid.plots"): "matplotlib loads only when a tuning draws its figure",
    ("hybrid.control.config", "hybrid.geometry.implicit"):
        "SymPy loads only when a controller file writes its surface as a formula",
}

#: the generator's package
GENERATOR = "hybrid.codegen"
def _run(args: list[str], cwd: Path, **env: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, *args], cwd=cwd, env={**os.environ, **env}, capture_output=True,
                          text=True, timeout=300)


def _tree(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` by its path there, with its bytes."""
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


def _committed() -> dict[str, bytes]:
    return {n: b for n, b in _tree(GENERATED).items() if n.endswith((".c", ".h", ".json"))}


# ------------------------------------------------------------------ import hybrid

_IMPORT_PROBE = r"""
import json, os, sys

opened = []

def audit(event, args):
    if event == "open" and isinstance(args[0], (str, bytes)):  # an int is a descriptor already open
        opened.append(os.path.realpath(os.fsdecode(args[0])))

sys.addaudithook(audit)
import hybrid

code = [getattr(m, "__file__", None) for m in list(sys.modules.values())]
print(json.dumps({"modules": sorted(sys.modules), "opened": opened, "package": hybrid.__file__,
                  "code": [f for f in code if f]}))
"""


def test_import_hybrid_loads_no_generator_and_reads_no_data(tmp_path):
    # No bytecode: with an empty cache prefix and -B, the import system reads each module's source
    # once and writes nothing, so any other open of a project file (its data, generated/, pyproject.toml,
    # the build cache, a module's source read as text as the generator's fingerprint does) is a read.
    probe = _run(["-B", "-c", _IMPORT_PROBE], ROOT, PYTHONPYCACHEPREFIX=str(tmp_path / "no-bytecode"))
    assert probe.returncode == 0, probe.stderr
    seen = json.loads(probe.stdout)
    assert Path(seen["package"]).resolve().parent == ROOT / "hybrid"  # this checkout's runtime was probed

    loaded = [h for h in HEAVY if any(m == h or m.startswith(h + ".") for m in seen["modules"])]
    assert not loaded, f"import hybrid loads {loaded}"

    ours = [ROOT / "hybrid", ROOT / "codegen", GENERATED, ROOT / "pyproject.toml", ROOT / "README.md",
            cache_dir().resolve()]
    opened = Counter(Path(p) for p in seen["opened"] if any(Path(p) == o or o in Path(p).parents for o in ours))
    assert opened[ROOT / "hybrid" / "__init__.py"] == 1, "the probe saw no import of hybrid"  # else: vacuous
    sources = {Path(f).resolve() for f in seen["code"] if f.endswith(".py")}
    reads = sorted(f"{p} ({n}x)" for p, n in opened.items() if p not in sources or n > 1)
    assert not reads, f"import hybrid opens {reads}"


# ------------------------------------------------------------------ the import graph


def _packages() -> dict[str, Path]:
    """Each package of the project and its folder, as pyproject.toml maps them (``hybrid.codegen`` is
    ``codegen/``)."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]
    mapped = {name: ROOT / folder for name, folder in config.get("package-dir", {}).items()}
    return {name: mapped.get(name, ROOT / name.replace(".", "/")) for name in config["packages"]}


def _modules() -> dict[str, Path]:
    """Every module of the project by its import name."""
    out = {}
    for package, folder in _packages().items():
        for path in sorted(folder.glob("*.py")):
            out[package if path.stem == "__init__" else f"{package}.{path.stem}"] = path
    return out


def _targets(node: ast.Import | ast.ImportFrom, module: str, is_package: bool, modules) -> tuple[set, set]:
    """``(project modules, unresolved project names)`` that the statement imports."""
    if isinstance(node, ast.Import):
        names = [a.name for a in node.names]
    else:
        base = node.module or ""
        if node.level:  # relative to the module's package (an __init__ is its own package)
            package = module if is_package else module.rpartition(".")[0]
            for _ in range(node.level - 1):
                package = package.rpartition(".")[0]
            base = f"{package}.{base}" if node.module else package
        # `from pkg import submodule` imports the submodule; `from pkg import name`, the package
        names = [f"{base}.{a.name}" if f"{base}.{a.name}" in modules else base for a in node.names]
    found = {n for n in names if n in modules and n != module}
    ours = {n for n in names if n.split(".")[0] in ("hybrid", "codegen")}
    return found, ours - set(modules)


def _ours(name: str) -> bool:
    return name.split(".")[0] in ("hybrid", "codegen")


def _called(node: ast.AST, names) -> str | None:
    """The name of the function ``node`` calls (``f(...)`` or ``obj.f(...)``) when it is one of ``names``."""
    if not isinstance(node, ast.Call):
        return None
    name = node.func.id if isinstance(node.func, ast.Name) else getattr(node.func, "attr", None)
    return name if name in names else None


#: the calls that import a module named by a string
_IMPORT_CALLS = ("import_module", "__import__")


def _import_graph(modules: dict[str, Path] | None = None) -> dict:
    """The imports among ``modules`` (the project's by default), by kind, each ``{(importer, imported):
    line}``, and ``"unresolved"``: the imports of project names the graph cannot follow.

    - ``"module"``: run when the importer is imported: top-level statements and those nested in ``if``
      (``TYPE_CHECKING`` too), ``try``, ``with`` and class bodies, but not in functions;
    - ``"deferred"``: import statements inside functions, run when the function is called;
    - ``"by_name"``: a module named by a string, imported when the code runs: ``import_module("name")``;
      the module names of a table that a computed ``import_module(table[key])`` reads (``hybrid._LAZY``),
      all of a module's strings that name a project module; and ``f("name")`` anywhere, where ``f`` is
      a function that imports a fixed prefix followed by its argument (``generator("model")`` imports
      ``hybrid.codegen.model``).
    """
    modules = _modules() if modules is None else modules
    kinds: dict = {"module": {}, "deferred": {}, "by_name": {}}
    unresolved: list[str] = []
    importers: dict[str, str] = {}  # a function that imports prefix + its argument, by name: the prefix
    trees = {m: ast.parse(path.read_text(), str(path)) for m, path in modules.items()}

    def where(module, node):
        return f"{module}:{node.lineno}"

    def computed(module, call, arg, function):
        if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
            if arg.value in modules:
                kinds["by_name"].setdefault((module, arg.value), call.lineno)
            elif _ours(arg.value):
                unresolved.append(f"{where(module, call)}: {arg.value}")
            return
        parameters = [a.arg for a in function.args.args] if function is not None else []
        if (isinstance(arg, ast.JoinedStr) and len(arg.values) == 2 and isinstance(arg.values[0], ast.Constant)
                and isinstance(arg.values[1], ast.FormattedValue)
                and isinstance(arg.values[1].value, ast.Name) and arg.values[1].value.id in parameters
                and not isinstance(function, ast.Lambda)):
            importers[function.name] = arg.values[0].value
            return
        strings = [(n.value, n.lineno) for n in ast.walk(trees[module])
                   if isinstance(n, ast.Constant) and isinstance(n.value, str) and n.value in modules]
        if not strings:
            unresolved.append(f"{where(module, call)}: an import of a computed name ({ast.unparse(arg)}) that "
                              "names no project module the graph can see")
        for name, line in strings:
            if name != module:
                kinds["by_name"].setdefault((module, name), line)

    for module, tree in trees.items():
        is_package = modules[module].name == "__init__.py"

        def visit(node, function, module=module, is_package=is_package):
            for child in ast.iter_child_nodes(node):
                inner = child if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)) else function
                if isinstance(child, (ast.Import, ast.ImportFrom)):
                    found, missing = _targets(child, module, is_package, modules)
                    unresolved.extend(f"{where(module, child)}: {n}" for n in sorted(missing))
                    for t in found:
                        kinds["deferred" if function else "module"].setdefault((module, t), child.lineno)
                elif _called(child, _IMPORT_CALLS) and child.args:
                    computed(module, child, child.args[0], function)
                visit(child, inner)

        visit(tree, None)

    for module, tree in trees.items():
        for node in ast.walk(tree):
            name = _called(node, importers)
            if name is None:
                continue
            arg = node.args[0] if node.args else None
            if not (isinstance(arg, ast.Constant) and isinstance(arg.value, str)):
                unresolved.append(f"{where(module, node)}: {name}() of a computed name")
            elif (target := importers[name] + arg.value) not in modules:
                unresolved.append(f"{where(module, node)}: {target}")
            elif target != module:
                kinds["by_name"].setdefault((module, target), node.lineno)
    return {**kinds, "unresolved": unresolved}


def _graph(*edges: dict) -> dict[str, set]:
    """The graph ``{module: the modules it imports}`` of some kinds of edges."""
    graph: dict[str, set] = {}
    for kind in edges:
        for a, b in kind:
            graph.setdefault(a, set()).add(b)
            graph.setdefault(b, set())
    return graph


def _cycle(graph: dict[str, set]) -> list[str] | None:
    """One cycle of ``graph`` as a path that ends where it starts, or None."""
    state: dict[str, int] = {}  # 1: on the current path, 2: done
    path: list[str] = []

    def visit(node):
        state[node] = 1
        path.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                return path[path.index(nxt):] + [nxt]
            if nxt not in state and (found := visit(nxt)):
                return found
        state[node] = 2
        path.pop()
        return None

    for node in sorted(graph):
        if node not in state and (found := visit(node)):
            return found
    return None


def _shown(cycle: list[str], imports: dict) -> str:
    """A cycle with the kind of each of its imports."""
    steps = [cycle[0]]
    for a, b in zip(cycle, cycle[1:]):
        kind = next((k for k in ("module", "deferred", "by_name") if (a, b) in imports[k]), "import")
        steps.append(f"-({kind})-> {b}")
    return " ".join(steps)


def _collapsed(graph: dict[str, set], package: str) -> dict[str, set]:
    """``graph`` with the modules of ``package`` taken as one node."""
    def node(m):
        return package if m == package or m.startswith(package + ".") else m
    out: dict[str, set] = {}
    for a, targets in graph.items():
        out.setdefault(node(a), set()).update(node(b) for b in targets if node(b) != node(a))
    return out


def _toy(tmp_path: Path, files: dict[str, str]) -> dict[str, Path]:
    """A set of modules written under ``tmp_path``, by their import name (``toy/a.py``: ``toy.a``)."""
    modules = {}
    for name, text in files.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        parts = Path(name).with_suffix("").parts
        modules[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return modules


def test_cycle_finder_finds_a_cycle():
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b", "c"}, "b": {"c"}, "c": set()}) is None
    assert _cycle(_collapsed({"g.x": {"r"}, "r": {"g.y"}, "g.y": set()}, "g")) == ["g", "r", "g"]


#: modules that import each other each in one of the ways the graph counts, and the cycle it must find
TOY_CYCLES = {
    "deferred": ({"toy/a.py": "import toy.b\n", "toy/b.py": "def f():\n    from toy import a\n"},
                 ["toy.a", "toy.b", "toy.a"]),
    "by a literal name": ({"toy/a.py": "import importlib\nimportlib.import_module('toy.b')\n",
                           "toy/b.py": "from . import a\n"}, ["toy.a", "toy.b", "toy.a"]),
    "by a table's names": ({"toy/__init__.py": "import importlib\n_LAZY = {'T': 'toy.b'}\n\n"
                                               "def __getattr__(name):\n"
                                               "    return getattr(importlib.import_module(_LAZY[name]), name)\n",
                            "toy/b.py": "import toy\n"}, ["toy", "toy.b", "toy"]),
    "through a function of the name": (
        {"toy/units.py": "import importlib\n\ndef generator(m):\n"
                         "    return importlib.import_module(f'toy.gen.{m}')\n",
         "toy/run.py": "from toy import units\n\ndef go():\n    return units.generator('law')\n",
         "toy/gen/law.py": "from toy.run import go\n"}, ["toy.gen.law", "toy.run", "toy.gen.law"]),
}


@pytest.mark.parametrize("case", TOY_CYCLES)
def test_the_graph_finds_a_cycle_of_every_kind_of_import(case, tmp_path):
    files, expected = TOY_CYCLES[case]
    imports = _import_graph(_toy(tmp_path, files))
    assert imports["unresolved"] == []
    assert _cycle(_graph(imports["module"], imports["deferred"], imports["by_name"])) == expected


def test_an_import_the_graph_cannot_follow_is_reported(tmp_path):
    files = {"toy/a.py": "import importlib\n\ndef load(name):\n    return importlib.import_module(name.upper())\n",
             "toy/units.py": "import importlib\n\ndef generator(m):\n    return importlib.import_module(f'toy.{m}')\n",
             "toy/b.py": "from toy.units import generator\n\nx = generator('nowhere')\n"}
    assert sorted(_import_graph(_toy(tmp_path, files))["unresolved"]) == [
        "toy.a:4: an import of a computed name (name.upper()) that names no project module the graph can see",
        "toy.b:3: toy.nowhere"]


def test_imports_form_a_dag():
    """Every import among the project's modules counts: at module level, inside functions, and by name."""
    folders = {p.parent for top in ("hybrid", "codegen") for p in (ROOT / top).rglob("__init__.py")}
    unlisted = sorted(str(f.relative_to(ROOT)) for f in folders - set(_packages().values()))
    assert not unlisted, f"packages missing from pyproject's [tool.setuptools] packages: {unlisted}"
    imports = _import_graph()
    assert not imports["unresolved"], f"imports of project modules the graph cannot follow: {imports['unresolved']}"
    graph = _graph(imports["module"], imports["deferred"], imports["by_name"])
    # the graph is the project's: both packages, relative imports resolved, imports of every kind seen
    assert {"hybrid", "hybrid.cli.main", "hybrid.codegen.emit", "hybrid.cli.regenerate"} <= set(graph)
    assert {"hybrid.native.generator", "hybrid.spec.stamp"} <= graph["hybrid.cli.regenerate"]
    assert ("hybrid.plants.registry", "hybrid.plants.mujoco") in imports["deferred"]
    assert {("hybrid", "hybrid.sweeps"), ("hybrid.native.generator", "hybrid.codegen.api")} <= set(imports["by_name"])
    cycle = _cycle(graph)
    assert cycle is None, "import cycle: " + _shown(cycle, imports)


def test_the_generator_and_the_runtime_do_not_import_each_other():
    """With the generator's modules taken as one, the imports still form a DAG: a runtime module the
    generator imports never leads back into the generator."""
    imports = _import_graph()
    edges = {**imports["module"], **imports["deferred"], **imports["by_name"]}
    cycle = _cycle(_collapsed(_graph(edges), GENERATOR))
    assert cycle is None, "the generator and the runtime import each other: " + " -> ".join(cycle)
    # the check sees such a cycle: the generator importing the module that imports it
    assert _cycle(_collapsed(_graph({**edges, ("hybrid.codegen.emit", "hybrid.native.generator"): 0}),
                             GENERATOR)) is not None


def test_imports_inside_functions_are_the_listed_ones():
    lazy = _import_graph()["deferred"]
    unlisted = sorted(f"{m} imports {t} in a function (line {line})" for (m, t), line in lazy.items()
                      if (m, t) not in LAZY_IMPORTS)
    assert not unlisted, ("move these imports to module level, or add them to LAZY_IMPORTS with the reason: "
                          + "; ".join(unlisted))
    stale = sorted(f"{m} -> {t}" for m, t in set(LAZY_IMPORTS) - set(lazy))
    assert not stale, f"LAZY_IMPORTS lists imports that are gone: {stale}"


# ------------------------------------------------------------------ regenerate in a checkout

#: Runs ``python -m hybrid`` with the copy's own generator. ``hybrid.codegen`` is ``codegen/`` only by
#: pyproject's package-dir mapping, which the editable install applies with a finder at the end of
#: ``sys.meta_path`` that points at this checkout: the copy's ``hybrid`` comes first on the path, yet its
#: ``hybrid.codegen`` would still be ours. This finder, ahead of all, applies the same mapping to the copy
#: (its submodules then follow the package's ``__path__``, into the copy too).
_IN_COPY = """
import runpy, sys
from importlib.machinery import PathFinder

root = sys.argv.pop(1)

class CopyLayout:
    @staticmethod
    def find_spec(name, path=None, target=None):
        return PathFinder.find_spec(name, [root]) if name == "hybrid.codegen" else None

sys.meta_path.insert(0, CopyLayout)
runpy.run_module("hybrid", run_name="__main__", alter_sys=True)
"""


def _copy_checkout(dest: Path, *extra: str) -> Path:
    dest.mkdir()
    for name in ("codegen", "generated", "hybrid", *extra):
        shutil.copytree(ROOT / name, dest / name, ignore=shutil.ignore_patterns("__pycache__"))
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(ROOT / name, dest / name)
    return dest


def test_regenerate_rebuilds_an_emptied_checkout_byte_for_byte(tmp_path):
    committed = _committed()
    assert {"hybrid_sympy.c", "hybrid_sympy.h", "hybrid_casadi.json"} <= set(committed)
    copy = _copy_checkout(tmp_path / "checkout")
    shutil.rmtree(copy / "generated")
    (copy / "generated").mkdir()

    def regenerate(*args):
        return _run(["-c", _IN_COPY, str(copy), "regenerate", *args], copy, PYTHONPATH=str(copy))

    check = regenerate("--check")
    assert check.returncode == 1, check.stderr
    assert "Traceback" not in check.stderr
    for name in committed:
        assert f"{name}: missing; run `python -m hybrid regenerate`" in check.stderr

    done = regenerate()
    assert done.returncode == 0, done.stderr
    written = _tree(copy / "generated")
    assert written.keys() == committed.keys()
    assert [n for n in committed if written[n] != committed[n]] == []
    mask = os.umask(0)
    os.umask(mask)
    modes = {p.name: stat.S_IMODE(p.stat().st_mode) for p in (copy / "generated").rglob("*") if p.is_file()}
    assert set(modes.values()) == {0o666 & ~mask}, modes  # readable as any file this user writes

    shutil.rmtree(copy / "generated")  # the folder itself may go too
    assert regenerate().returncode == 0
    assert regenerate("--check").returncode == 0
    assert _tree(copy / "generated") == committed


# ------------------------------------------------------------------ an installed package


def _can_build_wheels() -> bool:
    """setuptools builds wheels itself from 70.1; before, it needs the ``wheel`` package."""
    try:
        major, minor = (int(x) for x in version("setuptools").split(".")[:2])
    except (PackageNotFoundError, ValueError):
        return False
    try:
        return (major, minor) >= (70, 1) or bool(version("wheel"))
    except PackageNotFoundError:
        return False


def _listing(folder: Path) -> dict[str, tuple[int, int]]:
    return {str(p.relative_to(folder)): (p.stat().st_size, p.stat().st_mtime_ns) for p in folder.rglob("*")}


def test_installed_package_refuses_regenerate_and_writes_nothing(tmp_path):
    if not _can_build_wheels():
        pytest.skip("building a wheel without network needs setuptools>=70.1: pip install -e '.[test]'")
    source = _copy_checkout(tmp_path / "source")  # the build writes build/ and *.egg-info into its source
    pip = ["-m", "pip", "--disable-pip-version-check", "-q"]
    built = _run([*pip, "wheel", "--no-deps", "--no-build-isolation", "--no-index", "-w", str(tmp_path / "dist"),
                  str(source)], tmp_path)
    assert built.returncode == 0, built.stderr
    (wheel,) = (tmp_path / "dist").glob("*.whl")
    site = tmp_path / "site"
    installed = _run([*pip, "install", "--no-deps", "--no-index", "--no-compile", "--target", str(site),
                      str(wheel)], tmp_path)
    assert installed.returncode == 0, installed.stderr
    assert (site / "hybrid" / "codegen" / "api.py").is_file()
    assert (site / "hybrid" / "codegen" / "templates" / "closed_loop.c.j2").is_file()  # the C templates
    assert (site / "hybrid" / "bench" / "c" / "driver.c.j2").is_file()  # the benchmarks' C
    assert (site / "hybrid" / "models" / "c" / "excitation.h.j2").is_file()  # an excitation trajectory's header
    assert (site / "hybrid" / "_generated" / "hybrid_sympy.c").is_file()
    assert (site / "hybrid" / "_generated" / "loops" / "index.json").is_file()  # the committed closed loops

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    env = {"PYTHONPATH": str(site), "PYTHONDONTWRITEBYTECODE": "1"}  # the installed copy, and no .pyc
    before = _listing(site)
    for args in (["regenerate"], ["regenerate", "--check"], ["regenerate", "--force"]):
        run = _run(["-m", "hybrid", *args], elsewhere, **env)
        assert run.returncode == 2, (args, run.stdout, run.stderr)
        assert run.stdout == ""
        (line,) = run.stderr.splitlines()
        assert line.startswith(REFUSAL), line
        assert str(site / "hybrid") in line  # the installed copy ran, and says where it is
    assert _listing(site) == before
    assert list(elsewhere.iterdir()) == []

    # a folder given explicitly is the user's to write into, from an installed package too
    out = tmp_path / "out"
    run = _run(["-m", "hybrid", "regenerate", "--target", str(out)], elsewhere, **env)
    assert run.returncode == 0, run.stderr
    assert _tree(out) == _committed()
    run = _run(["-m", "hybrid", "regenerate", "--check", "--target", str(out)], elsewhere, **env)
    assert run.returncode == 0, run.stderr
    assert _listing(site) == before

    # the runtime compiles the installed C, even beside a folder that merely looks like a checkout's
    (site / "generated").mkdir()
    shutil.copy2(site / "hybrid" / "_generated" / "hybrid_sympy.c", site / "generated")
    probe = _run(["-c", "from hybrid.native import loader; print(loader.source_dir())"], elsewhere, **env)
    assert probe.stdout.strip() == str(site / "hybrid" / "_generated"), probe.stderr

    # the paper's experiment from the installed package, in another folder: metrics and figures, no series
    paper = _run(["-m", "hybrid", "paper", "--no-series", "--out", "run"], elsewhere, **env)
    assert paper.returncode == 0, paper.stderr
    written = sorted(p.name for p in (elsewhere / "run").iterdir())
    assert any(n.endswith(".png") for n in written) and any("metrics" in n for n in written), written
    assert not any(n.endswith((".npz", ".csv")) and "metrics" not in n for n in written), written


def test_a_warm_run_needs_neither_sympy_nor_casadi(tmp_path):
    """Once a run's units are in the cache, running it loads no part of the generator."""
    code = ("import sys, hybrid; hybrid.simulate(hybrid.paper_experiment(duration=0.02)); "
            "hybrid.simulate(hybrid.tracing_experiment(duration=0.02)); "
            "print(sorted(m for m in ('sympy', 'casadi', 'hybrid.codegen') if m in sys.modules))")
    first = _run(["-c", code], tmp_path)  # builds what the cache lacks (it may load the generator)
    assert first.returncode == 0, first.stderr
    again = _run(["-c", code], tmp_path)
    assert again.returncode == 0, again.stderr
    assert again.stdout.strip() == "[]", f"a warm run loaded {again.stdout.strip()}"


def test_the_papers_runs_in_a_fresh_cache_need_no_generator_and_compile_only_their_loop(tmp_path):
    """The paper's experiment, under each scheme, alone and in a sweep, runs from the closed loops
    committed in ``generated/loops``: a fresh cache generates nothing, and compiles the loops alone (a
    run's record comes from the loop, not from the plant's unit)."""
    code = ("import sys, hybrid\n"
            "for c in ('task', 'khatib', 'raibert_craig'):\n"
            "    hybrid.simulate(hybrid.paper_experiment(duration=0.02, controller=c))\n"
            "hybrid.sweep(hybrid.paper_experiment(duration=0.02), {'controller': ['task', 'raibert_craig'], "
            "'model_error': [0.0, 0.1]}, workers=1)\n"
            "print(sorted(m for m in ('sympy', 'casadi', 'hybrid.codegen') if m in sys.modules))")
    cache = tmp_path / "cache"
    run = _run(["-c", code], tmp_path, HYBRID_CACHE_DIR=str(cache))
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "[]", f"a fresh cache loaded {run.stdout.strip()}"
    assert not (cache / "units").exists() or not any((cache / "units").iterdir())  # nothing generated
    built = sorted(p.name.rsplit("_", 1)[0] for p in cache.iterdir() if p.name.startswith("_hybrid"))
    committed = json.loads((GENERATED / "loops" / "index.json").read_text())["loops"]
    assert built == sorted(f"_{prefix}" for prefix in committed), built


def test_the_paper_command_builds_its_loops_side_by_side_once_each(tmp_path):
    """``build_side_by_side`` compiles each distinct loop of the experiments once (the task law and
    Khatib's scheme share theirs), and the runs after it compile nothing more."""
    code = """if True:
        import os, hybrid
        from hybrid.simulation import closed_loop
        def built():
            return len([p for p in os.listdir(os.environ["HYBRID_CACHE_DIR"]) if p.startswith("_hybrid")])
        exps = [hybrid.paper_experiment(duration=0.02, controller=c) for c in ("task", "khatib", "raibert_craig")]
        closed_loop.build_side_by_side(exps)
        print(built())
        for e in exps:
            hybrid.simulate(e)
        print(built())
    """
    run = _run(["-c", code], tmp_path, HYBRID_CACHE_DIR=str(tmp_path / "cache"))
    assert run.returncode == 0, run.stderr
    from hybrid.cli.regenerate import committed_loops

    alone = {(plant, tuple(sorted(v.items(), key=str))) for plant, v, lanes in committed_loops() if lanes == 1}
    assert run.stdout.split() == [str(len(alone)), str(len(alone))]


def test_the_version_has_one_source():
    """``hybrid.__version__`` is the installed distribution's version (the build reads the same file)."""
    from importlib.metadata import version

    import hybrid

    assert hybrid.__version__ == version("hybrid-decoupling")
