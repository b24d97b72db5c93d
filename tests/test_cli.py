"""The command line's help, options, errors and progress, and the figures it writes."""

from __future__ import annotations

import argparse
import logging
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

import hybrid
from hybrid import plots
from hybrid.cli import progress
from hybrid.cli import sweep as sweep_cli
from hybrid.cli.main import build_parser, main
from hybrid.native import cache

ROOT = Path(__file__).resolve().parent.parent
LONG_COMMANDS = ("paper", "trace", "sweep", "generate", "bench")


def _commands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(sub.choices)


def _help(capsys, *args: str) -> str:
    with pytest.raises(SystemExit) as done:
        main([*args, "--help"])
    assert done.value.code == 0
    return capsys.readouterr().out


# ------------------------------------------------------------------ help


def test_the_top_level_help_lists_every_command_with_its_summary(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    text = _help(capsys)
    commands = _commands(build_parser())
    assert {"regenerate", "generate", "paper", "trace", "sweep", "bench"} <= set(commands)
    for name, parser in commands.items():
        summary = parser.description.split(". ")[0].rstrip(".")
        assert re.search(rf"^\s+{name}\s+{re.escape(summary)}$", text, flags=re.M), (name, text)
    assert "``" not in text and ":func:" not in text and ":mod:" not in text  # plain text, no markup
    assert text.startswith("usage: hybrid ")


@pytest.mark.parametrize("name", list(_commands(build_parser())))
def test_every_option_of_every_command_has_help_and_is_in_its_help(capsys, monkeypatch, name):
    monkeypatch.setenv("COLUMNS", "100")
    parser = _commands(build_parser())[name]
    assert parser.description and len(parser.description) > 40, f"{name} has no description"
    text = _help(capsys, name)
    assert "``" not in text
    for action in parser._actions:
        what = action.option_strings or [action.metavar or action.dest]
        assert action.help and action.help is not argparse.SUPPRESS, f"{name} {what[0]} has no help text"
        for option in what:
            assert re.search(rf"(^|[\s\[]){re.escape(option)}\b", text), f"{name} --help does not mention {option}"
    if name in LONG_COMMANDS:
        assert "--verbose" in text and "-v" in text


def test_the_program_is_named_as_invoked(tmp_path):
    module = subprocess.run([sys.executable, "-m", "hybrid", "--help"], capture_output=True, text=True, cwd=tmp_path)
    assert module.returncode == 0 and module.stdout.startswith("usage: python -m hybrid ")
    script = shutil.which("hybrid", path=str(Path(sys.executable).parent))
    if script is None:
        pytest.skip("the console script is not installed beside this Python (pip install -e .)")
    done = subprocess.run([script, "paper", "--help"], capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 0 and done.stdout.startswith("usage: hybrid paper "), done.stderr


# ------------------------------------------------------------------ errors


def test_an_unknown_option_names_the_command_and_the_nearest_option(capsys, tmp_path):
    assert main(["paper", "--out", str(tmp_path / "o"), "--forse"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "hybrid paper: unrecognized argument --forse" in err and "did you mean '--force'?" in err
    assert main(["pape"]) == 2
    assert "did you mean 'paper'?" in capsys.readouterr().err


def test_option_values_are_refused_in_the_command_lines_words(capsys, tmp_path):
    for args, words in ((["--workers", "0"], "argument --workers: '0'"),
                        (["--connect-timeout", "nan"], "argument --connect-timeout: 'nan'"),
                        (["--format", "pdff"], "did you mean 'pdf'?")):
        assert main(["sweep", "--demo", "--out", str(tmp_path / "o"), *args]) == 2
        err = capsys.readouterr().err
        assert words in err and "workers =" not in err and "connect_timeout" not in err, err
    assert not (tmp_path / "o").exists()


def _sweep_file(path: Path, body: str) -> Path:
    path.write_text('[base]\nduration = 0.05\n' + body)
    return path


def test_a_sweep_clash_says_pass_force(capsys, tmp_path):
    out = str(tmp_path / "out")
    assert main(["sweep", str(_sweep_file(tmp_path / "a.toml", "[parameters]\nmodel_error = [0.0]\n")),
                 "--out", out]) == 0
    capsys.readouterr()
    other = _sweep_file(tmp_path / "b.toml", "[parameters]\nmodel_error = [0.1]\n")
    assert main(["sweep", str(other), "--out", out]) == 2
    err = capsys.readouterr().err
    assert "different sweep" in err and "pass --force" in err and "force=True" not in err, err
    assert main(["sweep", str(other), "--out", out, "--force"]) == 0


@pytest.mark.parametrize("body, words", [
    ('[parameters]\n"contact.fricton" = [0.0]\n',
     "unknown setting 'contact.fricton' (did you mean 'contact.friction'?)"),
    ('[parameters]\nmodel_eror = [0.0]\n', "(did you mean 'model_error'?)"),
    ('duraton = 1.0\n[parameters]\nmodel_error = [0.0]\n', "[base] duraton: unknown setting of the paper experiment "
                                                           "(did you mean 'duration'?)"),
    ('contact = {frictoin = 0.1}\n[parameters]\nmodel_error = [0.0]\n', "(did you mean 'friction'?)"),
    ('[parameters]\nmodel_error = {unifrom = [0.0, 0.1]}\n', "(did you mean 'uniform'?)"),
    ('[parameter]\nmodel_error = [0.0]\n', "(did you mean 'parameters'?)"),
    ('[parameters]\nmodel_error = [0.0]\n"contact.friction" = [0.0]\n[figures]\nx = "model_error"\n'
     'y = "contact.friction"\nmetrics = ["rms_force_eror_N"]\n', "(did you mean 'rms_force_error_N'?)"),
])
def test_a_typo_in_a_sweep_file_gets_a_did_you_mean(capsys, tmp_path, body, words):
    assert main(["sweep", str(_sweep_file(tmp_path / "s.toml", body)), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert words in err and err.count("\n") == 1, err
    assert not (tmp_path / "o").exists()


def test_a_typo_in_a_generate_setting_gets_a_did_you_mean(capsys, tmp_path):
    for setting, near in (("duraton=1.0", "duration"), ("contact.frictio=0.1", "contact.friction")):
        assert main(["generate", "--experiment", "paper", "--set", setting, "--out", str(tmp_path)]) == 2
        err = capsys.readouterr().err
        assert f"--set {setting.split('=')[0]}: unknown setting" in err and f"did you mean '{near}'?" in err, err
        assert "below" not in err  # the details the one line does not show


def test_the_shipped_sweep_file_prints(capsys):
    with pytest.raises(SystemExit) as done:
        main(["sweep", "--print-demo"])
    assert done.value.code == 0
    assert capsys.readouterr().out == sweep_cli.DEMO.read_text()


# ------------------------------------------------------------------ paper and trace


@pytest.mark.parametrize("command", ["paper", "trace"])
def test_no_series_writes_metrics_and_figures_only(capsys, tmp_path, command):
    out = tmp_path / "out"
    assert main([command, "--out", str(out), "--no-series"]) == 0
    written = sorted(p.name for p in out.iterdir())
    assert "metrics.json" in written and "metrics.csv" in written
    assert not [n for n in written if n.endswith(".npz") or (n.endswith(".csv") and n != "metrics.csv")], written
    assert [n for n in written if n.endswith(".png")]
    assert "time series" not in capsys.readouterr().out


def test_vector_figures_and_progress(capsys, tmp_path):
    out = tmp_path / "out"
    assert main(["paper", "--out", str(out), "--no-series", "--format", "pdf,svg", "-v"]) == 0
    err = capsys.readouterr().err
    assert "running the paper's experiment" in err and "done in" in err and "drawing the figures" in err
    pdfs, svgs = sorted(out.glob("*.pdf")), sorted(out.glob("*.svg"))
    assert len(pdfs) == len(svgs) == 5 and not list(out.glob("*.png"))
    assert all(p.read_bytes().startswith(b"%PDF") for p in pdfs)
    assert all(b"<svg" in p.read_bytes()[:2000] for p in svgs)
    # the clash check knows the vector files too
    assert main(["paper", "--out", str(out)]) == 2 and "--force" in capsys.readouterr().err


def test_slow_work_is_one_line_by_default_and_every_line_with_verbose(capsys):
    log = logging.getLogger("hybrid")
    for verbose in (False, True):
        stream = __import__("io").StringIO()
        with progress.reporting(verbose, stream) as report:
            with report.step("running the schemes"):
                for unit in ("a", "b", "c"):
                    log.info("hybrid: compiling %s", unit, extra=cache.SLOW)
        lines = stream.getvalue().splitlines()
        if verbose:
            assert lines[0] == "running the schemes ..." and sum("compiling" in ln for ln in lines) == 3
        else:
            assert lines == [f"running the schemes ({progress.COMPILING}) ..."]
    assert log.level == logging.NOTSET and not log.handlers  # left as it was
    log.info("hybrid: compiling x", extra=cache.SLOW)  # the library alone stays silent
    assert capsys.readouterr().err == ""


def test_a_step_is_told_when_it_lasts(capsys):
    import io
    import time

    stream = io.StringIO()
    with progress.reporting(False, stream) as report:
        report.quiet_for = 0.05
        with report.step("quick"):
            pass
        with report.step("slow"):
            time.sleep(0.3)
    assert stream.getvalue() == "slow ...\n"


def test_the_library_example_runs_twice(tmp_path, monkeypatch):
    page = ROOT / "docs" / "reference" / "library.md"
    blocks = re.findall(r"```python\n(.*?)```", page.read_text(), flags=re.S)
    monkeypatch.chdir(tmp_path)
    for _ in range(2):
        exec(compile(blocks[0], str(page), "exec"), {})
    assert (tmp_path / "task.npz").is_file()


# ------------------------------------------------------------------ figures


@pytest.fixture(scope="module")
def runs():
    paper = {c: hybrid.simulate(hybrid.paper_experiment(controller=c, duration=0.6)) for c in ("task", "khatib")}
    spatial = {c: hybrid.simulate(hybrid.tracing_experiment(controller=c, duration=0.6)) for c in ("task", "khatib")}
    return paper, spatial


UNIT = re.compile(r"\[[^\]]+\]$")


def _labelled(fig) -> list:
    axes = [ax for ax in fig.axes if ax.get_label() != "<colorbar>"]
    for ax in axes:
        if ax.get_ylabel():
            assert UNIT.search(ax.get_ylabel()), ax.get_ylabel()
        if ax.get_xlabel():
            assert UNIT.search(ax.get_xlabel()), ax.get_xlabel()
    return axes


def test_a_results_plot_has_labelled_axes_with_units(runs):
    from matplotlib.figure import Figure

    paper, spatial = runs
    fig = paper["task"].plot()
    assert isinstance(fig, Figure)
    axes = _labelled(fig)
    assert [ax.get_ylabel() for ax in axes] == ["tangential speed [m/s]", "normal force [N]"]
    assert axes[-1].get_xlabel() == "time [s]"
    fig = spatial["task"].plot()
    labels = [ax.get_ylabel() for ax in _labelled(fig)]
    assert labels[:2] == ["tangential speed [m/s]", "normal force [N]"]
    assert "deviation across\nthe desired path [mm]" in labels and "penetration [mm]" in labels
    assert len(fig.axes[0].get_lines()) == 2  # the reference and the run


def test_the_comparison_draws_the_task_law_on_top_with_distinct_styles(runs):
    paper, _ = runs
    fig = plots.plot_comparison({"raibert_craig": paper["khatib"], **paper})
    lines = {ln.get_label(): ln for ln in fig.axes[0].get_lines()}
    task = lines[plots.TITLES["task"]]
    others = [lines[plots.TITLES[c]] for c in ("khatib", "raibert_craig")]
    assert all(task.get_zorder() > o.get_zorder() for o in others)
    styles = {(ln.get_linestyle(), ln.get_marker()) for ln in (task, *others)}
    assert len(styles) == 3  # told apart without colour


def test_the_comparison_draws_the_task_law_minus_khatib_under_each_signal(runs):
    """Their curves nearly coincide on the signals' scale: the difference panels hold exactly the task law's
    speed and force minus Khatib's; a comparison without both has none; the paper's figures say their
    conditions."""
    paper, _ = runs
    fig = plots.plot_comparison(paper)
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["tangential speed [m/s]", "task law - Khatib\n[m/s]", "normal force [N]",
                      "task law - Khatib\n[N]"]
    for ax, what in ((fig.axes[1], "velocity_tangential"), (fig.axes[3], "force_normal")):
        want = (getattr(paper["task"], what) - getattr(paper["khatib"], what))[plots._rows(paper["task"])]
        assert np.abs(ax.get_lines()[0].get_ydata() - want).max() == 0 and np.abs(want).max() > 0
    assert len(plots.plot_comparison({"task": paper["task"]}).axes) == 2
    exp = paper["task"].experiment
    assert plots.conditions(exp).startswith(f"{exp.surface.kind}, friction {exp.contact.friction:g}, model +10 %")


def test_the_path_plot_has_equal_scales_and_the_deviation(runs):
    _, spatial = runs
    fig = plots.plot_path(spatial)
    ax3 = next(ax for ax in fig.axes if ax.name == "3d")
    spans = [np.ptp(getattr(ax3, f"get_{a}lim")()) for a in "xyz"]
    np.testing.assert_allclose(spans, spans[0], rtol=1e-9)
    assert [getattr(ax3, f"get_{a}label")() for a in "xyz"] == ["x [m]", "y [m]", "z [m]"]
    flat = [ax for ax in _labelled(fig) if ax.name != "3d"]
    assert {ax.get_ylabel() for ax in flat} == {"deviation across\nthe desired path [mm]", "penetration [mm]"}
    across, normal = plots.path_deviation(spatial["task"])
    assert np.abs(across).max() < 5e-3  # within millimetres of the desired path
    np.testing.assert_allclose(-normal, spatial["task"].penetration, atol=2e-4)


def _table() -> pd.DataFrame:
    rows = []
    for c in ("task", "khatib"):
        for speed in (0.1, 0.3):
            for e in (0.0, 0.25, 0.5):
                for f in (0.0, 0.2, 0.4):
                    drop = (0.002 + 0.01 * speed) * (1 - 0.5 * e) if c == "task" else (0.005 + 0.05 * f) * speed * 3
                    rows.append({"controller": c, "speed_reference.before": speed, "model_error": e,
                                 "contact.friction": f, "speed_drop_after_force_step_m_per_s": drop, "status": "ok"})
    return pd.DataFrame(rows)


def test_sweep_heatmaps_have_names_and_units_and_one_scale_for_their_panels():
    table = _table()
    fig = plots.plot_sweep(table, "model_error", "contact.friction", "speed_drop_after_force_step_m_per_s",
                           rows="controller", cols="speed_reference.before")
    panels = [ax for ax in fig.axes if ax.images]
    assert len(panels) == 4
    (bar,) = [ax for ax in fig.axes if ax.get_label() == "<colorbar>"]  # the panels compare: one colour bar
    assert bar.get_ylabel() == "speed drop after the force step [mm/s]"
    # one scale, from the table's smallest drop to its largest (mm/s): a colour is one value in every panel
    drops = 1000 * table["speed_drop_after_force_step_m_per_s"]
    (norm,) = {(im.norm.vmin, im.norm.vmax) for ax in panels for im in ax.images}
    assert norm == pytest.approx((drops.min(), drops.max()))
    assert np.ptp(panels[0].images[0].get_array()) < 0.5 * (drops.max() - drops.min())  # not a panel's own range
    assert {ax.get_xlabel() for ax in panels} - {""} == {"model error (inertia too high) [fraction]"}
    assert "friction coefficient [-]" in panels[0].get_ylabel() and "task-space decoupling" in panels[0].get_ylabel()
    assert panels[0].get_title() == "speed while the force steps = 0.1 m/s"
    assert "speed drop after the force step [mm/s]" in fig._suptitle.get_text()
    ratio = plots.plot_sweep(table, "model_error", "contact.friction", "speed_drop_after_force_step_m_per_s",
                             rows="controller", cols="speed_reference.before", ratio=("task", "khatib"))
    (bar,) = [ax for ax in ratio.axes if ax.get_label() == "<colorbar>"]  # one scale for every ratio panel
    assert bar.get_ylabel() == "task law / Khatib"
    norms = {(im.norm.vmin, im.norm.vmax) for ax in ratio.axes for im in ax.images}
    assert len(norms) == 1 and np.prod(next(iter(norms))) == pytest.approx(1.0)  # centred at 1


def test_labels_name_metrics_and_settings_with_units():
    assert plots.label("speed_drop_after_force_step_m_per_s") == "speed drop after the force step [m/s]"
    assert plots.label("peak_torque_joint3_Nm") == "peak torque of joint 3 [N m]"
    assert plots.label("gains.KPf") == "gain KPf [1/kg]"
    assert plots.label("some_new_length_m") == "some new length [m]"
    from hybrid.sweeps import metric_names

    for name in metric_names(hybrid.tracing_experiment()):
        assert "_" not in plots.label(name) and UNIT.search(plots.label(name)), name


def test_sweep_heatmaps_write_every_format(tmp_path):
    figures = {"x": "model_error", "y": "contact.friction", "rows": "controller", "cols": "speed_reference.before",
               "metrics": ["speed_drop_after_force_step_m_per_s"], "ratio": ["task", "khatib"]}
    written = plots.sweep_heatmaps(_table(), figures, tmp_path, formats=("png", "pdf", "svg"))
    assert sorted(p.name for p in written) == sorted(
        f"heatmap_speed_drop_after_force_step_m_per_s{s}.{f}" for s in ("", "_task_over_khatib")
        for f in ("png", "pdf", "svg"))
    assert all(p.stat().st_size > 1000 for p in written)
    assert (tmp_path / "heatmap_speed_drop_after_force_step_m_per_s.pdf").read_bytes().startswith(b"%PDF")


def test_a_ratio_needs_two_values_of_the_rows(capsys, tmp_path):
    body = ('[parameters]\nmodel_error = [0.0]\n"contact.friction" = [0.0]\ncontroller = ["task", "khatib"]\n'
            '[figures]\nx = "model_error"\ny = "contact.friction"\nrows = "controller"\nratio = ["task", "kahtib"]\n')
    assert main(["sweep", str(_sweep_file(tmp_path / "s.toml", body)), "--out", str(tmp_path / "o")]) == 2
    assert "[figures] ratio" in capsys.readouterr().err
