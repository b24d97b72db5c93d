"""Files a user names: only a regular file of UTF-8 text and bounded size is read; anything else,
a FIFO included, is one HybridError naming the file, never a hang or a foreign exception."""

from __future__ import annotations

import os
import re
import threading

import pytest

import hybrid
from hybrid import files
from hybrid.cli.sweep import read_config
from hybrid.control.config import read_controller_config
from hybrid.errors import URDFError
from hybrid.models.urdf import _read_tree


def within(seconds, call):
    """``call()``'s exception (or None), failing the test if it has not returned after ``seconds``:
    a reader that blocks on a FIFO is a failure, not a hung test run."""
    outcome = {}

    def run():
        try:
            call()
            outcome["error"] = None
        except BaseException as exc:  # handed to the test
            outcome["error"] = exc

    worker = threading.Thread(target=run, daemon=True)
    worker.start()
    worker.join(seconds)
    if worker.is_alive():
        pytest.fail(f"the read has not returned after {seconds} s")
    return outcome["error"]


READERS = {
    "controller": lambda path: read_controller_config(path, None),  # refused before the robot is used
    "sweep": read_config,
    "urdf": _read_tree,
}


def bad_paths(tmp_path):
    fifo = tmp_path / "fifo.toml"
    os.mkfifo(fifo)
    folder = tmp_path / "folder.toml"
    folder.mkdir()
    latin = tmp_path / "latin.toml"
    latin_bytes = '# ok\nname = "café"\n'.encode("latin-1")  # not UTF-8
    latin.write_bytes(latin_bytes)
    offset = latin_bytes.index("é".encode("latin-1"))
    return {
        "fifo": (fifo, "FIFO"),
        "int": (3, "give a path"),
        "nul": (str(tmp_path / "a\0b.toml"), "not a file name"),
        "folder": (folder, "folder"),
        "not utf-8": (latin, rf"not UTF-8 text \(byte {offset}, line 2\)"),
        "missing": (tmp_path / "missing.toml", "No such file"),
    }


@pytest.mark.parametrize("reader", READERS)
@pytest.mark.parametrize("case", ["fifo", "int", "nul", "folder", "not utf-8", "missing"])
def test_a_bad_path_is_one_hybrid_error(tmp_path, reader, case):
    path, message = bad_paths(tmp_path)[case]
    error = within(5, lambda: READERS[reader](path))
    assert isinstance(error, hybrid.HybridError), repr(error)
    if reader == "urdf":
        assert isinstance(error, URDFError)
    assert error.args[0].count("\n") == 0
    assert re.search(message, str(error)), str(error)


def test_the_byte_offset_is_the_first_undecodable_byte(tmp_path):
    data = "ü".encode() * 5 + b"\xff" + b"x"
    path = tmp_path / "f.toml"
    path.write_bytes(data)
    first = data.index(b"\xff")  # the UTF-8 of "ü" is two bytes: the offset counts bytes, not characters
    with pytest.raises(hybrid.HybridError, match=f"byte {first},"):
        files.read_user_text(path, "file")


def test_a_file_over_the_limit_is_refused_before_reading(tmp_path):
    path = tmp_path / "big.toml"
    path.write_bytes(b"#" * 101)
    with pytest.raises(hybrid.HybridError, match="101 bytes, more than the 100 read"):
        files.read_user_text(path, "controller file", limit_bytes=100)
    assert files.read_user_text(path, "controller file", limit_bytes=101) == "#" * 101


def test_a_large_urdf_is_refused(tmp_path, monkeypatch):
    import hybrid.models.urdf as urdf
    path = tmp_path / "arm.urdf"
    path.write_text("<robot name='a'/>" + " " * 100)
    monkeypatch.setattr(urdf, "MAX_URDF_BYTES", 50)
    with pytest.raises(URDFError, match="more than the 50 read"):
        urdf._read_tree(path)


def test_a_saved_result_that_is_a_fifo_is_refused(tmp_path):
    fifo = tmp_path / "r.npz"
    os.mkfifo(fifo)
    error = within(5, lambda: hybrid.SimulationResult.load(fifo))
    assert isinstance(error, hybrid.HybridError) and "FIFO" in str(error), repr(error)
