"""hapstab.sweep: the sweep layer from Python (issue 17/18/41): the table is the command's own
(equal to single hapstab.bound calls) as a structured numpy array, specs as dicts, TOML text or
paths, errors naming the key (and no temporary file)."""
import math
import os
from fractions import Fraction

import numpy as np
import pytest

import hapstab

SPEC = {"command": "bound",
        "args": {"H": "K + B*(z-1)/(T*z)", "T": "1/1000", "delay": 1},
        "axes": {"K": {"from": "0", "to": "3000", "points": 4}, "B": {"values": ["0", "5/2"]}}}


def test_a_dict_spec_gives_one_row_per_point_equal_to_single_bound_calls(tmp_path):
    t = hapstab.sweep(SPEC, out=tmp_path / "out", jobs=2)
    assert len(t) == 8 and t.failed == 0 and t.exit_code == 0
    assert t.path == str(tmp_path / "out") and (tmp_path / "out" / "points.csv").exists()
    assert isinstance(t, np.ndarray) and t.dtype.names is not None and t.shape == (8,)
    assert list(t.exact["index"]) == [str(i) for i in range(8)]
    assert t["bound"].dtype == np.float64
    assert t["status"].dtype == object
    assert t["index"].dtype == np.int64 and list(t["exit"]) == [0] * 8
    assert t["enclosure_rigorous"].dtype == bool and t["enclosure_rigorous"].all()
    assert t.manifest["points"]["ok"] == 8 and len(t.manifest["spec_sha256"]) == 64
    for i in (0, 3, 6):  # the last axis (B) varies fastest
        K, B = t.exact["K"][i], t.exact["B"][i]
        single = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", delay=1, params={"K": K, "B": B})
        assert t.exact["bound"][i] == single.decimal
        assert t.exact["enclosure_lo"][i] == single.lo_exact
        assert t["B"][i] == float(Fraction(B))


def test_toml_text_and_a_path_give_the_same_table(tmp_path):
    text = hapstab._sweep.spec_toml(SPEC)
    path = tmp_path / "spec.toml"
    path.write_text(text)
    a = hapstab.sweep(text)
    b = hapstab.sweep(path)
    assert a.path is None
    for name in a.exact:
        assert list(a.exact[name]) == list(b.exact[name])


def test_a_failing_point_is_a_row_not_an_exception():
    spec = {"command": "bound", "args": {"H": "1/(z-c)", "T": "1/1000"}, "axes": {"c": {"values": ["1/2", "2"]}}}
    t = hapstab.sweep(spec)
    assert t.exit_code == 1 and t.failed == 1
    assert t.exact["error"][0] == "" and "unstable" in t.exact["error"][1]
    assert math.isnan(t["bound"][1])


@pytest.mark.parametrize("spec, match", [
    ({"command": "bound", "args": {"H": "K", "T": "1/1000"}, "axes": {"K": {"values": ["1"]}}, "extra": 1}, "extra"),
    ({"command": "bound", "args": {"H": "K", "T": float("nan")}, "axes": {"K": {"values": ["1"]}}},
     "args.T: nan is not a finite number"),  # a finite float is its shortest decimal (0.001: 1/1000)
    ({"command": "bound", "args": {"H": "K", "T": "1/1000"}, "axes": {"K": {"from": "0"}}}, "K"),
    ({"command": "no-such", "args": {}, "axes": {"K": {"values": ["1"]}}}, "no-such"),
])
def test_a_bad_spec_raises_input_error_naming_it(spec, match):
    with pytest.raises(hapstab.InputError, match=match):
        hapstab.sweep(spec)


def test_to_pandas_is_a_dataframe_when_pandas_is_there():
    t = hapstab.sweep(SPEC)
    try:
        import pandas  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="python3-pandas"):
            t.to_pandas()
        return
    df = t.to_pandas()
    assert list(df.columns) == list(t.dtype.names) and len(df) == len(t)
    assert df["bound"].dtype == np.float64 and list(df["bound"]) == list(t["bound"])
