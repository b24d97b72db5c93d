"""The first line every generated file carries: a do-not-edit note and the hash of its body.

The generator writes it (:func:`stamp`); the runtime reads it (:func:`is_hand_edited`) to warn
when generated code it compiles was edited by hand, without loading the generator.
"""

from __future__ import annotations

import hashlib
import json

STAMP = "/* hybrid generated file: do not edit; change codegen/ and run `python -m hybrid regenerate`. body-sha256: "
MANIFEST_STAMP = "hybrid generated file: do not edit; change codegen/ and regenerate"


def stamp(body: str) -> str:
    """Prefix ``body`` with the do-not-edit line carrying its hash."""
    return f"{STAMP}{hashlib.sha256(body.encode()).hexdigest()} */\n{body}"


def json_body_hash(data: dict) -> str:
    body = {k: v for k, v in data.items() if k not in ("do_not_edit", "body_sha256")}
    return hashlib.sha256(json.dumps(body, sort_keys=True).encode()).hexdigest()


def is_hand_edited(text: str) -> bool:
    """True when a generated file's body no longer matches the hash it carries."""
    if text.startswith("{"):
        try:
            data = json.loads(text)
            return data.get("body_sha256") != json_body_hash(data)
        except ValueError:
            return True
    first, _, body = text.partition("\n")
    if not first.startswith(STAMP):
        return True
    return first[len(STAMP):].split()[0] != hashlib.sha256(body.encode()).hexdigest()
