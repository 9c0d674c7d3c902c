"""pytest: results that behave like numbers and arrays, and the inputs researchers already have
(issue 49), and comparisons only on proven results (issue 46 item 7).

  - a numeric result (method='fast' or 'grid', a simulation, a scene's spectral radius in double)
    decides no comparison: UndecidedComparison, saying it is numeric and how to compare anyway;
  - stability(scene=..., max=NAME) is the library's (no forked command line), its value the
    supremum only where it is proven (else status 'undecided', value NaN), against the command's
    JSON (the same library functions, an independent writer);
  - f"{b:.3f}", round(b, 3), np.isclose(b, x), elementwise ==/!= on a ResultArray, slicing and
    iteration, to_numpy() (the values) / to_table(), RArray indexing, a 0-d omega, one status
    type (strings) in to_pandas() of a ResultArray and of a sweep, the stubs' @overloads (mypy);
  - pandas Series and DataFrame columns as arrays, unknown names in params refused, an array
    for the quantity maximised refused, delay= capped as the command line caps it, floats read
    as their shortest decimal (Fraction(x): the binary value), scipy.signal and python-control
    systems (read by their attributes) as H, plant and ss=, their dt checked against T.

Run: PYTHONPATH=build/python HAPSTAB_CLI=build/hapstab /usr/bin/python3 -m pytest tests/python
"""
import math
import os
import shutil
import subprocess
import sys
import textwrap
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import hapstab
from clitools import CLI, F, cli

EXAMPLES = Path(hapstab.examples_dir())
WALL = "K + B*(z-1)/(T*z)"
KB = {"K": 1000, "B": 5}
NARROW = "(z-1)/(z^2-2*0.9999*0.8*z+0.9999^2)"  # a resonance: b* certified (irrational), 6.6667...






# ---- issue 46 item 7: comparisons only on proven results ---------------------------------------

@pytest.mark.parametrize("method", ["fast", "grid"])
def test_a_numeric_result_decides_no_comparison(method):
    b = hapstab.bound(WALL, T="1/1000", delay=1, params=KB, method=method)
    assert b.status == "numeric" and 5 < b.value < 7  # the estimate is there, as a number
    for compare in (lambda: b < 100, lambda: b > 0, lambda: b <= 6, lambda: b >= 6, lambda: b == 6,
                    lambda: b != 6, lambda: np.float64(100) > b):
        with pytest.raises(hapstab.UndecidedComparison, match=r"numeric .*r\.value") as e:
            compare()
        assert "method='certified'" in str(e.value)
    assert (b.value < 100) is True  # the explicit numeric comparison
    # the certified result of the same wall decides (its enclosure is proven)
    c = hapstab.bound(WALL, T="1/1000", delay=1, params=KB)
    assert c.status in ("exact", "certified") and c < 100 and not c > 100
    # vectorised: a numeric ResultArray refuses elementwise, naming the first point
    K = np.array([0, 1000, 2000])
    fa = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5}, method=method)
    assert set(fa.status) == {"numeric"}
    with pytest.raises(hapstab.UndecidedComparison, match=r"3 of 3 points are not proven .*numeric"):
        fa < 100
    assert list(fa.value < 100) == [True] * 3


def test_a_simulation_and_a_scenes_radius_decide_no_comparison():
    s = hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml")
    assert s.status == "numeric" and s.verdict_status in ("exact", "certified")
    with pytest.raises(hapstab.UndecidedComparison, match="numeric"):
        s < 1  # the spectral radius in double: the verdict (bool(s)) is the proven answer
    assert bool(s) is True


def _scene_with_gain():
    text = (EXAMPLES / "000_two_dof_loop.toml").read_text().replace("[parameters]\n", "[parameters]\ng = \"1\"\n", 1)
    return text.replace("[environment]\n", "[environment]\ngain = \"g\"\n", 1)


def test_stability_of_a_scene_max_is_bound_not_forked(monkeypatch, tmp_path):
    # the library's max_parameter (stability/loop_max.hpp) through the binding: the command line
    # is never run (a forked `hapstab` would call _core.run)
    def no_fork(*a, **k):
        raise AssertionError("stability(scene=..., max=...) ran the command line")
    monkeypatch.setattr(hapstab._core, "run", no_fork)
    text = _scene_with_gain()
    r = hapstab.stability(scene=text, max="g", digits=12)
    monkeypatch.undo()
    path = tmp_path / "g.toml"
    path.write_text(text)
    code, j = cli("stability", "--scene", str(path), "--max", "g", "--digits", "12", codes=(0, 3))
    assert r.path == j["path"] == "closed_loop_matrix" and r.status == j["status"]
    assert r.supremum_proven == (code == 0) and r.stable_on == tuple(j["stable_on"])
    if code == 0:  # the supremum proven: the value is it, the midpoint of [stable_to, crossing.hi]
        assert r.outcome == "holds" and r.status == "certified" and (r.lo_exact, r.hi_exact) == tuple(j["sup_enclosure"])
        assert r.lo <= r.value <= r.hi and f"{r.value:.10f}".startswith(j["max"][:11])  # the digits the ends share
        assert r.crossing["crossing"] == tuple(j["enclosure"]) and r.crossing["at"] == j["crossing"]["at"]
        assert r.crossing["mode"] == j["crossing"]["mode"] and r.gap == j["gap"]
        assert r.unstable_at == j["unstable_at"] and r.stable_at == j["stable_at"]
        assert r > F(r.lo_exact) - 1 and r < F(r.hi_exact) + 1  # a proven value decides comparisons
    else:  # stable on [a, b] proven, (0, a) not: the supremum is undecided (issue 46 item 2), never a number
        assert r.status == "undecided" and math.isnan(r.value) and j["max"] is None and r.outcome == "undecided"
        assert r.crossing is None or r.crossing["crossing"] == tuple(j["enclosure"])
        with pytest.raises(hapstab.UndecidedComparison, match="undecided"):
            r < 100


def test_stability_of_a_scene_max_not_affine_is_not_called_certified():
    # the coupling (27)/kc: the loop is not affine in kc; the bisection on certified verdicts gives
    # a change of verdict, not a supremum: status 'undecided', value NaN, the bracket beside it
    scene = EXAMPLES / "multidof_case_ii_coupling.toml"
    c = hapstab.stability(scene=scene, max="kc", conservatism=True, digits=1, params={"g": 10})
    code, j = cli("stability", "--scene", str(scene), "--max", "kc", "--conservatism", "--digits", "1", "--set", "g=10",
                  codes=(0, 1, 3))
    assert c.path == j["path"] == "bisection_on_verdicts" and not c.supremum_proven and c.not_affine
    assert c.status == "undecided" and math.isnan(c.value) and c.outcome == "undecided"
    assert c.change_in == tuple(j["change_in"]) and c.stable_at == j["stable_at"] and c.unstable_at == j["unstable_at"]
    with pytest.raises(hapstab.UndecidedComparison, match="undecided"):
        c < 1e9
    with pytest.raises(hapstab.UndecidedComparison, match="undecided"):
        bool(c)  # an unproven supremum is never counted as a yes or a no
    assert c.verdicts_outcome == "holds" and c.verdicts > 0
    assert c.theorem5["bracket"] == tuple(j["theorem5"]["bracket"]) and c.theorem5["not_at"] == j["theorem5"]["not_at"]
    assert c.theorem5["concludes_at"] == j["theorem5"]["concludes_at"]
    # neither region is proven an interval (kc is no [environment] gain; the exact side is a change
    # of verdict): no ratio of suprema is claimed (issue 46 item 6), the brackets stand as boundaries
    assert c.conservatism is None and c.conservatism_note.startswith("no ratio of suprema") and not c.contradiction


ONE_DOF = textwrap.dedent("""\
    [scene]
    name = "one DOF: a mass-damper on a delayed wall"
    T = "1/1000"
    [parameters]
    K = "1000"
    B = "2"
    [[device]]
    name = "d"
    m = "1"
    b = "1"
    [environment]
    tf = "(K + B*(z-1)/(T*z))/z^2"
    """)


def test_stability_of_a_one_dof_scene_max_is_max_gain(tmp_path):
    r = hapstab.stability(scene=ONE_DOF, max="K", digits=20)
    path = tmp_path / "one.toml"
    path.write_text(ONE_DOF)
    code, j = cli("stability", "--scene", str(path), "--max", "K", "--digits", "20")
    # the same loop written as plant/H: stability::max_gain, the same number
    direct = hapstab.stability("1/(s^2 + s)", "(K + 2*(z-1)/(T*z))/z^2", T="1/1000", max="K", digits=20)
    assert code == 0 and r.path == "one_dof" and r.status == j["status"] == direct.status
    assert (r.lo, r.hi, r.value) == (direct.lo, direct.hi, direct.value) and r.crossing == j["crossing"]["at"]
    assert F(r.lo_exact) <= F(j["enclosure"][0]) and F(j["enclosure"][1]) <= F(r.hi_exact)


# ---- issue 49: results that behave like numbers -------------------------------------------------

def test_a_result_formats_rounds_and_is_a_numpy_number():
    b = hapstab.bound(NARROW, T="1/1000")                      # certified, 6.66672...
    e = hapstab.bound(WALL, T="1/1000", params=KB)           # exact 11/2
    assert b.status == "certified" and e.status == "exact"
    assert f"{e:.3f}" == "5.500" and f"{b:.3f}" == f"{float(b):.3f}" and f"{b:>10.2e}" == f"{float(b):>10.2e}"
    assert f"{e}" == repr(e) and "{:g}".format(e) == "5.5"
    assert round(e, 3) == Fraction(11, 2) and isinstance(round(e, 3), Fraction) and round(e) == 6  # half to even
    assert round(b, 3) == round(float(b), 3)
    assert np.isclose(b, 6.6667) and np.isclose(e, 5.5) and not np.isclose(e, 5.6) and f"{b:.3f}" == "6.667"
    assert np.asarray(e).dtype == np.float64 and np.array([e, b]).tolist() == [5.5, float(b)]
    # numpy's comparison ufuncs are the honest comparisons; others see the value
    assert (np.float64(6) > e) is np.True_ and np.less(e, 6) and list(np.less(np.array([5, 6]), e)) == [True, False]
    assert np.sqrt(e) == math.sqrt(5.5)


def test_result_array_equality_is_elementwise_and_decided():
    K = np.array([0, 1000, 2000])
    bs = hapstab.bound(WALL, T="1/1000", params={"K": K, "B": 5})  # exact: KT/2 + 5
    eq = bs == 5.5
    assert eq.dtype == bool and list(eq) == [False, True, False]  # not the plain bool False
    assert list(bs != 5.5) == [True, False, True] and list(bs == np.array([5, 5.5, 6])) == [True] * 3
    d = hapstab.bound("(z-1)/(z^2-2*a*0.8*z+a^2)", T="1/1000", params={"a": ["0.9999", "0.999"]}, digits=10)
    assert list(d.status) == ["certified"] * 2  # irrational points, enclosures about 1e-10 wide
    with pytest.raises(hapstab.UndecidedComparison, match="cannot decide =="):
        d == d.value  # the midpoint lies inside each enclosure: undecidable
    assert list(hapstab.bound("(z-1)/(z^2-2*a*0.8*z+a^2)", T="1/1000", params={"a": ["0.9999"]}) == d.value[:1]) == [False]  # 30 digits: decided
    assert list(d == 0) == [False, False]
    assert list(np.float64(5.5) == bs) == [False, True, False]  # the numpy side dispatches to the same


def test_result_array_slices_iterates_and_gives_values():
    K = np.linspace(0, 4000, 5)
    bs = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5})
    tail = bs[1:]
    assert isinstance(tail, hapstab.ResultArray) and tail.shape == (4,) and np.array_equal(tail.value, bs.value[1:])
    assert list(tail.params["K"]) == list(K[1:]) and tail[0].K == K[1] and tail[0].lo == bs[1].lo
    points = list(bs)
    assert len(points) == 5 and all(isinstance(p, hapstab.Bound) for p in points)
    assert [p.status for p in points] == list(bs.status) and points[2].value == bs[2].value
    assert bs[-1].K == K[-1] and bs[np.array([0, 2])].shape == (2,) and bs[bs.value > 6].shape[0] >= 1
    grid = hapstab.bound(WALL, T="1/1000", params={"K": K[None, :], "B": np.array([[0], [5]])})
    assert grid[1].shape == (5,) and isinstance(grid[1, 2], hapstab.Bound) and [row.shape for row in grid] == [(5,)] * 2
    # to_numpy(): the values (plt.plot(K, bs) and np.asarray(bs) take them); to_table(): the table
    v = bs.to_numpy()
    assert v.dtype == np.float64 and np.array_equal(v, bs.value) and v is not bs.value
    t = bs.to_table()
    assert t.dtype.names[:4] == ("K", "value", "lo", "hi") and list(t["status"]) == list(bs.status)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    line, = plt.plot(K, bs)
    assert np.array_equal(line.get_ydata(), bs.value)
    plt.close("all")


def test_one_status_type_everywhere():
    K = np.array([0, 1000, 40000.5])
    bs = hapstab.bound(WALL, T="1/1000", delay=1, params={"K": K, "B": 5})
    assert bs.status.dtype.kind == "U" and set(bs.status) <= set(hapstab.STATUS)
    assert [str(s) for s in bs.status] == [p.status for p in bs]  # the scalar results' statuses
    pd = pytest.importorskip("pandas")
    table = bs.to_pandas()
    t = hapstab.sweep({"command": "bound", "args": {"H": WALL, "T": 1e-3, "delay": 1},  # a float: its shortest decimal
                       "axes": {"K": {"values": ["0", "1000"]}, "B": {"values": ["5"]}}})
    sweep_table = t.to_pandas()
    assert all(isinstance(s, str) for s in table["status"]) and all(isinstance(s, str) for s in sweep_table["status"])
    assert list(table["status"][:2]) == list(sweep_table["status"])  # the same points, the same names
    sa = hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml", params={"k1": [50, 100000]})
    assert set(sa.verdict_status) <= {"exact", "certified", "undecided"} and sa.verdict_status.dtype.kind == "U"
    assert isinstance(sa[0].verdict_status, str) and pd.api.types.is_string_dtype(sa.to_pandas()["verdict_status"])


def test_r_array_indexes_and_a_0d_omega_is_a_number():
    w = np.linspace(1, 3000, 7)
    ra = hapstab.r("1/1000", w)
    p = ra[3]
    assert isinstance(p, hapstab.R) and p.im.value == ra.im[3] and p.re.value == Fraction(-1, 2000)
    assert p.im.status == "numeric" and p.im.lo <= p.im.value <= p.im.hi
    assert ra[2:].shape == (5,) and np.array_equal(ra[2:].im, ra.im[2:]) and len(list(ra)) == 7
    rc = hapstab.r("1/1000", w, method="certified")
    assert rc[1].im.status == "certified" and rc[1].im < 0  # Im r < 0 on (0, pi/T): proven, decided
    one = hapstab.r("1/1000", np.array(100.0))  # a 0-d array is one number
    assert isinstance(one, hapstab.R) and one.decimal == hapstab.r("1/1000", 100).decimal


# ---- issue 49: the inputs researchers have ------------------------------------------------------

def test_pandas_series_and_dataframe_columns_are_arrays():
    pd = pytest.importorskip("pandas")
    df = pd.DataFrame({"K": [0, 1000, 2000], "B": [5, 5, 2.5]})
    a = hapstab.bound(WALL, T="1/1000", params={"K": df["K"], "B": df["B"]})
    b = hapstab.bound(WALL, T="1/1000", params={"K": [0, 1000, 2000], "B": [5, 5, Fraction(5, 2)]})
    assert a.shape == (3,) and list(a.exact) == list(b.exact) == ["5", "11/2", "7/2"]
    s = hapstab.stability("1/(s^2 + s)", "K", T="1/1000", delay=2, params={"K": pd.Series([100, 1000])})
    assert s.shape == (2,) and s.failed == 0 and list(s.stable) == list(hapstab.stability(
        "1/(s^2 + s)", "K", T="1/1000", delay=2, params={"K": [100, 1000]}).stable)
    m = hapstab.bound(WALL, T="1/1000", params={"B": pd.Series([0.5, 1])}, damping="3/2", max="K")
    assert list(m.exact) == ["2000", "1000"]  # 2(b - B)/T, the Series' values as decimals
    w = hapstab.r("1/1000", pd.Series([1.0, 2.0]))
    assert len(w) == 2


@pytest.mark.parametrize("call,match", [
    (lambda: hapstab.bound(WALL, T="1/1000", params={"K": 1, "B": 2, "Kp": 3}),
     r"unknown name 'Kp': the expressions name B, K"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"K": [1, 2], "B": 2, "b": 3}), r"unknown name 'b'"),
    (lambda: hapstab.stability("1/(m*s^2)", WALL, T="1/1000", params={"m": 1, "K": 1, "B": 1, "Bx": 1}),
     r"unknown name 'Bx': the expressions name B, K, m"),
    (lambda: hapstab.passivity_level("1/(z-a)", T="1/100", params={"a": "1/2", "c": 1}), r"unknown name 'c'"),
    (lambda: hapstab.wedge("1/(z-a)", params={"a": "1/2", "aa": 1}), r"unknown name 'aa'"),
    (lambda: hapstab.tf(WALL, T="1/1000", params={"K": 1, "B": 1, "KK": 1}), r"unknown name 'KK'"),
    (lambda: hapstab.bound(WALL, T="1/1000", params={"K": [1, 2], "B": 1}, damping=2, max="K"),
     r"params\['K'\]: K is the quantity maximised .* no an array|params\['K'\]: K is the quantity maximised"),
    (lambda: hapstab.stability("1/(s^2+s)", "K", T="1/1000", max="K", params={"K": np.array([1, 2])}),
     r"params\['K'\]: K is the quantity maximised"),
    (lambda: hapstab.stability(scene=EXAMPLES / "000_two_dof_loop.toml", max="k1", params={"k1": [1, 2]}),
     "one point per call"),
    (lambda: hapstab.bound(WALL, T="1/1000", params=KB, delay=10**6 + 1), r"delay: 1000001 is outside \[0, 1000000\]"),
])
def test_inputs_refused_by_name(call, match):
    with pytest.raises(hapstab.InputError, match=match):
        call()


def test_delay_reaches_the_command_lines_limit():
    # the command line takes --delay up to 10^6 (numeric/limits.hpp criterion_delay), so does Python
    assert hapstab._core.CRITERION_DELAY == 10**6
    b = hapstab.bound(WALL, T="1/1000", params={"K": 10, "B": 1}, delay=5000)
    code, j = cli("bound", "--H", WALL, "--T", "1/1000", "--set", "K=10", "--set", "B=1", "--delay", "5000")
    assert b.status == j["status"] and (b.lo_exact, b.hi_exact) == tuple(j["enclosure"])


def test_floats_are_their_shortest_decimal_and_fraction_is_binary():
    # T=1e-3 is 1/1000 (repr), so b* of a wall is exact 11/2, not a 19-digit fraction
    b = hapstab.bound(WALL, T=1e-3, params={"K": 1000, "B": 5})
    assert b.status == "exact" and b.value == Fraction(11, 2)
    assert hapstab.bound(([0.1], [1]), T=1).value == Fraction(1, 20)
    assert hapstab.bound(([np.float32(0.1)], [1]), T=1).value == Fraction(1, 20)  # numpy's own shortest
    assert hapstab.bound(([np.array(0.1)], [1]), T=1).value == Fraction(1, 20)
    # Fraction(x) asks for the exact binary value
    assert hapstab.bound(([Fraction(0.1)], [1]), T=1).value == Fraction(0.1) / 2 != Fraction(1, 20)
    assert hapstab.bound(WALL, T=Fraction(1e-3), params=KB).value == Fraction(1e-3) * 500 + 5
    # float arrays in params: each the shortest decimal too (a non-integer grid)
    bs = hapstab.bound(WALL, T="1/1000", params={"K": np.array([0.1, 2.5, 1e3]), "B": 5})
    assert [F(x) for x in bs.exact] == [Fraction(1, 20000) + 5, Fraction(5, 4000) + 5, Fraction(11, 2)]
    # comparisons read a float the same way: exactly 11/2 == 5.5, and 1/20 == 0.05
    assert hapstab.bound(([0.1], [1]), T=1) == 0.05


class ControlTF:
    """A stand-in with python-control's TransferFunction attributes: num[0][0], den[0][0], dt (0: continuous)."""

    def __init__(self, num, den, dt):
        self.num, self.den, self.dt = [[np.array(num, dtype=float)]], [[np.array(den, dtype=float)]], dt


class ControlSS:
    """A stand-in with python-control's StateSpace attributes: A, B, C, D (numpy arrays), dt."""

    def __init__(self, A, B, C, D, dt):
        self.A, self.B, self.C, self.D = (np.array(M, dtype=float) for M in (A, B, C, D))
        self.dt = dt


def test_scipy_signal_systems_are_read_by_their_attributes():
    signal = pytest.importorskip("scipy.signal")
    ref = hapstab.bound("(6*z - 5)/z", T="1/1000", delay=1)
    for H in (signal.dlti([6, -5], [1, 0], dt=1e-3), signal.TransferFunction([6, -5], [1, 0], dt=0.001),
              signal.dlti([6, -5], [1, 0], dt=1e-3).to_zpk(), signal.dlti([6, -5], [1, 0], dt=1e-3).to_ss()):
        b = hapstab.bound(H, delay=1)  # T from dt, read as 1/1000
        assert (b.value, b.lo, b.hi, b.status) == (ref.value, ref.lo, ref.hi, ref.status), H
        assert hapstab.bound(H, T="1/1000", delay=1).value == ref.value
        with pytest.raises(hapstab.InputError, match=r"dt = 0\.001 .* does not match T = 1/100"):
            hapstab.bound(H, T="1/100", delay=1)
    with pytest.raises(hapstab.InputError, match="continuous-time system"):
        hapstab.bound(signal.lti([1], [1, 1]))
    # a continuous scipy system as the plant of stability, a discrete one as H
    s = hapstab.stability(signal.lti([1], [1, 1, 0]), signal.dlti([1000], [1], dt=1e-3), delay=2)
    s_ref = hapstab.stability("1/(s^2 + s)", "1000", T="1/1000", delay=2)
    assert s.stable == s_ref.stable and (s.lo, s.hi) == (s_ref.lo, s_ref.hi)
    op = hapstab.stability("1/(s^2 + s)", "1000", T="1/1000", delay=2, operator=signal.lti([2, 100], [1, 0]))
    assert op.stable == hapstab.stability("1/(s^2 + s)", "1000", T="1/1000", delay=2, operator="2 + 100/s").stable
    assert op.value == hapstab.stability("1/(s^2 + s)", "1000", T="1/1000", delay=2, operator="2 + 100/s").value
    with pytest.raises(hapstab.InputError, match="plant: a discrete-time system"):
        hapstab.stability(signal.dlti([1], [1, 1], dt=1e-3), "1000", T="1/1000")
    # ss=: scipy's StateSpace (A, B, C, D, dt)
    ss = signal.StateSpace([[0.5]], [[1]], [[1]], [[1]], dt=0.01)
    v = hapstab.passivity_level(ss=ss, kind="osp")
    assert v.value == hapstab.passivity_level(ss=([[0.5]], [[1]], [[1]], [[1]]), T="1/100").value == Fraction(1, 3)
    with pytest.raises(hapstab.InputError, match="does not match"):
        hapstab.passivity_level(ss=ss, T="1/1000")


def test_python_control_systems_are_read_by_their_attributes():
    ref = hapstab.bound("(6*z - 5)/z", T="1/1000", delay=1)
    b = hapstab.bound(ControlTF([6.0, -5.0], [1.0, 0.0], 0.001), delay=1)
    assert (b.value, b.status) == (ref.value, ref.status)
    with pytest.raises(hapstab.InputError, match="does not match"):
        hapstab.bound(ControlTF([6.0, -5.0], [1.0, 0.0], 0.001), T="1/1024")
    with pytest.raises(hapstab.InputError, match="pass T"):
        hapstab.bound(ControlTF([6.0, -5.0], [1.0, 0.0], True))
    plant = ControlTF([1.0], [1.0, 1.0, 0.0], 0)  # python-control: dt = 0 is continuous
    s = hapstab.stability(plant, ControlTF([1000.0], [1.0], 0.001), delay=2)
    assert s.stable == hapstab.stability("1/(s^2 + s)", "1000", T="1/1000", delay=2).stable
    v = hapstab.passivity_level(ss=ControlSS([[0.5]], [[1]], [[1]], [[1]], 0.01))
    assert v.value == Fraction(1, 3) and v.status == "exact"
    with pytest.raises(hapstab.InputError, match="continuous-time"):
        hapstab.passivity_level(ss=ControlSS([[0.5]], [[1]], [[1]], [[1]], 0))


# ---- the stubs: mypy sees scalar calls as scalar results --------------------------------------

TYPED = '''
from fractions import Fraction
import numpy as np
import hapstab

b = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", params={"K": 1000, "B": 5})
reveal_type(b)
omega: str | None = b.omega
passive: bool = b < 6
m = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", params={"B": "1/2"}, damping="3/2", max="K")
reveal_type(m)
bzero: hapstab.Bound = m.b_at_zero
bs = hapstab.bound("K + B*(z-1)/(T*z)", T="1/1000", params={"K": np.linspace(0, 1, 3), "B": 5})
reveal_type(bs)
s = hapstab.stability("1/(s^2 + s)", "K", T="1/1000", params={"K": 100})
reveal_type(s)
g = hapstab.stability("1/(s^2 + s)", "K", T="1/1000", max="K")
reveal_type(g)
r = hapstab.r("1/1000", 100)
reveal_type(r)
ra = hapstab.r("1/1000", np.linspace(1, 2, 3))
reveal_type(ra)
p = hapstab.passivity_level("1/(z-0.5)", T="1/100")
reveal_type(p)
level: float = float(p)
text: str = f"{b:.3f}"
'''


def test_mypy_sees_scalar_calls_as_scalar_results(tmp_path):
    pytest.importorskip("mypy")
    script = tmp_path / "typed.py"
    script.write_text(TYPED)
    package = Path(hapstab.__file__).parent.parent
    env = dict(os.environ, MYPYPATH=str(package))
    p = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", os.devnull,
                        "--python-version", "3.11", str(script)], capture_output=True, text=True, env=env, check=False)
    out = p.stdout
    revealed = [line.split('Revealed type is "')[1].rstrip('"') for line in out.splitlines() if "Revealed type" in line]
    assert revealed == ["hapstab.Bound", "hapstab.MaxPassiveGain", "hapstab.ResultArray", "hapstab.Stability",
                        "hapstab.MaxGain", "hapstab.R", "hapstab.RArray", "hapstab.PassivityLevel"], out
    assert "error" not in out.replace("Revealed", ""), out
    # the stubs themselves are consistent (overloads, operators): no error reported in a .pyi
    p = subprocess.run([sys.executable, "-m", "mypy", "--no-incremental", "--cache-dir", os.devnull, "--python-version",
                        "3.11", "-p", "hapstab"], capture_output=True, text=True, cwd=package, check=False)
    assert [line for line in p.stdout.splitlines() if ".pyi:" in line and "error" in line] == [], p.stdout
