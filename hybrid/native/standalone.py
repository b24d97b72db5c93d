"""``python -m hybrid generate``: standalone C for a user's arm, written into a folder of theirs."""

from __future__ import annotations

from pathlib import Path

from hybrid.errors import HybridError
from hybrid.models.robot import Robot
from hybrid.models.urdf import read_chain
from hybrid.native import build, units
from hybrid.validate import c_identifier, check_c_name


def generate(urdf, tip: str, out, name: str | None = None, locked: dict | None = None,
             force: bool = False, gravity=(0.0, 0.0, -9.81)) -> list[Path]:
    """Write standalone C99 for the arm of ``urdf`` (``<prefix>.c``, ``.h``, ``.json``) into ``out``.

    ``name`` (ASCII letters, digits, ``_``, a letter first) prefixes the files and symbols; without it
    a prefix is derived from the URDF's robot name. Refuses to overwrite files that differ from
    what it would write unless ``force``.
    """
    if name is not None:  # the user's own name is used as given or refused, never silently changed
        check_c_name("--name", name)
    parsed = read_chain(urdf, tip, locked)
    prefix = c_identifier(parsed.name if name is None else name)
    robot = Robot(parsed.name, parsed.chain, parsed.links, parsed.damping, gravity, parsed.limits)
    unit = units.generator("robot_unit").build_robot_unit(
        parsed.chain, prefix, units.robot_info(parsed.chain, parsed.name) | {"tip": tip},
        defaults=robot.as_array())
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise HybridError(f"--out {out} is a file; give a folder")
    clash = [n for n, text in unit.files.items() if (out / n).is_file() and (out / n).read_text() != text]
    if clash and not force:
        raise HybridError(f"{', '.join(clash)} already exist in {out} with other content; "
                          "pass --force to overwrite them, or choose another --out or --name")
    try:
        build.write_unit_files(out, unit.files)
    except OSError as exc:
        raise HybridError(f"cannot write into {out} ({exc.strerror}); choose a writable --out") from None
    return [out / n for n in unit.files]
