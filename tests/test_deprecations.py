"""Old names keep working for one release, each with a DeprecationWarning that names the new one."""

from __future__ import annotations

import importlib
import sys

import pytest

from hybrid import oracle


def test_the_old_module_name_of_the_numpy_oracle_is_the_oracle_and_warns():
    sys.modules.pop("hybrid.reference", None)  # imported before: import it afresh
    with pytest.warns(DeprecationWarning, match="hybrid.oracle"):
        old = importlib.import_module("hybrid.reference")
    assert old is oracle
    assert old.simulate is oracle.simulate
