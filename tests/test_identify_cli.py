"""``python -m hybrid identify``: a log written here (the UR5 shipped, its links 20 % heavier, along a
multi-sine) read as CSV and Parquet, the report printed, the identified robot written; bad logs and
options refused in one line."""

from __future__ import annotations

import json

import numpy as np
import pandas as pd
import pytest
from test_identify_dynamics import multisine, torques

import hybrid
from hybrid.cli.main import main
from hybrid.experiments.serialisation import robot_from_dict


@pytest.fixture(scope="module")
def table():
    robot = hybrid.ur5()
    heavier = robot.with_model_error(inertial=0.2)
    t, q, qd, qdd = multisine(robot, 1000.0, 20.0, seed=1)
    tau = torques(heavier, q, qd, qdd)
    columns = {"t": t, **{f"q[{j}]": q[:, i] for i, j in enumerate(robot.joint_names)},
               **{f"tau[{j}]": tau[:, i] for i, j in enumerate(robot.joint_names)}}
    return pd.DataFrame(columns), heavier


def _run(capsys, *args):
    code = main(["identify", *map(str, args), "--urdf", str(hybrid.UR5_URDF), "--tip", "tool0"])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("kind", ["csv", "parquet"])
def test_a_log_is_identified_reported_and_its_robot_written(capsys, tmp_path, table, kind):
    frame, heavier = table
    log = tmp_path / f"log.{kind}"
    if kind == "csv":
        frame.to_csv(log, index=False)
    else:
        pytest.importorskip("pyarrow")
        frame.to_parquet(log)
    out = tmp_path / "robot.json"
    code, text, err = _run(capsys, log, "--out", out)
    assert code == 0, err
    assert text.startswith("identified the dynamics of ur5 from log")
    assert "20,000 samples at 1000 Hz, filtered at 20 Hz" in text and "condition number" in text
    base = hybrid.base_parameters(hybrid.ur5())
    want = dict(zip((base.names[i] for i in base.independent), base.of(hybrid.linear_parameters(heavier))))
    rows = {line.split()[0]: line.split() for line in text.splitlines() if line.split()[:1] and line.split()[0] in want}
    assert set(rows) == set(want)
    for name, cells in rows.items():  # name, estimate, std, consistent, nominal, unit
        assert abs(float(cells[1]) - want[name]) < 1e-4 * max(abs(v) for v in want.values()), name
    assert "residual RMS per joint" in text and "poorly excited" in text
    robot = robot_from_dict(json.loads(out.read_text()))
    np.testing.assert_allclose(base.of(hybrid.linear_parameters(robot)), list(want.values()), rtol=0,
                               atol=1e-4 * max(abs(v) for v in want.values()))
    assert robot.chain == heavier.chain
    code, _, err = _run(capsys, log, "--out", out)  # never over a file unasked
    assert code == 2 and err == f"error: --out {out} exists; choose another name or pass --force to overwrite it\n"
    code, text, _ = _run(capsys, log, "--out", out, "--force", "--cutoff", "30")
    assert code == 0 and "filtered at 30 Hz" in text
    urdf = tmp_path / "robot.urdf"  # the same robot as a URDF, read back by the library
    assert _run(capsys, log, "--out", urdf)[0] == 0
    again = hybrid.Robot.from_urdf(urdf, tip="tip")
    assert again.chain == robot.chain and again.damping == pytest.approx(robot.damping, abs=1e-12)
    for field in ("coulomb", "offset", "coulomb_speed"):  # the friction the URDF carries, read back
        assert getattr(again, field) == pytest.approx(getattr(robot, field), abs=1e-12), field
    assert "columns not read" not in text
    np.testing.assert_allclose(base.of(hybrid.linear_parameters(again)), list(want.values()), rtol=0,
                               atol=1e-4 * max(abs(v) for v in want.values()))


def test_bad_logs_and_options_are_refused_in_one_line(capsys, tmp_path, table):
    frame, _ = table

    def refused(frame_or_path, *args, match):
        if isinstance(frame_or_path, pd.DataFrame):
            path = tmp_path / "bad.csv"
            frame_or_path.to_csv(path, index=False)
        else:
            path = frame_or_path
        code, out, err = _run(capsys, path, *args)
        assert code == 2 and err.startswith("error: ") and err.count("\n") == 1, err
        assert match in err, err

    refused(frame.drop(columns=["tau[elbow_joint]"]), match="has no column tau[elbow_joint]; give the columns t, q[")
    shuffled = frame.copy()
    shuffled.loc[100, "t"] = shuffled.loc[50, "t"]
    refused(shuffled, match="t[100] = 0.05 is before t[99] = 0.099; give strictly increasing times")
    words = frame.astype({"q[elbow_joint]": object})
    words.loc[7, "q[elbow_joint]"] = "about 1"
    refused(words, match="column q[elbow_joint] has 'about 1' in data row 7; give numbers")
    holes = frame.copy()
    holes.loc[412, "tau[wrist_1_joint]"] = np.nan
    refused(holes, match="tau[412, 3] = nan (sample 412, joint wrist_1_joint); give finite numbers")
    refused(frame.assign(**{"qd[shoulder_pan_joint]": 0.0}),
            match="has qd[JOINT] columns but no qd[shoulder_lift_joint]; give qd for every joint, or for none")
    refused(frame.iloc[:300], match="the log has 300 samples; filtering at 20 Hz drops 292 at each end")
    refused(frame, "--cutoff", "700", match="cutoff_hz = 700 Hz is not below the log's Nyquist frequency 500 Hz")
    (tmp_path / "log.txt").write_text("t\n0\n")
    refused(tmp_path / "log.txt", match="is neither .csv nor .parquet")
    refused(tmp_path / "missing.csv", match="cannot read the log")
    refused(frame, "--out", tmp_path / "robot.txt", match="is neither .urdf nor .json; give FILE.urdf or FILE.json")
    code, _, err = _run(capsys, tmp_path / "bad.csv", "--cutoff", "-3")
    assert code == 2 and "--cutoff: '-3': give the cutoff in Hz, a positive number" in err


def test_a_parquet_log_without_pyarrow_says_to_install_it(capsys, tmp_path, table, monkeypatch):
    pytest.importorskip("pyarrow")
    log = tmp_path / "log.parquet"
    table[0].to_parquet(log)
    monkeypatch.setitem(__import__("sys").modules, "pyarrow", None)  # an import of it fails
    code, _, err = _run(capsys, log)
    assert code == 2 and err == "error: reading a Parquet log needs pyarrow: pip install pyarrow (or give a CSV log)\n"


def test_columns_not_read_are_named(capsys, tmp_path, table):
    """A column the identification does not read (a misspelt joint's, a note's) is said, not passed over."""
    frame, _ = table
    log = tmp_path / "log.csv"
    frame.assign(**{"q[wrist_3]": 0.0, "note": "x"}).to_csv(log, index=False)
    code, text, err = _run(capsys, log)
    assert code == 0, err
    assert "columns not read" in text and "q[wrist_3]" in text and "note" in text
