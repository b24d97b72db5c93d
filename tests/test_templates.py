"""The C templates (``codegen/templates/``): each renders, strictly, for the paper's arm and the UR5; the
standalone C they render compiles warning-free; the units' modules build only the context.

The units are generated in a fresh cache (the generator runs, nothing is read back from an earlier run).
"""

from __future__ import annotations

import ast
import ctypes
import math
import re
import shutil
import subprocess
from pathlib import Path

import jinja2
import numpy as np
import pytest
from hybrid.codegen import closed_loop, lanes, part_grid, path_follow, robot_unit, templates

import hybrid
from hybrid.native import standalone, units

ROOT = Path(__file__).resolve().parent.parent

STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
SPHERE = hybrid.Sphere(center=(0.5, 0.0, 0.2), radius=0.15)


def shared_headers() -> dict[str, str]:
    """The headers the units include, rendered: the SIMD lanes', the path follower's, a part's surface's."""
    return {lanes.LANES_HEADER: lanes.lanes_header(), path_follow.PATH_HEADER: path_follow.path_header(),
            part_grid.PART_HEADER: part_grid.part_header()}


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """Every template the generator loads while it writes the paper's closed loop, its standalone controller
    and plant, the UR5's standalone controller with and without a wrench sensor and its plant's unit, and the
    headers units share; and those units' files."""
    mp = pytest.MonkeyPatch()
    mp.setenv("HYBRID_CACHE_DIR", str(tmp_path_factory.mktemp("cache")))
    env, loaded = templates.environment(), []
    get_template = env.get_template

    def spy(name, *args, **kwargs):
        loaded.append(name)
        return get_template(name, *args, **kwargs)

    mp.setattr(env, "get_template", spy)
    try:
        exp = hybrid.paper_experiment()
        spec = units.loop_spec(exp.plant_class.loop_plant(exp), exp.build_controller().step_variant())
        loop = closed_loop.build_closed_loop_unit(spec, "paper_loop", "the paper's closed loop", {})
        ur5 = hybrid.ur5().chain
        unit = robot_unit.build_plant_unit(ur5, SPHERE.spec(), "ur5_plant", units.robot_info(ur5, "ur5"))
        files = standalone.controller_files(exp.build_controller(), "paper", "paper_controller")
        files |= standalone.plant_files(exp, "paper_plant", exp.initial_state())
        for name, sensor in (("ur5", None), ("ur5_sensor", hybrid.WrenchSensor(position=(0.01, -0.02, 0.05),
                                                                              bias=(0.3, -0.2, 0.5, 0.0, 0.0, 0.1),
                                                                              cutoff=15.0, order=2))):
            files |= standalone.controller_files(hybrid.Controller(hybrid.ur5(), SPHERE, wrench_sensor=sensor), name)
        files |= shared_headers()
    finally:
        mp.undo()
    return set(loaded), files, loop, unit


def test_every_template_renders_strictly(rendered):
    loaded, files, loop, unit = rendered
    on_disk = {p.name for p in templates.FOLDER.iterdir() if p.suffix == ".j2"}
    assert on_disk == loaded, f"templates never rendered: {sorted(on_disk - loaded)}"
    assert templates.environment().undefined is jinja2.StrictUndefined
    # a name the context lacks is an error, not an empty string
    with pytest.raises(jinja2.UndefinedError):  # a field without its doc
        templates.macro("standalone_common.c.j2", "array_field")({"name": "x", "size": 1, "unit": "1", "names": []},
                                                                 str)
    for text in (*files.values(), *loop.files.values(), *unit.files.values()):
        assert "{{" not in text and "{%" not in text and "{#" not in text


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
def test_the_rendered_standalone_c_compiles_warning_free(rendered, tmp_path):
    files = rendered[1]
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    sources = sorted(n for n in files if n.endswith(".c"))
    assert sources == ["paper_controller.c", "paper_plant.c", "ur5.c", "ur5_sensor.c"]
    for source in sources:
        done = subprocess.run(["gcc", *STRICT, "-c", source, "-o", source[:-2] + ".o"], cwd=tmp_path,
                              capture_output=True, text=True)
        assert done.returncode == 0 and not done.stderr, f"{source}:\n{done.stderr}"


# ------------------------------------------------------------------ no C in the units' Python

#: a line of the C preprocessor's
DIRECTIVE = re.compile(r"^\s*#(if|ifdef|ifndef|elif|else|endif|define|undef|include|error|pragma)\b", re.MULTILINE)


def c_texts(source: str) -> list[tuple[int, str]]:
    """The string literals of the Python ``source`` that hold C spanning lines (a newline and a ``;``, a
    brace starting or ending a line, or a preprocessor directive), with their line numbers: an f-string's
    literal parts count, docstrings do not."""
    tree = ast.parse(source)
    docs = {id(node.body[0].value) for node in ast.walk(tree)
            if isinstance(node, (ast.Module, ast.FunctionDef, ast.ClassDef)) and node.body
            and isinstance(node.body[0], ast.Expr) and isinstance(node.body[0].value, ast.Constant)}
    docs |= {id(v) for node in ast.walk(tree) if isinstance(node, ast.JoinedStr) for v in node.values}  # its parts
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.JoinedStr):
            text = "\0".join(v.value if isinstance(v, ast.Constant) else "" for v in node.values)
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in docs:
            text = node.value
        else:
            continue
        lines = text.split("\n")
        if len(lines) > 1 and (";" in text or DIRECTIVE.search(text)
                               or any(s.strip().startswith(("{", "}")) or s.rstrip().endswith("{") for s in lines)):
            found.append((node.lineno, text))
    return found


#: C written in Python as the units once were: a header in a triple-quoted f-string, a block joined from
#: f-strings, a function from implicitly joined literals, preprocessor lines alone
OLD_STYLE = '''
"""A module."""


def status_name_source(prefix, cases):
    """Its C."""
    return (f"const char *{prefix}_status_name(int status) {{\\n    switch (status) {{\\n{cases}"
            '    default: return "UNKNOWN";\\n    }\\n}\\n')


def array_statement(struct, field, numbers, n):
    return (f"    {{\\n        static const double v[{n}] = {{{numbers}}};\\n"
            f"        for (i = 0; i < {n}; ++i) {struct}->{field}[i] = v[i];\\n    }}")


def header(P, prefix):
    return f"""#ifndef {P}_H
#define {P}_H
void {prefix}_init({prefix} *p);
#endif
"""


PARTS = """#ifdef HL_PART
#define HL_IN_PART(n) (HL_PART == (n))
#else
#define HL_IN_PART(n) 1
#endif"""
'''


def test_the_c_finder_finds_c_in_python():
    assert sorted(line for line, _ in c_texts(OLD_STYLE)) == [7, 12, 17, 24]
    assert c_texts('"""Docs: x = {1};\nmore."""\nMESSAGE = "a wrench has six numbers; give six"\n'
                   'JOIN = "\\n".join\nTITLE = "# if it runs\\nit is fine"\n') == []


@pytest.mark.parametrize("module", ["standalone_controller", "standalone_plant", "emit", "closed_loop", "robot_unit"])
def test_the_units_python_holds_no_c(module):
    path = templates.FOLDER.parent / f"{module}.py"
    found = c_texts(path.read_text())
    assert not found, f"C text in {path.name} at lines {[line for line, _ in found]}: move it into a template"


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
def test_the_headers_compile_on_their_own_and_are_included_not_copied(tmp_path):
    """Every C header the generator renders compiles alone, warning-free; the generated units include the SIMD
    lanes' header (one copy, in generated/) instead of holding its text."""
    headers = shared_headers()
    assert lanes.LANES_HEADER in headers
    for name, text in headers.items():
        (tmp_path / name).write_text(text)
        for flags in ([], ["-march=native"]):  # the portable build's lanes and this machine's
            done = subprocess.run(["gcc", "-std=gnu99", "-O2", *flags, "-Wall", "-Wextra", "-Werror", "-fsyntax-only",
                                   "-x", "c", str(tmp_path / name)], capture_output=True, text=True)
            assert done.returncode == 0 and not done.stderr, f"{name}: {done.stderr}"
    generated = ROOT / "generated"
    header = headers[lanes.LANES_HEADER]
    body = header.split("#define HYBRID_LANES_H", 1)[1]
    first_function = body[body.index("static inline"):].split("\n", 1)[0]
    units = [generated / "hybrid_sympy.c", generated / "hybrid_casadi.c", *sorted((generated / "loops").glob("*.c"))]
    for unit in units:
        text = unit.read_text()
        assert '#include "hybrid_lanes.h"' in text and first_function not in text, unit.name
    assert (generated / lanes.LANES_HEADER).read_text().endswith(header)


@pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")
@pytest.mark.parametrize("build", ["strict", "native"])
def test_the_kernels_sine_and_cosine_are_the_c_librarys_within_an_ulp(tmp_path, build):
    """``hybrid_sin`` and ``hybrid_cos`` (the CasADi kernels' inline ones) against the C library's, through
    Python's math module, on angles from 1e-300 to beyond their polynomial's span, with the signs of zero, the
    quadrants' edges, infinities and NaN; for the portable build and this machine's (fused multiply-adds)."""
    source = tmp_path / "sincos.c"
    source.write_text("#include <math.h>\n" + templates.render("hybrid_sincos.c.j2") +
                      "void both(const double *x, double *s, double *c, int n) {\n"
                      "    int i;\n"
                      "    for (i = 0; i < n; ++i) { s[i] = hybrid_sin(x[i]); c[i] = hybrid_cos(x[i]); }\n}\n")
    flags = ["-std=c99", "-O2", "-Wall", "-Wextra", "-Werror", "-pedantic"] + (["-march=native"] if build == "native"
                                                                                else ["-ffp-contract=off"])
    library = tmp_path / "sincos.so"
    done = subprocess.run(["gcc", *flags, "-shared", "-fPIC", str(source), "-o", str(library), "-lm"],
                          capture_output=True, text=True)
    assert done.returncode == 0 and not done.stderr, done.stderr
    rng = np.random.default_rng(7)
    x = np.concatenate([rng.uniform(-4, 4, 20_000), rng.uniform(-200, 200, 20_000), rng.uniform(-1.1e5, 1.1e5, 5000),
                        10.0 ** rng.uniform(-300, 0, 2000) * rng.choice([-1, 1], 2000),
                        np.arange(-64, 65) * np.pi / 4, np.nextafter(np.arange(-64, 65) * np.pi / 4, np.inf),
                        [0.0, -0.0, 1e5, -1e5, np.nextafter(1e5, np.inf), 1e300, np.inf, -np.inf, np.nan]])
    lib = ctypes.CDLL(str(library))
    s, c = np.empty_like(x), np.empty_like(x)
    pointer = ctypes.POINTER(ctypes.c_double)
    lib.both(*(a.ctypes.data_as(pointer) for a in (x, s, c)), ctypes.c_int(len(x)))
    for ours, theirs in ((s, np.array([math.sin(v) if math.isfinite(v) else math.nan for v in x])),
                         (c, np.array([math.cos(v) if math.isfinite(v) else math.nan for v in x]))):
        finite = np.isfinite(theirs)
        assert np.array_equal(np.isnan(ours), ~finite)
        ulps = np.abs(ours[finite] - theirs[finite]) / np.spacing(np.abs(theirs[finite]))
        # within an ulp for the angles of joints; within two out to the polynomial's span (|x| <= 1e5)
        assert ulps.max() <= 2.0, (ulps.max(), x[finite][ulps.argmax()])
        assert ulps[np.abs(x[finite]) <= 200].max() <= 1.0
        assert np.array_equal(np.signbit(ours[finite & (theirs == 0)]), np.signbit(theirs[finite & (theirs == 0)]))
